// The pinhole camera as scene data. Task 1 turns it into rays.
#pragma once

#include "pathlab/math.h"

namespace pathlab {

struct Camera {
  Point3 position{0.0f, 0.0f, 0.0f};
  Point3 lookAt{0.0f, 0.0f, -1.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};  // need not be perpendicular to the view direction
  float vfovDegrees = 40.0f;  // full vertical field of view, in (0, 180)
};

}  // namespace pathlab
