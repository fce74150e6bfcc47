// Directions drawn uniformly, for the framework's own samplers (sphere
// lights, a constant-colour sky, the uniform-hemisphere strategy). The
// students' samplers (tasks 5 and 7) are their own code.
#pragma once

#include <algorithm>
#include <cmath>

#include "util/math.h"

namespace pathlab {

// Archimedes: z uniform in [-1, 1] and phi uniform give a uniform point on
// the unit sphere. Density 1 / (4 pi).
inline Vec3 uniformSphereDirection(Vec2 u) {
  const float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// The same over the hemisphere z >= 0 (z uniform in [0, 1]). Density 1 / (2 pi).
inline Vec3 uniformHemisphereDirection(Vec2 u) {
  const float z = u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace pathlab
