// Ray queries against a whole scene through task 3's BVH. If the BVH is
// missing (task 3 not done) or breaks its invariants, the accelerator says so
// once and falls back to brute force, so a student's mistake never crashes
// the renderer.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/hit.h"
#include "core/leaf_geometry.h"
#include "core/scene.h"
#include "core/trace.h"
#include "render/wide_bvh.h"
#include "tasks/bvh.h"

namespace pathlab {

// "" when `bvh` is a well-formed tree over `primitiveCount` primitives, else
// the first broken rule (children after parents, siblings adjacent, leaf
// ranges in bounds, every primitive exactly once, leaf size, child boxes
// inside their parent).
std::string validateBvh(const Bvh& bvh, size_t primitiveCount, const std::vector<Aabb>* bounds = nullptr);

// SAH cost of a tree: sum over nodes of area(node)/area(root) times
// (1 for an interior node, count for a leaf). Comparable between builders.
double sahCost(const Bvh& bvh);

// Shape of a tree, for the debugger and the benchmark.
struct BvhStatistics {
  size_t nodes = 0;
  size_t leaves = 0;
  uint32_t maxDepth = 0;
  std::vector<size_t> leafSizes;  // leafSizes[k] = number of leaves with k primitives
  double sahCost = 0.0;
};
BvhStatistics bvhStatistics(const Bvh& bvh);
std::string formatBvhStatistics(const BvhStatistics& statistics);

// The work a tree makes closest-hit rays do, whoever wrote the traversal:
// the framework's own ordered walk (the nearer child first; a node skipped
// when its box is entered beyond the closest hit so far) over the tree's
// boxes, with `geometry`'s tests in the leaves. It scores the tree alone, so
// a traversal's own counters are never trusted (the grader's leaderboard).
struct TreeCost {
  size_t rays = 0;
  double nodesPerRay = 0.0;           // nodes whose box the walk entered
  double primitiveTestsPerRay = 0.0;  // leaf primitives tested
  // The measure Dartmouth's Darts leaderboard uses: lower is better.
  double score() const { return nodesPerRay + 10.0 * primitiveTestsPerRay; }
};
TreeCost treeCost(const Bvh& bvh, const LeafGeometry& geometry, std::span<const Ray> rays);
// side x side rays fanning out from a point outside `box` (beyond its +z
// face, looking along -z) through all of it: the same rays for any builder.
std::vector<Ray> raysThroughBox(const Aabb& box, int side);
// "31.3 = 12.3 nodes + 10 x 1.90 primitive tests per ray" (the score first; lower is better)
std::string formatTreeCost(const TreeCost& cost);

// How rendering walks task 3's tree: Task3 calls the linked task-3 code
// (intersectClosest, intersectAny); Fast collapses the same tree into the
// framework's 8-wide layout (wide_bvh.h) and tests eight boxes and eight
// triangles at a time (AVX2; four per instruction without it), with the
// reference task 2's arithmetic: the same hits.
// Fast is the default where tasks 2 and 3 are both the reference's; a
// student's render runs their own code.
enum class Traversal { Task3, Fast };

std::optional<Traversal> traversalFromName(const std::string& name);
const char* traversalName(Traversal traversal);
// The default for a build whose tasks `taskSummary` describes
// ("1:reference 2:student ...", as CMake records it): Fast only when tasks 2
// and 3 are the reference.
Traversal defaultTraversal(const std::string& taskSummary);

class Accelerator final : public RayQueries {
 public:
  explicit Accelerator(const Scene& scene, Traversal traversal = Traversal::Task3);

  std::optional<Hit> intersect(const Ray& ray, Interval range, TraversalStats* stats = nullptr) const;
  bool occluded(const Ray& ray, Interval range, TraversalStats* stats = nullptr) const;

  // RayQueries, for TraceContext.
  std::optional<Hit> closestHit(const Ray& ray, Interval range) const override { return intersect(ray, range); }
  bool anyHit(const Ray& ray, Interval range) const override { return occluded(ray, range); }

  bool usesBvh() const { return usesBvh_; }
  const Bvh& bvh() const { return bvh_; }
  const LeafGeometry& geometry() const { return geometry_; }
  double buildSeconds() const { return buildSeconds_; }

 private:
  // Traversal::Fast: the hit record from data made once per primitive (a flat
  // triangle's unit normal, its material) with the reference task 2's
  // arithmetic, so the same records as surfaceHit at less cost per hit.
  struct SurfaceData {
    Vec3 normal;        // flat triangles: normalize(cross(p1 - p0, p2 - p0))
    uint32_t material;  // index into Scene::materials
    uint32_t kind;      // kFlat, kSmooth (vertex normals) or kSphere
  };
  enum : uint32_t { kFlat, kSmooth, kSphere };
  Hit fastSurfaceHit(const Ray& ray, const PrimitiveHit& hit) const;

  const Scene& scene_;
  std::vector<SurfaceData> surfaces_;  // Traversal::Fast only
  Bvh bvh_;
  LeafGeometry geometry_;
  WideBvh wide_;  // Traversal::Fast only
  Traversal traversal_;
  bool usesBvh_ = false;
  double buildSeconds_ = 0.0;
};

}  // namespace pathlab
