// Task 3's remote calls: the judge's view of the student's bvh.cpp. A
// traversal runs in the candidate over the scene's leaf geometry in the
// order of the tree's `primitives`, as the renderer does.
#pragma once

#include <tuple>
#include <vector>

#include "../remote/call.h"
#include "core/scene.h"
#include "tasks/bvh.h"

namespace pathlab::calls {
using RayInRange = std::tuple<Ray, Interval>;
using ClosestResult = std::tuple<std::optional<PrimitiveHit>, TraversalStats>;
using AnyResult = std::tuple<bool, TraversalStats>;

// A tree over n boxes: `primitives` lists n slots (validateBvh checks that
// each box is in one), and a binary tree whose leaves hold at least one box
// has at most 2 n - 1 nodes (a few more: a builder may leave slots unused,
// as Bikker's leaves node 1).
struct BvhShape {
  using Args = std::tuple<std::vector<Aabb>>;
  static size_t mostNodes(const Args& args) { return 2 * std::get<0>(args).size() + 2; }
  static uint64_t maxBytes(shape::Of<Bvh>, const Args& args) {
    return 16 + mostNodes(args) * wire::maxWireSize<BvhNode>() + std::get<0>(args).size() * sizeof(uint32_t);
  }
  static void read(wire::Reader& r, Bvh& bvh, const Args& args) {
    const size_t nodes = r.count(wire::minWireSize<BvhNode>());
    if (nodes > mostNodes(args)) {
      throw wire::WireError("a tree of " + std::to_string(nodes) + " nodes over " +
                            std::to_string(std::get<0>(args).size()) + " boxes (at most 2 n + 2)");
    }
    wire::readElements(r, bvh.nodes, nodes);
    r.expectCount(std::get<0>(args).size(), "the tree's primitives (one slot per box)");
    wire::readElements(r, bvh.primitives, std::get<0>(args).size());
  }
};
// The slots of the tree a ray's traversal tested: each below the tree's
// slot count, each at most twice per ray.
using TraversalArgs = std::tuple<Bvh, Scene, std::vector<RayInRange>, bool>;
struct Slots {
  static size_t of(const TraversalArgs& args) { return std::get<0>(args).primitives.size(); }
};
struct SlotTests {
  static size_t of(const TraversalArgs& args) { return 2 * Slots::of(args); }
};
PATHLAB_REMOTE_CALL(IntersectBox, 1, shape::Fixed, std::optional<float>(Aabb, Ray, Vec3, Interval));
PATHLAB_REMOTE_CALL(BuildBvh, 2, BvhShape, Bvh(std::vector<Aabb>));
PATHLAB_REMOTE_CALL(IntersectClosest, 3, shape::OnePer<2>, std::vector<ClosestResult>(Bvh, Scene, std::vector<RayInRange>));
PATHLAB_REMOTE_CALL(IntersectAny, 4, shape::OnePer<2>, std::vector<AnyResult>(Bvh, Scene, std::vector<RayInRange>));
// The slots each ray's traversal tested, as the leaf geometry records them
// (the framework's log, not the candidate's own count): closest hit, or any hit.
using SlotsPerRay = shape::OnePer<2, shape::AtMost<SlotTests, shape::IndexBelow<Slots>>>;
PATHLAB_REMOTE_CALL(TestedSlots, 5, SlotsPerRay, std::vector<std::vector<uint32_t>>(Bvh, Scene, std::vector<RayInRange>, bool));
}  // namespace pathlab::calls

namespace pathlab::candidate {

inline std::optional<float> intersectBox(const Aabb& box, const Ray& ray, const Vec3& inverseDirection, Interval range) {
  return remote::call<calls::IntersectBox>(box, ray, inverseDirection, range);
}

inline Bvh buildBvh(const std::vector<Aabb>& primitiveBounds) { return remote::call<calls::BuildBvh>(primitiveBounds); }

// intersectClosest / intersectAny over `scene`'s primitives stored in the order of bvh.primitives.
inline std::vector<calls::ClosestResult> intersectClosest(const Bvh& bvh, const Scene& scene,
                                                          const std::vector<calls::RayInRange>& rays) {
  return remote::call<calls::IntersectClosest>(bvh, scene, rays);
}
inline std::optional<PrimitiveHit> intersectClosest(const Bvh& bvh, const Scene& scene, const Ray& ray, Interval range) {
  return std::get<0>(intersectClosest(bvh, scene, {{ray, range}}).at(0));
}
inline std::vector<calls::AnyResult> intersectAny(const Bvh& bvh, const Scene& scene,
                                                  const std::vector<calls::RayInRange>& rays) {
  return remote::call<calls::IntersectAny>(bvh, scene, rays);
}
inline bool intersectAny(const Bvh& bvh, const Scene& scene, const Ray& ray, Interval range,
                         TraversalStats* stats = nullptr) {
  auto [blocked, work] = intersectAny(bvh, scene, {{ray, range}}).at(0);
  if (stats) *stats = work;
  return blocked;
}

inline std::vector<std::vector<uint32_t>> testedSlots(const Bvh& bvh, const Scene& scene,
                                                     const std::vector<calls::RayInRange>& rays, bool anyHit) {
  return remote::call<calls::TestedSlots>(bvh, scene, rays, anyHit);
}

}  // namespace pathlab::candidate
