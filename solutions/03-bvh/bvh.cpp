// Task 3 — bounding volume hierarchy (reference solution): binned SAH build,
// ordered stack traversal with a NaN-safe slab test. (The framework's render
// path walks the same tree 8-wide: framework/render/wide_bvh.cpp.)
#include "tasks/bvh.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

namespace pathlab {
namespace {

constexpr int kBins = 16;
constexpr float kTraversalCost = 1.0f;    // cost of visiting an interior node...
constexpr float kIntersectionCost = 1.0f; // ...relative to testing one primitive
constexpr uint32_t kMedianSplitDepth = 32;  // below this depth, split in halves: depth stays bounded
// Rounding in the slab test can shrink an interval that really encloses a
// hit; widen exits by 2 gamma(3) (pbrt-v4) so such boxes are never missed.
constexpr float kWidenExit = 1.0f + 2.0f * (3.0f * 0x1.0p-24f) / (1.0f - 3.0f * 0x1.0p-24f);

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  float cost = kInfinity;
};

class Builder {
 public:
  Builder(std::span<const Aabb> bounds, Bvh& bvh) : bounds_(bounds), bvh_(bvh) {
    centroids_.reserve(bounds.size());
    for (const Aabb& b : bounds) centroids_.push_back(b.centroid());
  }

  void build() {
    const uint32_t n = uint32_t(bounds_.size());
    if (n == 0) return;
    bvh_.primitives.resize(n);
    std::iota(bvh_.primitives.begin(), bvh_.primitives.end(), 0u);
    bvh_.nodes.reserve(2 * size_t(n) - 1);  // a binary tree with n leaves at most: no reallocation
    bvh_.nodes.push_back(BvhNode{Aabb{}, 0, n});
    std::vector<std::pair<uint32_t, uint32_t>> todo = {{0, 0}};  // (node, depth)
    while (!todo.empty()) {
      auto [node, depth] = todo.back();
      todo.pop_back();
      if (subdivide(node, depth)) {
        const uint32_t left = bvh_.nodes[node].leftOrFirst;
        todo.push_back({left + 1, depth + 1});
        todo.push_back({left, depth + 1});
      }
    }
  }

 private:
  // Sets the node's box; splits it in two and returns true, or leaves it a leaf.
  bool subdivide(uint32_t index, uint32_t depth) {
    BvhNode& node = bvh_.nodes[index];
    const uint32_t first = node.leftOrFirst, count = node.count;
    Aabb centroidBounds;
    for (uint32_t s = first; s < first + count; ++s) {
      node.bounds.grow(bounds_[bvh_.primitives[s]]);
      centroidBounds.grow(centroids_[bvh_.primitives[s]]);
    }
    if (count == 1) return false;

    uint32_t leftCount = 0;
    const Split split = depth < kMedianSplitDepth ? bestSplit(node, centroidBounds, first, count) : Split{};
    const float leafCost = kIntersectionCost * float(count);
    if (split.axis >= 0 && (split.cost < leafCost || count > kMaxLeafSize)) {
      // Partition: primitives whose centroid falls in bins [0, split.bin] go left.
      uint32_t* begin = bvh_.primitives.data() + first;
      uint32_t* middle = std::partition(begin, begin + count, [&](uint32_t p) {
        return binOf(centroids_[p], centroidBounds, split.axis) <= split.bin;
      });
      leftCount = uint32_t(middle - begin);
    } else if (count > kMaxLeafSize || depth >= kMedianSplitDepth) {
      // No useful SAH split (e.g. every centroid equal), or too deep: halves.
      if (count <= kMaxLeafSize) return false;
      const int axis = centroidBounds.largestAxis();
      uint32_t* begin = bvh_.primitives.data() + first;
      std::nth_element(begin, begin + count / 2, begin + count,
                       [&](uint32_t a, uint32_t b) { return centroids_[a][axis] < centroids_[b][axis]; });
      leftCount = count / 2;
    } else {
      return false;  // a leaf is cheaper
    }

    const uint32_t left = uint32_t(bvh_.nodes.size());
    bvh_.nodes.push_back(BvhNode{Aabb{}, first, leftCount});
    bvh_.nodes.push_back(BvhNode{Aabb{}, first + leftCount, count - leftCount});
    BvhNode& parent = bvh_.nodes[index];  // push_back never reallocates (reserved), but be explicit
    parent.leftOrFirst = left;
    parent.count = 0;
    return true;
  }

  // The same arithmetic as the binning in bestSplit, so partitions match the counts.
  static int binOf(const Point3& centroid, const Aabb& centroidBounds, int axis) {
    const float scale = binScale(centroidBounds.extent()[axis]);
    return std::min(int((centroid[axis] - centroidBounds.min[axis]) * scale), kBins - 1);
  }

  // kBins / extent (0 for an axis where every centroid is equal), at most the
  // largest float: below extent 1e-37 the quotient overflows, and
  // (centroid - min) * inf is NaN for the lowest centroid, whose int() is undefined.
  static float binScale(float extent) {
    return extent > 0.0f ? std::min(float(kBins) / extent, std::numeric_limits<float>::max()) : 0.0f;
  }

  // SAH: cost(split) = C_trav + C_isect * (A_left N_left + A_right N_right) / A_node,
  // for every boundary between the 16 bins of every axis. One pass over the
  // primitives fills the bins of all three axes.
  Split bestSplit(const BvhNode& node, const Aabb& centroidBounds, uint32_t first, uint32_t count) const {
    std::array<std::array<Aabb, kBins>, 3> binBounds;
    std::array<std::array<uint32_t, kBins>, 3> binCount{};
    const Vec3 extent = centroidBounds.extent();
    const Vec3 scale(binScale(extent.x), binScale(extent.y), binScale(extent.z));
    for (uint32_t s = first; s < first + count; ++s) {
      const uint32_t p = bvh_.primitives[s];
      const Vec3 offset = (centroids_[p] - centroidBounds.min) * scale;
      for (int axis = 0; axis < 3; ++axis) {
        const int b = std::min(int(offset[axis]), kBins - 1);
        binBounds[axis][b].grow(bounds_[p]);
        ++binCount[axis][b];
      }
    }
    Split best;
    const float parentArea = node.bounds.surfaceArea();
    for (int axis = 0; axis < 3; ++axis) {
      if (!(extent[axis] > 0.0f)) continue;  // all centroids equal along this axis
      // Sweep from the right to know each suffix, then from the left.
      std::array<float, kBins> rightArea{};
      std::array<uint32_t, kBins> rightCount{};
      Aabb box;
      uint32_t n = 0;
      for (int b = kBins - 1; b > 0; --b) {
        box.grow(binBounds[axis][b]);
        n += binCount[axis][b];
        rightArea[b] = box.surfaceArea();
        rightCount[b] = n;
      }
      box = Aabb{};
      n = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        box.grow(binBounds[axis][b]);
        n += binCount[axis][b];
        if (n == 0 || rightCount[b + 1] == 0) continue;
        const float cost = kTraversalCost + kIntersectionCost *
                                                (box.surfaceArea() * float(n) + rightArea[b + 1] * float(rightCount[b + 1])) /
                                                parentArea;
        if (cost < best.cost) best = Split{axis, b, cost};
      }
    }
    return best;
  }

  std::span<const Aabb> bounds_;
  std::vector<Point3> centroids_;
  Bvh& bvh_;
};

}  // namespace

std::optional<float> intersectBox(const Aabb& box, const Ray& ray, const Vec3& inverseDirection, Interval range) {
  float entry = range.min, exit = range.max;
  for (int axis = 0; axis < 3; ++axis) {
    const float t0 = (box.min[axis] - ray.origin[axis]) * inverseDirection[axis];
    const float t1 = (box.max[axis] - ray.origin[axis]) * inverseDirection[axis];
    // A ray lying in a slab plane gives 0 * inf = NaN: that axis sets no
    // limit, so NaN must reach the comparisons below, which then ignore it.
    const float near = (t0 < t1 || t0 != t0) ? t0 : t1;
    const float far = ((t0 > t1 || t0 != t0) ? t0 : t1) * kWidenExit;
    entry = near > entry ? near : entry;
    exit = far < exit ? far : exit;
  }
  if (!(entry <= exit)) return std::nullopt;
  return entry;
}

Bvh buildBvh(std::span<const Aabb> primitiveBounds) {
  Bvh bvh;
  Builder(primitiveBounds, bvh).build();
  return bvh;
}

std::optional<PrimitiveHit> intersectClosest(const Bvh& bvh, const LeafGeometry& geometry, const Ray& ray,
                                             Interval range, TraversalStats* stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  const Vec3 inverseDirection = 1.0f / ray.direction;
  if (stats) ++stats->boxTests;
  if (!intersectBox(bvh.nodes[0].bounds, ray, inverseDirection, range)) return std::nullopt;
  // A child's entry t, +inf for a miss: one number to compare and to stack.
  auto entry = [&](uint32_t child) {
    return intersectBox(bvh.nodes[child].bounds, ray, inverseDirection, range).value_or(kInfinity);
  };

  struct Pending {
    uint32_t node;
    float tEntry;
  };
  std::array<Pending, kMaxBvhDepth> stack;
  int size = 0;
  std::optional<PrimitiveHit> closest;
  uint32_t index = 0;
  while (true) {
    const BvhNode& node = bvh.nodes[index];
    if (stats) ++stats->nodesVisited;
    if (node.isLeaf()) {
      for (uint32_t slot = node.leftOrFirst; slot < node.leftOrFirst + node.count; ++slot) {
        if (stats) ++stats->primitiveTests;
        if (auto hit = geometry.intersect(slot, ray, range)) {
          closest = hit;
          range.max = hit->t;  // from now on only closer hits count
        }
      }
    } else {
      // Test both children; go to the nearer, keep the farther for later.
      uint32_t near = node.leftOrFirst, far = near + 1;
      float tNear = entry(near), tFar = entry(far);
      if (stats) stats->boxTests += 2;
      if (tFar < tNear) std::swap(near, far), std::swap(tNear, tFar);
      if (tNear != kInfinity) {
        if (tFar != kInfinity) stack[size++] = {far, tFar};
        index = near;
        continue;
      }
    }
    // Pop the next subtree that can still hold a closer hit.
    while (true) {
      if (size == 0) return closest;
      const Pending next = stack[--size];
      if (next.tEntry <= range.max) {
        index = next.node;
        break;
      }
    }
  }
}

bool intersectAny(const Bvh& bvh, const LeafGeometry& geometry, const Ray& ray, Interval range,
                  TraversalStats* stats) {
  if (bvh.nodes.empty()) return false;
  const Vec3 inverseDirection = 1.0f / ray.direction;
  if (stats) ++stats->boxTests;
  if (!intersectBox(bvh.nodes[0].bounds, ray, inverseDirection, range)) return false;
  // The closest-hit loop without ordering or culling: any hit ends it.
  std::array<uint32_t, kMaxBvhDepth> stack;
  int size = 0;
  uint32_t index = 0;
  while (true) {
    const BvhNode& node = bvh.nodes[index];
    if (stats) ++stats->nodesVisited;
    if (node.isLeaf()) {
      for (uint32_t slot = node.leftOrFirst; slot < node.leftOrFirst + node.count; ++slot) {
        if (stats) ++stats->primitiveTests;
        if (geometry.intersect(slot, ray, range)) return true;
      }
    } else {
      const uint32_t left = node.leftOrFirst;
      const bool hitLeft = intersectBox(bvh.nodes[left].bounds, ray, inverseDirection, range).has_value();
      const bool hitRight = intersectBox(bvh.nodes[left + 1].bounds, ray, inverseDirection, range).has_value();
      if (stats) stats->boxTests += 2;
      if (hitLeft) {
        if (hitRight) stack[size++] = left + 1;
        index = left;
        continue;
      }
      if (hitRight) {
        index = left + 1;
        continue;
      }
    }
    if (size == 0) return false;
    index = stack[--size];
  }
}

}  // namespace pathlab
