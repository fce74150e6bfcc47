// The pinhole camera as scene data. Task 1 turns it into rays.
#pragma once

#include "util/math.h"

namespace pathlab {

struct Camera {
  Point3 position{0.0f, 0.0f, 0.0f};
  Point3 lookAt{0.0f, 0.0f, -1.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};  // any length; need not be perpendicular to the view direction
  float vfovDegrees = 40.0f;  // full vertical field of view, in (0, 180)
};

// Moving the camera with the mouse (the GUI). All keep the up vector and
// the field of view.
// Rotates the eye around lookAt: yaw about `up`, pitch about the camera's
// right axis (stopping 5 degrees short of looking straight along up).
Camera orbitCamera(const Camera& camera, float yawDegrees, float pitchDegrees);
// Slides eye and lookAt together so the scene at lookAt's distance moves by
// `pixels` (x right, y down) in an image `imageHeight` pixels tall.
Camera panCamera(const Camera& camera, Vec2 pixels, int imageHeight);
// Moves the eye towards lookAt (factor < 1) or away from it (factor > 1).
Camera dollyCamera(const Camera& camera, float factor);

}  // namespace pathlab
