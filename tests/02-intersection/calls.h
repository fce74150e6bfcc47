// Task 2's remote calls: the judge's view of the student's intersection.cpp.
#pragma once

#include <cstdint>
#include <tuple>
#include <vector>

#include "wire/call.h"
#include "core/scene.h"
#include "tasks/intersection.h"

// This task's own value types on the wire (grader/wire/wire.h).
namespace pathlab::wire {
PATHLAB_WIRE_FIELDS(SurfacePoint, s.point, s.geometricNormal, s.shadingNormal);
}  // namespace pathlab::wire

namespace pathlab::calls {
PATHLAB_REMOTE_CALL(IntersectTriangle, 1, shape::Fixed, std::optional<TriangleHit>(Ray, Interval, Point3, Point3, Point3));
PATHLAB_REMOTE_CALL(IntersectSphere, 2, shape::Fixed, std::optional<float>(Ray, Interval, Point3, float));
// normals: empty, or the three vertex normals.
PATHLAB_REMOTE_CALL(TriangleSurfacePoint, 3, shape::Fixed, SurfacePoint(TriangleHit, Point3, Point3, Point3, std::vector<Vec3>));
PATHLAB_REMOTE_CALL(SphereSurfacePoint, 4, shape::Fixed, SurfacePoint(Ray, float, Point3, float));
// For each ray, every triangle of a mesh it hits and the t of that hit
// (intersectTriangle on each triangle, in the candidate: a closed mesh has
// thousands). Per ray, at most one hit per triangle. Each hit names its
// triangle so that the judge can check it against its own crossing of that
// triangle: a t alone could be any number.
using MeshHit = std::tuple<uint32_t /*triangle*/, float /*t*/>;
using HitsPerRay = shape::OnePer<2, shape::AtMost<shape::LengthOf<1>>>;
PATHLAB_REMOTE_CALL(MeshHits, 5, HitsPerRay,
                    std::vector<std::vector<MeshHit>>(std::vector<Point3>, std::vector<glm::uvec3>, std::vector<Ray>));
}  // namespace pathlab::calls

namespace pathlab::candidate {
inline std::optional<TriangleHit> intersectTriangle(const Ray& ray, Interval range, const Point3& p0, const Point3& p1,
                                                    const Point3& p2) {
  return remote::call<calls::IntersectTriangle>(ray, range, p0, p1, p2);
}
// Many triangle tests in one message.
inline std::vector<std::optional<TriangleHit>> intersectTriangles(const std::vector<calls::IntersectTriangle::Args>& tests) {
  return remote::callMany<calls::IntersectTriangle>(tests);
}
// Every triangle of `mesh` that each ray hits, with its t (range: all t > 0).
inline std::vector<std::vector<calls::MeshHit>> meshHits(const TriangleMesh& mesh, const std::vector<Ray>& rays) {
  return remote::call<calls::MeshHits>(mesh.positions, mesh.triangles, rays);
}
inline std::optional<float> intersectSphere(const Ray& ray, Interval range, const Point3& center, float radius) {
  return remote::call<calls::IntersectSphere>(ray, range, center, radius);
}
inline SurfacePoint triangleSurfacePoint(const TriangleHit& hit, const Point3& p0, const Point3& p1, const Point3& p2,
                                         const Vec3* normals) {
  return remote::call<calls::TriangleSurfacePoint>(hit, p0, p1, p2,
                                                   normals ? std::vector<Vec3>(normals, normals + 3) : std::vector<Vec3>{});
}
inline SurfacePoint sphereSurfacePoint(const Ray& ray, float t, const Point3& center, float radius) {
  return remote::call<calls::SphereSurfacePoint>(ray, t, center, radius);
}
}  // namespace pathlab::candidate
