#include "render/accelerator.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <mutex>

#include "render/scene_intersect.h"
#include "render/task_wiring.h"

namespace pathlab {

std::string validateBvh(const Bvh& bvh, size_t primitiveCount, const std::vector<Aabb>* bounds) {
  auto where = [](size_t i) { return "node " + std::to_string(i) + ": "; };
  if (primitiveCount == 0) return bvh.nodes.empty() ? "" : "a scene without primitives needs no nodes";
  if (bvh.nodes.empty()) return "no nodes";
  if (bvh.primitives.size() != primitiveCount) {
    return "primitives lists " + std::to_string(bvh.primitives.size()) + " entries for " +
           std::to_string(primitiveCount) + " primitives";
  }
  std::vector<uint8_t> slotSeen(primitiveCount, 0), primitiveSeen(primitiveCount, 0), nodeSeen(bvh.nodes.size(), 0);
  for (uint32_t p : bvh.primitives) {
    if (p >= primitiveCount) return "primitives holds index " + std::to_string(p) + ", out of range";
    if (primitiveSeen[p]++) return "primitive " + std::to_string(p) + " is listed twice";
  }
  // Walk the tree from the root; children must come after their parent, so
  // the walk always ends.
  std::vector<std::pair<uint32_t, uint32_t>> stack = {{0, 0}};  // (node, depth)
  nodeSeen[0] = 1;
  while (!stack.empty()) {
    const auto [i, depth] = stack.back();
    stack.pop_back();
    const BvhNode& node = bvh.nodes[i];
    if (depth > kMaxBvhDepth) return where(i) + "deeper than kMaxBvhDepth (" + std::to_string(kMaxBvhDepth) + ")";
    if (node.isLeaf()) {
      if (node.count > kMaxLeafSize) {
        return where(i) + "leaf holds " + std::to_string(node.count) + " primitives, more than kMaxLeafSize (" +
               std::to_string(kMaxLeafSize) + ")";
      }
      if (uint64_t(node.leftOrFirst) + node.count > primitiveCount) return where(i) + "leaf range out of bounds";
      for (uint32_t s = node.leftOrFirst; s < node.leftOrFirst + node.count; ++s) {
        if (slotSeen[s]++) return where(i) + "slot " + std::to_string(s) + " belongs to two leaves";
        if (bounds && !node.bounds.contains((*bounds)[bvh.primitives[s]])) {
          return where(i) + "leaf box does not contain primitive " + std::to_string(bvh.primitives[s]);
        }
      }
      continue;
    }
    const uint32_t left = node.leftOrFirst;
    if (left <= i || uint64_t(left) + 1 >= bvh.nodes.size()) {
      return where(i) + "children at " + std::to_string(left) + " must come after their parent and exist";
    }
    for (uint32_t child : {left, left + 1}) {
      if (nodeSeen[child]++) return where(child) + "reached twice";
      if (!node.bounds.contains(bvh.nodes[child].bounds)) return where(child) + "box is not inside its parent's";
      stack.push_back({child, depth + 1});
    }
  }
  for (size_t s = 0; s < primitiveCount; ++s) {
    if (!slotSeen[s]) return "slot " + std::to_string(s) + " is in no leaf";
  }
  return "";
}

double sahCost(const Bvh& bvh) {
  if (bvh.nodes.empty()) return 0.0;
  const double rootArea = bvh.nodes[0].bounds.surfaceArea();
  if (!(rootArea > 0.0)) return 0.0;
  double cost = 0.0;
  for (const BvhNode& node : bvh.nodes) {
    cost += double(node.bounds.surfaceArea()) / rootArea * (node.isLeaf() ? double(node.count) : 1.0);
  }
  return cost;
}

namespace {

// Where `ray` enters `box` within [tMin, tMax], or a negative number. Slabs
// with the inverse direction; a zero component's infinities are handled by
// min/max ordering (0 * inf gives NaN, which std::min/max drop to the other side).
float enterBox(const Aabb& box, const Ray& ray, const Vec3& inverse, float tMin, float tMax) {
  for (int axis = 0; axis < 3; ++axis) {
    float t0 = (box.min[axis] - ray.origin[axis]) * inverse[axis];
    float t1 = (box.max[axis] - ray.origin[axis]) * inverse[axis];
    if (t0 > t1) std::swap(t0, t1);
    if (!(t0 <= t1)) {  // NaN: the origin lies in this slab's plane and the ray is parallel to it
      if (ray.origin[axis] < box.min[axis] || ray.origin[axis] > box.max[axis]) return -1.0f;
      continue;
    }
    tMin = std::max(tMin, t0);
    tMax = std::min(tMax, t1);
    if (tMin > tMax) return -1.0f;
  }
  return tMin;
}

}  // namespace

TreeCost treeCost(const Bvh& bvh, const LeafGeometry& geometry, std::span<const Ray> rays) {
  TreeCost cost;
  cost.rays = rays.size();
  if (bvh.nodes.empty() || rays.empty()) return cost;
  uint64_t nodes = 0, tests = 0;
  std::vector<std::pair<uint32_t, float>> stack;
  for (const Ray& ray : rays) {
    const Vec3 inverse = 1.0f / ray.direction;
    float closest = std::numeric_limits<float>::infinity();
    stack.clear();
    const float rootEnter = enterBox(bvh.nodes[0].bounds, ray, inverse, 0.0f, closest);
    if (rootEnter >= 0.0f) stack.push_back({0, rootEnter});
    while (!stack.empty()) {
      const auto [index, enter] = stack.back();
      stack.pop_back();
      if (enter > closest) continue;
      ++nodes;
      const BvhNode& node = bvh.nodes[index];
      if (node.isLeaf()) {
        for (uint32_t k = 0; k < node.count; ++k) {
          ++tests;
          const std::optional<PrimitiveHit> hit =
              geometry.intersect(node.leftOrFirst + k, ray, Interval{0.0f, closest});
          if (hit) closest = hit->t;
        }
        continue;
      }
      const uint32_t left = node.leftOrFirst, right = left + 1;
      const float tl = enterBox(bvh.nodes[left].bounds, ray, inverse, 0.0f, closest);
      const float tr = enterBox(bvh.nodes[right].bounds, ray, inverse, 0.0f, closest);
      // The farther child first on the stack, so the nearer one is walked first.
      if (tl >= 0.0f && tr >= 0.0f) {
        stack.push_back(tl <= tr ? std::pair{right, tr} : std::pair{left, tl});
        stack.push_back(tl <= tr ? std::pair{left, tl} : std::pair{right, tr});
      } else if (tl >= 0.0f) {
        stack.push_back({left, tl});
      } else if (tr >= 0.0f) {
        stack.push_back({right, tr});
      }
    }
  }
  cost.nodesPerRay = double(nodes) / double(rays.size());
  cost.primitiveTestsPerRay = double(tests) / double(rays.size());
  return cost;
}

std::vector<Ray> raysThroughBox(const Aabb& box, int side) {
  const Vec3 extent = box.max - box.min;
  const float size = std::max({extent.x, extent.y, extent.z, 1e-30f});
  const Point3 center = 0.5f * (box.min + box.max);
  const Point3 eye(center.x, center.y, box.max.z + 2.0f * size);
  std::vector<Ray> rays;
  rays.reserve(size_t(side) * size_t(side));
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      // Aimed at the box's middle plane, a grid a little wider than the box.
      const Point3 target(box.min.x + (float(i) + 0.5f) / float(side) * extent.x * 1.1f - 0.05f * extent.x,
                          box.min.y + (float(j) + 0.5f) / float(side) * extent.y * 1.1f - 0.05f * extent.y, center.z);
      rays.push_back(Ray{eye, glm::normalize(target - eye)});
    }
  return rays;
}

std::string formatTreeCost(const TreeCost& cost) {
  char text[200];
  std::snprintf(text, sizeof text, "%.1f = %.1f nodes + 10 x %.2f primitive tests per ray", cost.score(),
                cost.nodesPerRay, cost.primitiveTestsPerRay);
  return text;
}

BvhStatistics bvhStatistics(const Bvh& bvh) {
  BvhStatistics s;
  s.nodes = bvh.nodes.size();
  s.sahCost = sahCost(bvh);
  s.leafSizes.assign(kMaxLeafSize + 1, 0);
  if (bvh.nodes.empty()) return s;
  std::vector<std::pair<uint32_t, uint32_t>> stack = {{0, 0}};
  while (!stack.empty()) {
    auto [i, depth] = stack.back();
    stack.pop_back();
    const BvhNode& node = bvh.nodes[i];
    s.maxDepth = std::max(s.maxDepth, depth);
    if (node.isLeaf()) {
      ++s.leaves;
      if (node.count >= s.leafSizes.size()) s.leafSizes.resize(node.count + 1, 0);
      ++s.leafSizes[node.count];
    } else {
      stack.push_back({node.leftOrFirst, depth + 1});
      stack.push_back({node.leftOrFirst + 1, depth + 1});
    }
  }
  return s;
}

std::string formatBvhStatistics(const BvhStatistics& s) {
  std::string text = "BVH: " + std::to_string(s.nodes) + " nodes, " + std::to_string(s.leaves) +
                     " leaves, depth " + std::to_string(s.maxDepth);
  char cost[64];
  std::snprintf(cost, sizeof cost, ", SAH cost %.2f\n", s.sahCost);
  text += cost;
  text += "leaf sizes:";
  for (size_t k = 1; k < s.leafSizes.size(); ++k) {
    if (!s.leafSizes[k]) continue;
    char entry[48];
    std::snprintf(entry, sizeof entry, " %zu:%zu", k, s.leafSizes[k]);
    text += entry;
  }
  return text + "\n";
}

std::optional<Traversal> traversalFromName(const std::string& name) {
  if (name == "task3") return Traversal::Task3;
  if (name == "fast") return Traversal::Fast;
  return std::nullopt;
}

const char* traversalName(Traversal traversal) { return traversal == Traversal::Fast ? "fast" : "task3"; }

Traversal defaultTraversal(const std::string& taskSummary) {
  const std::string tasks = " " + taskSummary + " ";
  const bool reference = tasks.find(" 2:reference ") != std::string::npos && tasks.find(" 3:reference ") != std::string::npos;
  return reference ? Traversal::Fast : Traversal::Task3;
}

Accelerator::Accelerator(const Scene& scene, Traversal traversal) : scene_(scene), traversal_(traversal) {
  if (scene.primitives.empty()) return;
  const auto start = std::chrono::steady_clock::now();
  std::vector<Aabb> bounds = primitiveBounds(scene);
  bvh_ = buildBvh(bounds);
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::string problem = validateBvh(bvh_, scene.primitives.size(), &bounds);
  if (!problem.empty()) {
    static std::once_flag once;
    std::call_once(once, [&] {
      std::fprintf(stderr, "task 3: the BVH is not usable (%s); using brute-force intersection (slow)\n",
                   problem.c_str());
    });
    bvh_ = Bvh{};
    return;
  }
  geometry_ = LeafGeometry(scene, bvh_.primitives, kLinkedTasks.primitives);
  if (traversal_ == Traversal::Fast) {
    wide_ = WideBvh(bvh_, geometry_, kLinkedTasks.primitives);
    surfaces_.reserve(scene.primitives.size());
    for (const PrimitiveRef& ref : scene.primitives) {
      if (ref.isSphere()) {
        surfaces_.push_back({Vec3(0.0f), scene.spheres[ref.index].material, kSphere});
        continue;
      }
      const TriangleMesh& mesh = scene.meshes[ref.mesh];
      const glm::uvec3& v = mesh.triangles[ref.index];
      const Point3 &p0 = mesh.positions[v.x], &p1 = mesh.positions[v.y], &p2 = mesh.positions[v.z];
      surfaces_.push_back({glm::normalize(glm::cross(p1 - p0, p2 - p0)), mesh.material,
                           mesh.normals.empty() ? kFlat : kSmooth});
    }
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  usesBvh_ = true;
}

std::optional<Hit> Accelerator::intersect(const Ray& ray, Interval range, TraversalStats* stats) const {
  if (!usesBvh_) return intersectBruteForce(scene_, ray, range);
  std::optional<PrimitiveHit> hit = traversal_ == Traversal::Fast && !stats
                                         ? wide_.intersectClosest(ray, range)
                                         : intersectClosest(bvh_, geometry_, ray, range, stats);
  if (!hit || hit->primitive >= scene_.primitives.size()) return std::nullopt;
  return surfaces_.empty() ? surfaceHit(scene_, ray, *hit) : fastSurfaceHit(ray, *hit);
}

// surfaceHit with the reference's triangleSurfacePoint and sphereSurfacePoint
// written out, in their order of operations: bit-identical records.
Hit Accelerator::fastSurfaceHit(const Ray& ray, const PrimitiveHit& hit) const {
  const SurfaceData& data = surfaces_[hit.primitive];
  const PrimitiveRef& ref = scene_.primitives[hit.primitive];
  Hit result;
  result.t = hit.t;
  result.primitive = hit.primitive;
  result.material = data.material;
  if (data.kind == kSphere) {
    const Sphere& sphere = scene_.spheres[ref.index];
    const Vec3 outward = glm::normalize(ray.at(hit.t) - sphere.center);
    result.point = sphere.center + sphere.radius * outward;
    result.geometricNormal = result.shadingNormal = outward;
    return result;
  }
  const TriangleMesh& mesh = scene_.meshes[ref.mesh];
  const glm::uvec3& v = mesh.triangles[ref.index];
  const float b0 = 1.0f - hit.b1 - hit.b2;
  result.point = b0 * mesh.positions[v.x] + hit.b1 * mesh.positions[v.y] + hit.b2 * mesh.positions[v.z];
  result.geometricNormal = result.shadingNormal = data.normal;
  if (data.kind == kSmooth) {
    const Vec3 n = b0 * mesh.normals[v.x] + hit.b1 * mesh.normals[v.y] + hit.b2 * mesh.normals[v.z];
    if (glm::dot(n, n) > 0.0f) {
      result.shadingNormal = glm::normalize(n);
      if (glm::dot(result.geometricNormal, result.shadingNormal) < 0.0f) result.geometricNormal = -data.normal;
    }
  }
  return result;
}

bool Accelerator::occluded(const Ray& ray, Interval range, TraversalStats* stats) const {
  if (!usesBvh_) return intersectBruteForce(scene_, ray, range).has_value();
  return traversal_ == Traversal::Fast && !stats ? wide_.intersectAny(ray, range)
                                                 : intersectAny(bvh_, geometry_, ray, range, stats);
}

}  // namespace pathlab
