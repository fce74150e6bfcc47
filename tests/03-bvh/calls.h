// Task 3's remote calls: the judge's view of the student's bvh.cpp. A
// traversal runs in the candidate over the scene's leaf geometry in the
// order of the tree's `primitives`, as the renderer does.
#pragma once

#include <tuple>
#include <vector>

#include "wire/call.h"
#include "core/leaf_geometry.h"
#include "core/scene.h"
#include "render/task_wiring.h"
#include "tasks/bvh.h"

// This task's own value types on the wire (grader/wire/wire.h).
namespace pathlab::wire {
PATHLAB_WIRE_FIELDS(TraversalStats, s.nodesVisited, s.boxTests, s.primitiveTests);
}  // namespace pathlab::wire

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
// A traversal whose primitive tests the judge serves: the candidate's leaf
// geometry asks the judge for each one (the ray's index, the slot and the
// range: two uint32_t and an Interval; the reply an optional PrimitiveHit,
// the judge's own test), so the judge knows every slot each traversal
// tested and every hit it was told of. Per ray: whether it found a hit
// (intersectAny: was blocked), and the traversal's own statistics: claims,
// which the tests judge by the judge's record (a hit claimed must be one the
// judge served; the work counted must be the work the judge served).
using ServedResult = std::tuple<bool, TraversalStats>;
PATHLAB_REMOTE_CALL(IntersectBox, 1, shape::Fixed, std::optional<float>(Aabb, Ray, Vec3, Interval));
PATHLAB_REMOTE_CALL(BuildBvh, 2, BvhShape, Bvh(std::vector<Aabb>));
PATHLAB_REMOTE_CALL(IntersectClosest, 3, shape::OnePer<2>, std::vector<ClosestResult>(Bvh, Scene, std::vector<RayInRange>));
PATHLAB_REMOTE_CALL(IntersectAny, 4, shape::OnePer<2>, std::vector<AnyResult>(Bvh, Scene, std::vector<RayInRange>));
// Each ray's traversal, closest hit or any hit, with its primitive tests served
// by the judge (candidate::traverseServed records them: not the candidate's own count).
PATHLAB_REMOTE_CALL(TraverseServed, 5, shape::OnePer<2>, std::vector<ServedResult>(Bvh, Scene, std::vector<RayInRange>, bool));
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

// A traversal of each ray (intersectAny with anyHit, else intersectClosest)
// whose primitive tests the judge served, and what the judge saw of it.
struct ServedTest {
  uint32_t slot = 0;                // the slot the traversal asked the judge to test
  Interval range;                   // with the range it asked with
  std::optional<PrimitiveHit> hit;  // and the judge's own answer (its test of that slot, within that range)
};
struct ServedTraversal {
  bool found = false;             // what the traversal returned: a hit, or blocked (its claim)
  TraversalStats stats;           // what it counted (its claim)
  std::vector<ServedTest> served;  // the tests the judge served it, in order: the judge's own record
  size_t tested() const { return served.size(); }
  // The judge's closest hit among those it served within `range` (the ray's own), if any.
  std::optional<PrimitiveHit> closestServed(Interval range) const {
    std::optional<PrimitiveHit> closest;
    for (const ServedTest& test : served) {
      if (test.hit && range.contains(test.hit->t) && (!closest || test.hit->t < closest->t)) closest = test.hit;
    }
    return closest;
  }
  // How many tests followed the first one the judge answered with a hit (any hit must stop there).
  size_t testsAfterFirstHit() const {
    for (size_t k = 0; k < served.size(); ++k)
      if (served[k].hit) return served.size() - k - 1;
    return 0;
  }
};
// `scene` with every primitive where it is counted but nowhere (every vertex and sphere at the origin): what
// a served traversal is sent, so that every hit it knows of is one the judge served it (a candidate sent the
// geometry could test it itself and ask for the one slot that hits).
inline Scene withoutGeometry(Scene scene) {
  for (TriangleMesh& mesh : scene.meshes) {
    for (Point3& p : mesh.positions) p = Point3(0.0f);
    for (Vec3& n : mesh.normals) n = Vec3(0.0f, 0.0f, 1.0f);
  }
  for (Sphere& sphere : scene.spheres) sphere.center = Point3(0.0f);
  return scene;
}

inline std::vector<ServedTraversal> traverseServed(const Bvh& bvh, const Scene& scene,
                                                   const std::vector<calls::RayInRange>& rays, bool anyHit) {
  for (uint32_t primitive : bvh.primitives) {  // the judge indexes the scene with them (validateBvh checks more)
    if (primitive >= scene.primitives.size()) throw remote::CandidateError("the tree names primitive " + std::to_string(primitive) + " of " + std::to_string(scene.primitives.size()));
  }
  const LeafGeometry geometry(scene, bvh.primitives, kLinkedTasks.primitives);  // the judge's (reference) tests
  std::vector<ServedTraversal> traversals(rays.size());
  const remote::AskHandler serve = [&](const std::string& question) {
    const auto [ray, slot, range] = remote::readAsk<uint32_t, uint32_t, Interval>(question, "a primitive test");
    if (ray >= rays.size() || slot >= geometry.size()) {
      throw remote::CandidateError("the candidate asked to test slot " + std::to_string(slot) + " for ray " +
                                   std::to_string(ray) + " (the tree has " + std::to_string(geometry.size()) +
                                   " slots, the request " + std::to_string(rays.size()) + " rays)");
    }
    std::vector<ServedTest>& served = traversals[ray].served;
    if (served.size() >= 4 * size_t(geometry.size()) + 16) {  // the judge's own log stays bounded
      throw remote::CandidateError("ray " + std::to_string(ray) + "'s traversal tested over " +
                                   std::to_string(served.size()) + " primitives, four times the tree's");
    }
    const std::optional<PrimitiveHit> hit = geometry.intersect(slot, std::get<0>(rays[ray]), range);
    served.push_back({slot, range, hit});
    wire::Writer reply;
    reply.put(hit);
    return reply.bytes();
  };
  const std::vector<calls::ServedResult> answers =
      remote::callMany<calls::TraverseServed>({{bvh, withoutGeometry(scene), rays, anyHit}}, &serve).front();
  for (size_t i = 0; i < rays.size(); ++i) std::tie(traversals[i].found, traversals[i].stats) = answers[i];
  return traversals;
}

}  // namespace pathlab::candidate
