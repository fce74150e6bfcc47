// Task 3 — bounding volume hierarchy. Implemented in tasks/03-bvh/bvh.cpp
// (the student's file; where the task is not the student's, the programs
// link the course's reference in its place).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/leaf_geometry.h"
#include "util/aabb.h"
#include "util/ray.h"

namespace pathlab {

// One node of the tree, 32 bytes so two siblings share a 64-byte cache line.
struct BvhNode {
  Aabb bounds;                // 24 bytes: encloses every primitive below
  uint32_t leftOrFirst = 0;   //  4 bytes: interior: index of the left child (the right child is
                              //           leftOrFirst + 1); leaf: first slot in Bvh::primitives
  uint32_t count = 0;         //  4 bytes: 0 for an interior node; leaf: number of primitives

  bool isLeaf() const { return count > 0; }
};
static_assert(sizeof(BvhNode) == 32, "BvhNode must stay 32 bytes");

// The most primitives a leaf may hold.
inline constexpr uint32_t kMaxLeafSize = 8;
// The deepest a leaf may be (the root has depth 0): a traversal stack of
// kMaxBvhDepth entries never overflows.
inline constexpr uint32_t kMaxBvhDepth = 64;

// nodes[0] is the root. Children come after their parent (index greater than
// the parent's), siblings are adjacent. A leaf's primitives are the slots
// [leftOrFirst, leftOrFirst + count) of `primitives`, which lists every
// primitive index exactly once.
struct Bvh {
  std::vector<BvhNode> nodes;
  std::vector<uint32_t> primitives;
};

// Work done by one traversal, for the debugger's heat map and the tests.
struct TraversalStats {
  uint32_t nodesVisited = 0;    // nodes popped and processed
  uint32_t boxTests = 0;        // calls of intersectBox
  uint32_t primitiveTests = 0;  // calls of LeafGeometry::intersect
};

// T3.1: the ray parameter where the ray enters `box` within `range` (range.min
// if it starts inside), or nothing. `inverseDirection` = 1 / ray.direction,
// component-wise (an infinity for a zero component).
std::optional<float> intersectBox(const Aabb& box, const Ray& ray, const Vec3& inverseDirection, Interval range);

// T3.2: a BVH over primitives 0 .. primitiveBounds.size() - 1, built with the
// surface area heuristic. Leaves hold at most kMaxLeafSize primitives.
Bvh buildBvh(std::span<const Aabb> primitiveBounds);

// T3.3: the closest hit along `ray` within `range`.
std::optional<PrimitiveHit> intersectClosest(const Bvh& bvh, const LeafGeometry& geometry, const Ray& ray,
                                             Interval range, TraversalStats* stats = nullptr);

// T3.4: whether anything blocks `ray` within `range`; stops at the first hit.
bool intersectAny(const Bvh& bvh, const LeafGeometry& geometry, const Ray& ray, Interval range,
                  TraversalStats* stats = nullptr);

}  // namespace pathlab
