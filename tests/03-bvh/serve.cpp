// The candidate's side of task 3's calls: the linked bvh.cpp.
#include "../remote/server.h"
#include "../remote/serve_images.h"
#include "calls.h"
#include "render/task_wiring.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::IntersectBox>(&intersectBox);
  server.serve<calls::BuildBvh>([](const std::vector<Aabb>& bounds) { return buildBvh(bounds); });
  server.serve<calls::IntersectClosest>(
      [](const Bvh& bvh, const Scene& scene, const std::vector<calls::RayInRange>& rays) {
        const LeafGeometry geometry(scene, bvh.primitives, kLinkedTasks.primitives);
        std::vector<calls::ClosestResult> results;
        for (const auto& [ray, range] : rays) {
          TraversalStats stats;
          auto hit = intersectClosest(bvh, geometry, ray, range, &stats);
          results.emplace_back(hit, stats);
        }
        return results;
      });
  server.serve<calls::IntersectAny>([](const Bvh& bvh, const Scene& scene, const std::vector<calls::RayInRange>& rays) {
    const LeafGeometry geometry(scene, bvh.primitives, kLinkedTasks.primitives);
    std::vector<calls::AnyResult> results;
    for (const auto& [ray, range] : rays) {
      TraversalStats stats;
      const bool blocked = intersectAny(bvh, geometry, ray, range, &stats);
      results.emplace_back(blocked, stats);
    }
    return results;
  });
  server.serve<calls::TestedSlots>(
      [](const Bvh& bvh, const Scene& scene, const std::vector<calls::RayInRange>& rays, bool anyHit) {
        LeafGeometry geometry(scene, bvh.primitives, kLinkedTasks.primitives);
        std::vector<std::vector<uint32_t>> tested(rays.size());
        for (size_t i = 0; i < rays.size(); ++i) {
          const auto& [ray, range] = rays[i];
          geometry.recordTests(&tested[i]);
          if (anyHit) {
            intersectAny(bvh, geometry, ray, range, nullptr);
          } else {
            intersectClosest(bvh, geometry, ray, range, nullptr);
          }
        }
        geometry.recordTests(nullptr);
        return tested;
      });
}

}  // namespace pathlab::remote
