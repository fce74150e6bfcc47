// Task @N@ — @TITLE@ (reference solution).
#include "tasks/@STEM@.h"

#include <cmath>

namespace pathlab::@STEM@ {

Point2 sampleTriangle(Vec2 u) {
  // Slices x = 1 - s of length s: s has density 2s, so s = sqrt(u.x).
  const float s = std::sqrt(u.x);
  return Point2(1.0f - s, s * u.y);
}

}  // namespace pathlab::@STEM@
