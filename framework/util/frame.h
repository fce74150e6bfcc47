// An orthonormal frame around a normal: the local shading space of BSDFs,
// where the normal is +z, so cos(theta) = w.z.
#pragma once

#include <cmath>

#include "util/math.h"

namespace pathlab {

struct Frame {
  Vec3 s{1, 0, 0}, t{0, 1, 0}, n{0, 0, 1};

  // Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017): no
  // branch on a threshold, continuous except at n.z = 0's sign change.
  static Frame fromNormal(const Vec3& normal) {
    Frame f;
    f.n = normal;
    const float sign = std::copysign(1.0f, normal.z);
    const float a = -1.0f / (sign + normal.z);
    const float b = normal.x * normal.y * a;
    f.s = Vec3(1.0f + sign * normal.x * normal.x * a, sign * b, -sign * normal.x);
    f.t = Vec3(b, sign + normal.y * normal.y * a, -normal.y);
    return f;
  }

  Vec3 toLocal(const Vec3& v) const { return {glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)}; }
  Vec3 toWorld(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace pathlab
