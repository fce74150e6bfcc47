// Task 2 — ray–triangle and ray–sphere intersection
//
// Goal: find where a ray meets a triangle or a sphere, exactly enough that
// meshes never leak and small far spheres never vanish; then build the
// surface point (position and normals) the shading code needs.
// Handout: tasks/02-intersection/README.md
//
// Functions to write (declared in framework/tasks/intersection.h):
//   T2.1 intersectTriangle      watertight ray–triangle test
//   T2.2 intersectSphere        numerically careful ray–sphere test
//   T2.3 triangleSurfacePoint   hit point and normals on a triangle
//   T2.4 sphereSurfacePoint     hit point and normal on a sphere
//
// Check your work:
//   ./build/pathlab debug --task 2 --view normals -o normals.png   (also: depth, primitive-id)
//   ctest --test-dir build -R 02-intersection --output-on-failure
#include "tasks/intersection.h"

#include <cmath>
#include <utility>

#include "util/todo.h"

namespace pathlab {

// T2.1 — Ray–triangle intersection.
//
// Return the hit with t inside `range` (range.contains(t): min < t < max) and
// the barycentric weights (b1, b2) of p1 and p2, so the hit point is
//   p = (1 - b1 - b2) p0 + b1 p1 + b2 p2   with b0, b1, b2 >= 0.
//
// Recipe (watertight, Woop–Benthin–Wald 2013):
//   1. Translate the vertices by -ray.origin.
//   2. Permute x, y, z so that |direction| is largest along z.
//   3. Shear: x += Sx z, y += Sy z with Sx = -dx/dz, Sy = -dy/dz. The ray
//      is now the +z axis and the test is 2D.
//   4. Edge functions  e0 = b.x c.y - b.y c.x,  e1 = c.x a.y - c.y a.x,
//      e2 = a.x b.y - a.y b.x  (a, b, c: the sheared p0, p1, p2).
//      The ray misses if they have mixed signs; det = e0 + e1 + e2 = 0 means
//      the triangle is seen edge-on: miss.
//   5. Scale z by Sz = 1/dz; tScaled = e0 a.z + e1 b.z + e2 c.z and
//      t = tScaled / det; b1 = e1 / det, b2 = e2 / det.
//
// PITFALL: an absolute epsilon (|det| < 1e-6) throws away every hit on small
// triangles: a scanned model's triangles are about 1e-3 across.
// PITFALL: if an edge function is exactly 0 in float, recompute the three in
// double, so the two triangles sharing that edge agree on which side it is.
// PITFALL: a triangle with zero area has no normal; never report a hit on it.
std::optional<TriangleHit> intersectTriangle(const Ray& ray, Interval range, const Point3& p0,
                                             const Point3& p1, const Point3& p2) {
  // TODO(T2.1): the watertight test above.
  PATHLAB_TODO("T2.1");
  (void)ray, (void)range, (void)p0, (void)p1, (void)p2;
  return std::nullopt;
}

// T2.2 — Ray–sphere intersection.
//
// |o + t d - c|^2 = r^2 is the quadratic  a t^2 + 2 b' t + c' = 0  with
//   f = o - center,  a = d.d,  b' = f.d,  c' = f.f - r^2.
// Return the smallest root inside `range`: that is the far root when the
// origin is inside the sphere.
//
// Two precision fixes (Ray Tracing Gems, chapter 7):
//   - discriminant  D = a (r^2 - |f - (b'/a) d|^2)  instead of b'^2 - a c':
//     for a small, far sphere b'^2 and a c' are huge and nearly equal, and
//     their difference is mostly rounding error.
//   - q = -(b' + sign(b') sqrt(D)), roots t0 = c'/q and t1 = q/a: neither
//     subtracts two nearly equal numbers.
std::optional<float> intersectSphere(const Ray& ray, Interval range, const Point3& center, float radius) {
  // TODO(T2.2): solve the quadratic as above.
  PATHLAB_TODO("T2.2");
  (void)ray, (void)range, (void)center, (void)radius;
  return std::nullopt;
}

// T2.3 — The surface point of a triangle hit.
//
//   point          = b0 p0 + b1 p1 + b2 p2   (b0 = 1 - b1 - b2); more precise
//                    than origin + t direction far from the origin.
//   geometricNormal = normalize((p1 - p0) x (p2 - p0)): counter-clockwise
//                    vertices face the viewer.
//   shadingNormal   = normalize(b0 n0 + b1 n1 + b2 n2) when `normals` is not
//                    null, else the geometric normal.
//
// PITFALL: vertex normals say which side is outside. If the geometric normal
// points the other way, flip the geometric normal (not the shading normal).
// If the interpolated normal is zero, keep the geometric normal.
SurfacePoint triangleSurfacePoint(const TriangleHit& hit, const Point3& p0, const Point3& p1,
                                  const Point3& p2, const Vec3* normals) {
  // TODO(T2.3): fill in the point and both normals.
  PATHLAB_TODO("T2.3");
  (void)hit, (void)p0, (void)p1, (void)p2, (void)normals;
  return SurfacePoint{};
}

// T2.4 — The surface point of a sphere hit.
//
//   outward = normalize(ray.at(t) - center)
//   point   = center + radius * outward    (re-projected onto the sphere, so
//             rounding in t cannot leave it inside or outside)
//   both normals = outward.
SurfacePoint sphereSurfacePoint(const Ray& ray, float t, const Point3& center, float radius) {
  // TODO(T2.4): fill in the point and the normals.
  PATHLAB_TODO("T2.4");
  (void)ray, (void)t, (void)center, (void)radius;
  return SurfacePoint{};
}

}  // namespace pathlab
