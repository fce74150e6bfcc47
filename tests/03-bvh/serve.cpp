// The candidate's side of task 3's calls: the linked bvh.cpp.
#include "wire/server.h"
#include "serve_images.h"
#include "calls.h"
#include "render/task_wiring.h"

namespace pathlab::remote {
namespace {

// TraverseServed's primitive tests: each asks the judge, which tests the
// slot the geometry is about to test (the last it logged) for the current
// ray, and counts it.
struct Served {
  uint32_t ray = 0;
  const std::vector<uint32_t>* slots = nullptr;
} served;

std::optional<PrimitiveHit> askJudge(Interval range) {
  wire::Writer question;
  question.put(served.ray);
  question.put(served.slots->back());
  question.put(range);
  return wire::Reader(ask(question.bytes())).get<std::optional<PrimitiveHit>>();
}
std::optional<TriangleHit> askTriangle(const Ray&, Interval range, const Point3&, const Point3&, const Point3&) {
  const std::optional<PrimitiveHit> hit = askJudge(range);
  return hit ? std::optional<TriangleHit>(TriangleHit{hit->t, hit->b1, hit->b2}) : std::nullopt;
}
std::optional<float> askSphere(const Ray&, Interval range, const Point3&, float) {
  const std::optional<PrimitiveHit> hit = askJudge(range);
  return hit ? std::optional<float>(hit->t) : std::nullopt;
}

}  // namespace

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
  server.serve<calls::TraverseServed>(
      [](const Bvh& bvh, const Scene& scene, const std::vector<calls::RayInRange>& rays, bool anyHit) {
        LeafGeometry geometry(scene, bvh.primitives, PrimitiveTests{&askTriangle, &askSphere});
        std::vector<uint32_t> slots;  // the geometry logs each slot just before it tests it
        geometry.recordTests(&slots);
        std::vector<calls::ServedResult> results;
        for (size_t i = 0; i < rays.size(); ++i) {
          served = {uint32_t(i), &slots};
          const auto& [ray, range] = rays[i];
          TraversalStats stats;
          const bool found = anyHit ? intersectAny(bvh, geometry, ray, range, &stats)
                                    : intersectClosest(bvh, geometry, ray, range, &stats).has_value();
          results.emplace_back(found, stats);
        }
        return results;
      });
}

}  // namespace pathlab::remote
