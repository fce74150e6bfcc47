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
PATHLAB_REMOTE_CALL(IntersectBox, 1, std::optional<float>(Aabb, Ray, Vec3, Interval));
PATHLAB_REMOTE_CALL(BuildBvh, 2, Bvh(std::vector<Aabb>));
PATHLAB_REMOTE_CALL(IntersectClosest, 3, std::vector<ClosestResult>(Bvh, Scene, std::vector<RayInRange>));
PATHLAB_REMOTE_CALL(IntersectAny, 4, std::vector<AnyResult>(Bvh, Scene, std::vector<RayInRange>));
// The slots each ray's traversal tested, as the leaf geometry records them
// (the framework's log, not the candidate's own count): closest hit, or any hit.
PATHLAB_REMOTE_CALL(TestedSlots, 5, std::vector<std::vector<uint32_t>>(Bvh, Scene, std::vector<RayInRange>, bool));
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
