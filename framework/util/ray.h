// A ray: origin + t * direction. Directions are unit length unless a function says otherwise.
#pragma once

#include "util/math.h"

namespace pathlab {

struct Ray {
  Point3 origin{0.0f};
  Vec3 direction{0.0f, 0.0f, -1.0f};

  Point3 at(float t) const { return origin + t * direction; }
};

}  // namespace pathlab
