// The camera as scene data: a pinhole (task 1), or a thin lens (task 10)
// when its aperture is open.
#pragma once

#include "util/math.h"

namespace pathlab {

struct Camera {
  Point3 position{0.0f, 0.0f, 0.0f};
  Point3 lookAt{0.0f, 0.0f, -1.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};  // any length; need not be perpendicular to the view direction
  float vfovDegrees = 40.0f;  // full vertical field of view, in (0, 180)
  // Task 10's thin lens: a disk of this radius (world units) centred on
  // `position`, perpendicular to the view; 0 is a pinhole, and every render
  // then takes task 1's rays alone.
  float apertureRadius = 0.0f;
  // The plane in focus: perpendicular to the view, this far from the lens
  // along the view direction (not along each ray). Scenes default it to the
  // distance to lookAt.
  float focalDistance = 1.0f;
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
