// The record of a ray hitting a surface, as the renderer and debuggers use it.
#pragma once

#include <cstdint>

#include "util/math.h"

namespace pathlab {

// Where a ray meets a triangle (task 2): the ray parameter and the
// barycentric weights of p1 and p2 (p0's weight is 1 - b1 - b2).
struct TriangleHit {
  float t = kInfinity;
  float b1 = 0.0f;
  float b2 = 0.0f;
};

// Where a ray meets one primitive: its parameter, the barycentrics of p1 and
// p2 for triangles (0 for spheres), and the primitive's index in the scene.
struct PrimitiveHit {
  float t = kInfinity;
  float b1 = 0.0f;
  float b2 = 0.0f;
  uint32_t primitive = 0;
};

struct Hit {
  float t = kInfinity;       // ray parameter of the hit
  Point3 point{0.0f};        // world-space hit position
  Vec3 geometricNormal{0.0f, 0.0f, 1.0f};  // unit, from the winding (triangles) or outward (spheres)
  Vec3 shadingNormal{0.0f, 0.0f, 1.0f};    // unit, interpolated; same hemisphere as geometricNormal
  uint32_t primitive = 0;    // index into Scene::primitives
  uint32_t material = 0;     // index into Scene::materials
};

}  // namespace pathlab
