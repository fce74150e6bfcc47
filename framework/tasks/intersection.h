// Task 2 — ray–triangle and ray–sphere intersection. Implemented in
// tasks/02-intersection/intersection.cpp (the student's file; where the task
// is not the student's, the programs link the course's reference in its
// place).
#pragma once

#include <optional>

#include "core/hit.h"
#include "util/math.h"
#include "util/ray.h"

namespace pathlab {

// TriangleHit (the ray parameter and the barycentrics b1, b2 of a triangle
// hit) is core data: core/hit.h.

// T2.1: the hit of `ray` with triangle (p0, p1, p2) for t in `range`, or nothing.
// Watertight: a ray through an edge or vertex shared by two triangles hits at
// least one of them. Degenerate (zero-area) triangles are never hit.
std::optional<TriangleHit> intersectTriangle(const Ray& ray, Interval range, const Point3& p0,
                                             const Point3& p1, const Point3& p2);

// T2.2: the smallest t in `range` where `ray` meets the sphere, or nothing.
std::optional<float> intersectSphere(const Ray& ray, Interval range, const Point3& center,
                                     float radius);

// Position and normals of a hit, in world space.
struct SurfacePoint {
  Point3 point{0.0f};
  Vec3 geometricNormal{0.0f, 0.0f, 1.0f};  // unit
  Vec3 shadingNormal{0.0f, 0.0f, 1.0f};    // unit, same hemisphere as geometricNormal
};

// T2.3: the surface point of a triangle hit. `normals` is null or points to
// the three vertex normals n0, n1, n2.
SurfacePoint triangleSurfacePoint(const TriangleHit& hit, const Point3& p0, const Point3& p1,
                                  const Point3& p2, const Vec3* normals);

// T2.4: the surface point where `ray` meets the sphere at parameter t.
SurfacePoint sphereSurfacePoint(const Ray& ray, float t, const Point3& center, float radius);

}  // namespace pathlab
