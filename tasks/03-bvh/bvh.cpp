// Task 3 — bounding volume hierarchy
//
// Goal: a tree of boxes so that a ray tests a few dozen primitives instead
// of all of them: the difference between minutes and hours.
// Handout: tasks/03-bvh/README.md
//
// Functions to write (declared in framework/tasks/bvh.h):
//   T3.1 intersectBox      ray–box slab test
//   T3.2 buildBvh          binned surface-area-heuristic (SAH) build
//   T3.3 intersectClosest  closest hit, nearer child first
//   T3.4 intersectAny      occlusion: stop at the first hit
//
// Check your work:
//   ./build/pathlab debug --task 3 --view heatmap -o heatmap.png   (also: boxes)
//   ctest --test-dir build -R 03-bvh --output-on-failure
#include "tasks/bvh.h"

#include <algorithm>
#include <array>
#include <numeric>

#include "util/todo.h"

namespace pathlab {

// T3.1 — Ray–box intersection (the slab test).
//
// A box is the intersection of three slabs min[a] <= x[a] <= max[a]. Along
// the ray, slab a is crossed for t between
//   t0 = (min[a] - origin[a]) * inverseDirection[a]   and
//   t1 = (max[a] - origin[a]) * inverseDirection[a]
// (swapped when the direction is negative). The ray is inside the box from
// the largest entry to the smallest exit, clipped to `range`; it hits when
// entry <= exit. Return the entry t.
//
// PITFALL: a direction component of 0 gives inverseDirection = +-inf: the ray
// never leaves that slab, which the formulas above already say — unless the
// origin lies exactly on a slab plane, where 0 * inf = NaN. Make sure a NaN
// sets no limit (compare so that NaN leaves entry and exit unchanged).
// PITFALL: rounding can shrink [entry, exit] for a box that truly encloses a
// hit; multiply each exit by (1 + 2 gamma(3)), gamma(3) = 3 eps / (1 - 3 eps),
// eps = 2^-24, so such boxes are never missed.
std::optional<float> intersectBox(const Aabb& box, const Ray& ray, const Vec3& inverseDirection, Interval range) {
  // TODO(T3.1): the slab test.
  PATHLAB_TODO("T3.1");
  (void)box, (void)ray, (void)inverseDirection, (void)range;
  return std::nullopt;
}

// T3.2 — Build the tree with the surface area heuristic.
//
// A random ray that hits a box B hits a child box C with probability
// area(C) / area(B). So the expected cost of splitting a node's primitives
// into L and R is
//   cost(split) = C_trav + C_isect * (area(L) N_L + area(R) N_R) / area(node)
// and of keeping them in a leaf  cost(leaf) = C_isect * N  (take C_trav = C_isect = 1).
//
// Recipe:
//   1. bvh.primitives = 0, 1, ..., n-1; the root covers all of them. An empty
//      input gives an empty Bvh.
//   2. For a node: its box is the union of its primitives' boxes.
//   3. Binning: along each axis, divide the extent of the primitives'
//      *centroids* into 16 bins; for each bin keep a count and a box. Sweep
//      the bins to evaluate the split between every pair of neighbours.
//   4. If the best split is cheaper than a leaf (or the node holds more than
//      kMaxLeafSize primitives), partition the node's slots of
//      bvh.primitives (std::partition) and create the two children next to
//      each other at the end of bvh.nodes; then subdivide them too.
//   5. Otherwise the node is a leaf: leftOrFirst = first slot, count = N.
//
// PITFALL: when every centroid is the same point no bin split exists; a node
// with more than kMaxLeafSize primitives must still be split (in halves by
// index), or the leaf size bound breaks.
// PITFALL: bvh.nodes.push_back may reallocate: take a fresh reference to the
// parent afterwards (or reserve 2n - 1 nodes first).
// PITFALL: keep leaves within kMaxBvhDepth of the root (split in halves deep down).
Bvh buildBvh(std::span<const Aabb> primitiveBounds) {
  // TODO(T3.2): the binned SAH build.
  PATHLAB_TODO("T3.2");
  (void)primitiveBounds;
  return Bvh{};
}

// T3.3 — Closest hit.
//
// Keep a stack of nodes to visit. At an interior node test both children's
// boxes with the current range; visit the nearer one next and push the
// farther one together with its entry t. At a leaf, test each slot with
// geometry.intersect(slot, ray, range) and on a hit shrink range.max to its
// t: farther boxes and primitives are then rejected for free. When popping,
// skip entries whose entry t is already beyond range.max.
//
// Compute inverseDirection = 1.0f / ray.direction once per ray.
// If `stats` is not null, count nodesVisited, boxTests and primitiveTests
// (the heat map and the tests read them).
std::optional<PrimitiveHit> intersectClosest(const Bvh& bvh, const LeafGeometry& geometry, const Ray& ray,
                                             Interval range, TraversalStats* stats) {
  // TODO(T3.3): ordered, stack-based traversal.
  PATHLAB_TODO("T3.3");
  (void)bvh, (void)geometry, (void)ray, (void)range, (void)stats;
  return std::nullopt;
}

// T3.4 — Any hit (shadow rays).
//
// The same traversal without ordering: return true at the first primitive
// hit within `range`; false once the stack is empty.
bool intersectAny(const Bvh& bvh, const LeafGeometry& geometry, const Ray& ray, Interval range,
                  TraversalStats* stats) {
  // TODO(T3.4): traversal with early exit.
  PATHLAB_TODO("T3.4");
  (void)bvh, (void)geometry, (void)ray, (void)range, (void)stats;
  return false;
}

}  // namespace pathlab
