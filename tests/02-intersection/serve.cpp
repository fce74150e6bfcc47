// The candidate's side of task 2's calls: the linked intersection.cpp.
#include "wire/server.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::IntersectTriangle>(&intersectTriangle);
  server.serve<calls::IntersectSphere>(&intersectSphere);
  server.serve<calls::TriangleSurfacePoint>(
      [](const TriangleHit& hit, const Point3& p0, const Point3& p1, const Point3& p2, const std::vector<Vec3>& normals) {
        return triangleSurfacePoint(hit, p0, p1, p2, normals.size() == 3 ? normals.data() : nullptr);
      });
  server.serve<calls::SphereSurfacePoint>(&sphereSurfacePoint);
  server.serve<calls::MeshHits>(
      [](const std::vector<Point3>& positions, const std::vector<glm::uvec3>& triangles, const std::vector<Ray>& rays) {
        std::vector<std::vector<calls::MeshHit>> hits(rays.size());
        for (size_t r = 0; r < rays.size(); ++r) {
          for (size_t k = 0; k < triangles.size(); ++k) {
            const glm::uvec3& t = triangles[k];
            auto hit = intersectTriangle(rays[r], Interval{}, positions.at(t.x), positions.at(t.y), positions.at(t.z));
            if (hit) hits[r].emplace_back(uint32_t(k), hit->t);
          }
        }
        return hits;
      });
}

}  // namespace pathlab::remote
