// The render path's 8-wide tree (wide_bvh.h): built by collapsing task 3's
// binary tree (wide_bvh_build.cpp), walked here with eight box tests and four
// triangle tests at a time.
#include "render/wide_bvh.h"

#include <array>
#include <bit>
#include <utility>

#include "core/leaf_geometry.h"
#include "render/lanes.h"
#include "util/compiler.h"

// The AVX2 box tests are compiled in on x86-64 (GCC and Clang) and chosen at
// run time, so one binary runs on any x86-64 CPU.
#if defined(__x86_64__) && defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#define PATHLAB_WIDE_BVH_AVX2 1
#else
#define PATHLAB_WIDE_BVH_AVX2 0
#endif

#if PATHLAB_WIDE_BVH_AVX2
#include <immintrin.h>
#endif

namespace pathlab {
namespace {

using lanes::F4;

// Rounding in the slab test can shrink an interval that really encloses a
// hit; pbrt-v4 widens exits by 2 gamma(3). Here the factor rides on
// 1/direction, one more rounding, so 2 gamma(4).
constexpr float kWidenExit = 1.0f + 2.0f * (4.0f * 0x1.0p-24f) / (1.0f - 4.0f * 0x1.0p-24f);

// A wide traversal stacks at most kWidth - 1 children per level of task 3's tree.
constexpr int kStackSize = (WideBvh::kWidth - 1) * int(kMaxBvhDepth) + 1;

// Per ray, once: the slab test's constants, and the watertight triangle
// test's permutation and shear (the reference task 2, pbrt-v4 section 6.5.3).
struct RayLanes {
  F4 origin[3], inverseDirection[3], widenedInverse[3];  // widenedInverse: for exits
  int nearBound[3], farBound[3];  // rows of Node::bounds: the slab a ray enters first on each axis
  int kx, ky, kz;                 // axes permuted so the direction's largest component is z
  F4 shearX, shearY, shearZ;

  explicit RayLanes(const Ray& ray) {
    const Vec3 inverse = 1.0f / ray.direction;
    for (int axis = 0; axis < 3; ++axis) {
      origin[axis] = lanes::splat(ray.origin[axis]);
      inverseDirection[axis] = lanes::splat(inverse[axis]);
      widenedInverse[axis] = lanes::splat(inverse[axis] * kWidenExit);
      nearBound[axis] = inverse[axis] < 0.0f ? axis + 3 : axis;
      farBound[axis] = inverse[axis] < 0.0f ? axis : axis + 3;
    }
    // The reference's largestAxis, (a.x > a.y) ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2),
    // in arithmetic: a ray's axis order is a coin flip the CPU cannot predict.
    const Vec3 a(std::abs(ray.direction.x), std::abs(ray.direction.y), std::abs(ray.direction.z));
    const int xOverY = a.x > a.y, xOverZ = a.x > a.z, yOverZ = a.y > a.z;
    kz = xOverY * (2 - 2 * xOverZ) + (1 - xOverY) * (2 - yOverZ);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    const Vec3& d = ray.direction;
    shearX = lanes::splat(-d[kx] / d[kz]);
    shearY = lanes::splat(-d[ky] / d[kz]);
    shearZ = lanes::splat(inverse[kz]);  // 1 / d[kz], already made
  }
};

// A packet's lanes through the reference's watertight test, in its order of
// operations (so each lane's t, b1, b2 are bit-identical to it): `hit` gets
// the lanes hit inside `range`, `onEdge` the lanes with an edge function of
// exactly 0, which the reference settles in double precision. Eight lanes at
// once with AVX2 (Avx2Boxes::packet), else four and four (testHalfPacket).
struct PacketHits {
  alignas(32) float t[WideBvh::kPacketSize], b1[WideBvh::kPacketSize], b2[WideBvh::kPacketSize];
  int hit = 0, onEdge = 0;
};

PATHLAB_ALWAYS_INLINE inline void testHalfPacket(const WideBvh::TrianglePacket& p, int half, const RayLanes& r,
                                                 Interval range, PacketHits& out) {
  const F4 zero = lanes::splat(0.0f);
  F4 x[3], y[3], z[3];  // the vertices relative to the origin, permuted and sheared
  for (int v = 0; v < 3; ++v) {
    x[v] = lanes::load(p.vertex[v][r.kx] + half) - r.origin[r.kx];
    y[v] = lanes::load(p.vertex[v][r.ky] + half) - r.origin[r.ky];
    z[v] = lanes::load(p.vertex[v][r.kz] + half) - r.origin[r.kz];
    x[v] = x[v] + r.shearX * z[v];
    y[v] = y[v] + r.shearY * z[v];
  }
  const F4 e0 = x[1] * y[2] - y[1] * x[2];
  const F4 e1 = x[2] * y[0] - y[2] * x[0];
  const F4 e2 = x[0] * y[1] - y[0] * x[1];
  const int onEdge = (e0 == zero) | (e1 == zero) | (e2 == zero);
  const int mixedSigns = ((e0 < zero) | (e1 < zero) | (e2 < zero)) & ((e0 > zero) | (e1 > zero) | (e2 > zero));
  const F4 det = e0 + e1 + e2;
  const F4 tScaled = e0 * (z[0] * r.shearZ) + e1 * (z[1] * r.shearZ) + e2 * (z[2] * r.shearZ);
  const F4 minDet = lanes::splat(range.min) * det, maxDet = lanes::splat(range.max) * det;
  const int outside = ((det < zero) & ((tScaled >= minDet) | (tScaled <= maxDet))) |
                      ((det > zero) & ((tScaled <= minDet) | (tScaled >= maxDet)));
  const int lanesIn = int(p.lanes >> half) & 15;
  int hit = lanesIn & ~onEdge & ~mixedSigns & ~(det == zero) & ~outside;
  out.onEdge |= (lanesIn & onEdge) << half;
  if (!hit) return;
  const F4 inverseDet = lanes::splat(1.0f) / det;
  lanes::store(out.t + half, tScaled * inverseDet);
  lanes::store(out.b1 + half, e1 * inverseDet);
  lanes::store(out.b2 + half, e2 * inverseDet);
  for (int mask = hit; mask; mask &= mask - 1) {  // as triangleHit: never an answer outside the range
    const int lane = std::countr_zero(unsigned(mask));
    if (!range.contains(out.t[half + lane])) hit &= ~(1 << lane);
  }
  out.hit |= hit << half;
}

// The box tests of one node: the entry t of each child box within
// [tMin, tMax] into `entry`, and the mask of children hit. A ray lying in a
// slab plane gives 0 * inf = NaN, which min/max pass over (lanes.h): that
// axis sets no limit. Two versions with the same arithmetic, so the same
// answers: four boxes per instruction (SSE2, or plain code elsewhere), and
// eight (AVX2, where the CPU has it; see WideBvh::Instructions).
struct BaselineBoxes {
  const RayLanes& r;
  int operator()(const WideBvh::Node& node, float tMin, float tMax, float* entry) const {
    int mask = 0;
    for (int half = 0; half < WideBvh::kWidth; half += 4) {
      F4 near = lanes::splat(tMin), far = lanes::splat(tMax);
      for (int axis = 0; axis < 3; ++axis) {
        const F4 tNear =
            (lanes::load(node.bounds[r.nearBound[axis]] + half) - r.origin[axis]) * r.inverseDirection[axis];
        const F4 tFar =
            (lanes::load(node.bounds[r.farBound[axis]] + half) - r.origin[axis]) * r.widenedInverse[axis];
        near = lanes::max(tNear, near);
        far = lanes::min(tFar, far);
      }
      lanes::store(entry + half, near);
      mask |= (near <= far) << half;
    }
    return mask & ((1 << node.count) - 1);
  }
  void packet(const WideBvh::TrianglePacket& p, Interval range, PacketHits& out) const {
    testHalfPacket(p, 0, r, range, out);
    if (p.lanes >> 4) testHalfPacket(p, 4, r, range, out);
  }
};

#if PATHLAB_WIDE_BVH_AVX2
static_assert(WideBvh::kWidth == 8 && WideBvh::kPacketSize == 8);
// Lane masks: a comparison (ordered: false where either side is NaN, as the
// scalar operators), and the lanes set in any of three masks.
template <int kPredicate>
[[gnu::target("avx2")]] inline __m256 compare(__m256 a, __m256 b) {
  return _mm256_cmp_ps(a, b, kPredicate);
}
[[gnu::target("avx2")]] inline __m256 any(__m256 a, __m256 b, __m256 c) { return _mm256_or_ps(_mm256_or_ps(a, b), c); }

struct Avx2Boxes {
  const RayLanes& r;
  __m256 origin[3], inverseDirection[3], widenedInverse[3];
  __m256 shearX, shearY, shearZ;  // the triangle test's, eight lanes wide

  [[gnu::target("avx2")]] explicit Avx2Boxes(const RayLanes& lanes) : r(lanes) {
    for (int axis = 0; axis < 3; ++axis) {
      origin[axis] = _mm256_set_m128(r.origin[axis].v, r.origin[axis].v);
      inverseDirection[axis] = _mm256_set_m128(r.inverseDirection[axis].v, r.inverseDirection[axis].v);
      widenedInverse[axis] = _mm256_set_m128(r.widenedInverse[axis].v, r.widenedInverse[axis].v);
    }
    shearX = _mm256_set_m128(r.shearX.v, r.shearX.v);
    shearY = _mm256_set_m128(r.shearY.v, r.shearY.v);
    shearZ = _mm256_set_m128(r.shearZ.v, r.shearZ.v);
  }
  [[gnu::target("avx2")]] int operator()(const WideBvh::Node& node, float tMin, float tMax, float* entry) const {
    __m256 near = _mm256_set1_ps(tMin), far = _mm256_set1_ps(tMax);
    for (int axis = 0; axis < 3; ++axis) {
      const __m256 tNear = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node.bounds[r.nearBound[axis]]), origin[axis]),
                                         inverseDirection[axis]);
      const __m256 tFar = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node.bounds[r.farBound[axis]]), origin[axis]),
                                        widenedInverse[axis]);
      near = _mm256_max_ps(tNear, near);  // as lanes::max: NaN in tNear keeps the running limit
      far = _mm256_min_ps(tFar, far);
    }
    _mm256_store_ps(entry, near);
    return _mm256_movemask_ps(_mm256_cmp_ps(near, far, _CMP_LE_OQ)) & ((1 << node.count) - 1);
  }
  // testHalfPacket's arithmetic on all eight lanes at once.
  [[gnu::target("avx2")]] void packet(const WideBvh::TrianglePacket& p, Interval range, PacketHits& out) const {
    const __m256 zero = _mm256_setzero_ps();
    __m256 x[3], y[3], z[3];
    for (int v = 0; v < 3; ++v) {
      x[v] = _mm256_sub_ps(_mm256_load_ps(p.vertex[v][r.kx]), origin[r.kx]);
      y[v] = _mm256_sub_ps(_mm256_load_ps(p.vertex[v][r.ky]), origin[r.ky]);
      z[v] = _mm256_sub_ps(_mm256_load_ps(p.vertex[v][r.kz]), origin[r.kz]);
      x[v] = _mm256_add_ps(x[v], _mm256_mul_ps(shearX, z[v]));
      y[v] = _mm256_add_ps(y[v], _mm256_mul_ps(shearY, z[v]));
    }
    const __m256 e0 = _mm256_sub_ps(_mm256_mul_ps(x[1], y[2]), _mm256_mul_ps(y[1], x[2]));
    const __m256 e1 = _mm256_sub_ps(_mm256_mul_ps(x[2], y[0]), _mm256_mul_ps(y[2], x[0]));
    const __m256 e2 = _mm256_sub_ps(_mm256_mul_ps(x[0], y[1]), _mm256_mul_ps(y[0], x[1]));
    const __m256 onEdge =
        any(compare<_CMP_EQ_OQ>(e0, zero), compare<_CMP_EQ_OQ>(e1, zero), compare<_CMP_EQ_OQ>(e2, zero));
    const __m256 negative =
        any(compare<_CMP_LT_OQ>(e0, zero), compare<_CMP_LT_OQ>(e1, zero), compare<_CMP_LT_OQ>(e2, zero));
    const __m256 positive =
        any(compare<_CMP_GT_OQ>(e0, zero), compare<_CMP_GT_OQ>(e1, zero), compare<_CMP_GT_OQ>(e2, zero));
    const __m256 det = _mm256_add_ps(_mm256_add_ps(e0, e1), e2);
    const __m256 tScaled = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(e0, _mm256_mul_ps(z[0], shearZ)),
                                                       _mm256_mul_ps(e1, _mm256_mul_ps(z[1], shearZ))),
                                         _mm256_mul_ps(e2, _mm256_mul_ps(z[2], shearZ)));
    const __m256 minDet = _mm256_mul_ps(_mm256_set1_ps(range.min), det);
    const __m256 maxDet = _mm256_mul_ps(_mm256_set1_ps(range.max), det);
    const __m256 outside = _mm256_or_ps(
        _mm256_and_ps(compare<_CMP_LT_OQ>(det, zero),
                      _mm256_or_ps(compare<_CMP_GE_OQ>(tScaled, minDet), compare<_CMP_LE_OQ>(tScaled, maxDet))),
        _mm256_and_ps(compare<_CMP_GT_OQ>(det, zero),
                      _mm256_or_ps(compare<_CMP_LE_OQ>(tScaled, minDet), compare<_CMP_GE_OQ>(tScaled, maxDet))));
    const __m256 rejected =
        any(onEdge, _mm256_and_ps(negative, positive), _mm256_or_ps(compare<_CMP_EQ_OQ>(det, zero), outside));
    const int lanesIn = int(p.lanes);
    out.onEdge = lanesIn & _mm256_movemask_ps(onEdge);
    out.hit = lanesIn & ~_mm256_movemask_ps(rejected);
    if (!out.hit) return;
    const __m256 inverseDet = _mm256_div_ps(_mm256_set1_ps(1.0f), det);
    _mm256_store_ps(out.t, _mm256_mul_ps(tScaled, inverseDet));
    _mm256_store_ps(out.b1, _mm256_mul_ps(e1, inverseDet));
    _mm256_store_ps(out.b2, _mm256_mul_ps(e2, inverseDet));
    for (int mask = out.hit; mask; mask &= mask - 1) {  // as triangleHit: never an answer outside the range
      const int lane = std::countr_zero(unsigned(mask));
      if (!range.contains(out.t[lane])) out.hit &= ~(1 << lane);
    }
  }
};
#endif

// The four lanes of a sphere packet through the reference's sphere test, in
// its order of operations (bit-identical t). Returns the lanes hit inside
// `range`, their t in `t`.
PATHLAB_ALWAYS_INLINE inline int testSpheres(const WideBvh::SpherePacket& p, const Ray& ray, const RayLanes& r,
                                             Interval range, float* t) {
  const Vec3& d = ray.direction;
  const float a = glm::dot(d, d);
  const F4 da = lanes::splat(a), dx = lanes::splat(d.x), dy = lanes::splat(d.y), dz = lanes::splat(d.z);
  const F4 fx = r.origin[0] - lanes::load(p.center[0]), fy = r.origin[1] - lanes::load(p.center[1]),
           fz = r.origin[2] - lanes::load(p.center[2]);
  const F4 radius = lanes::load(p.radius), radiusSquared = radius * radius;
  const F4 halfB = fx * dx + fy * dy + fz * dz;
  const F4 c = fx * fx + fy * fy + fz * fz - radiusSquared;
  const F4 k = halfB / da;
  const F4 px = fx - k * dx, py = fy - k * dy, pz = fz - k * dz;
  const F4 discriminant = da * (radiusSquared - (px * px + py * py + pz * pz));
  int lanesHit = int(p.lanes) & ~(discriminant < lanes::splat(0.0f));
  if (!lanesHit) return 0;
  const F4 q = -(halfB + lanes::copysign(lanes::sqrt(discriminant), halfB));
  alignas(16) float qs[4], near[4], far[4];
  lanes::store(qs, q);
  lanes::store(near, c / q);
  lanes::store(far, q / da);
  for (int mask = lanesHit; mask; mask &= mask - 1) {
    const int lane = std::countr_zero(unsigned(mask));
    float t0 = qs[lane] != 0.0f ? near[lane] : 0.0f, t1 = far[lane];
    if (t0 > t1) std::swap(t0, t1);  // (only when t1 < 0: a no-op for ranges from 0 on, kept as the reference has it)
    if (range.contains(t0)) {
      t[lane] = t0;
    } else if (range.contains(t1)) {
      t[lane] = t1;
    } else {
      lanesHit &= ~(1 << lane);
    }
  }
  return lanesHit;
}

std::optional<PrimitiveHit> laneOnEdge(const PrimitiveTests& tests, const WideBvh::TrianglePacket& p, int lane,
                                       const Ray& ray, Interval range) {
  auto vertex = [&](int v) { return Point3(p.vertex[v][0][lane], p.vertex[v][1][lane], p.vertex[v][2][lane]); };
  return triangleHit(tests, ray, range, vertex(0), vertex(1), vertex(2), p.primitive[lane]);
}

// The hits in one leaf, each found within `range` as it stands at its turn:
// each triangle packet's nearest lane (the first on a tie, as a sequential
// test keeps it), its lanes on an edge, then each sphere packet's nearest.
// `onHit` narrows the range (closest hit) or returns true to stop (any hit);
// so does leafHits.
template <class Lanes, class OnHit>
bool leafHits(const WideBvh::Leaf& leaf, const std::vector<WideBvh::TrianglePacket>& packets,
              const std::vector<WideBvh::SpherePacket>& spheres, const PrimitiveTests& tests, const Lanes& lanes,
              const RayLanes& r, const Ray& ray, Interval& range, OnHit&& onHit) {
  for (uint32_t k = 0; k < leaf.packetCount; ++k) {
    const WideBvh::TrianglePacket& packet = packets[leaf.firstPacket + k];
    PacketHits hits;
    lanes.packet(packet, range, hits);
    int nearest = -1;
    for (int mask = hits.hit; mask; mask &= mask - 1) {
      const int lane = std::countr_zero(unsigned(mask));
      if (nearest < 0 || hits.t[lane] < hits.t[nearest]) nearest = lane;
    }
    if (nearest >= 0 &&
        onHit(PrimitiveHit{hits.t[nearest], hits.b1[nearest], hits.b2[nearest], packet.primitive[nearest]})) {
      return true;
    }
    for (int mask = hits.onEdge; mask; mask &= mask - 1) {
      auto hit = laneOnEdge(tests, packet, std::countr_zero(unsigned(mask)), ray, range);
      if (hit && onHit(*hit)) return true;
    }
  }
  for (uint32_t k = 0; k < leaf.spherePacketCount; ++k) {
    const WideBvh::SpherePacket& packet = spheres[leaf.firstSpherePacket + k];
    alignas(16) float t[4];
    const int hit = testSpheres(packet, ray, r, range, t);
    if (!hit) continue;
    int nearest = std::countr_zero(unsigned(hit));
    for (int mask = hit & (hit - 1); mask; mask &= mask - 1) {
      const int lane = std::countr_zero(unsigned(mask));
      if (t[lane] < t[nearest]) nearest = lane;
    }
    if (onHit(PrimitiveHit{t[nearest], 0.0f, 0.0f, packet.primitive[nearest]})) return true;
  }
  return false;
}

}  // namespace

WideBvh::WideBvh(const Bvh& bvh, const LeafGeometry& geometry, const PrimitiveTests& tests,
                 Instructions instructions)
    : tests_(tests) {
#if PATHLAB_WIDE_BVH_AVX2
  avx2_ = instructions == Instructions::Best && __builtin_cpu_supports("avx2");
#else
  (void)instructions;
#endif
  if (bvh.nodes.empty()) return;
  // Primitives below each node (children come after their parents).
  std::vector<uint32_t> below(bvh.nodes.size());
  for (size_t i = bvh.nodes.size(); i-- > 0;) {
    const BvhNode& node = bvh.nodes[i];
    below[i] = node.isLeaf() ? node.count : below[node.leftOrFirst] + below[node.leftOrFirst + 1];
  }
  nodes_.reserve(bvh.nodes.size() / 3 + 1);
  leaves_.reserve(bvh.nodes.size() / 2 + 1);
  packets_.reserve(bvh.nodes.size() / 2 + 1);
  nodes_.emplace_back();
  if (below[0] <= kPacketSize) {  // the whole tree in one leaf: a root with one child
    Node& root = nodes_[0];
    for (int axis = 0; axis < 3; ++axis) {
      root.bounds[axis][0] = bvh.nodes[0].bounds.min[axis];
      root.bounds[axis + 3][0] = bvh.nodes[0].bounds.max[axis];
    }
    root.child[0] = kLeaf | addLeaf(bvh, geometry, 0);
    root.count = 1;
    return;
  }
  collapse(bvh, geometry, below, 0, 0);
}

// The walks, written once for both box tests. Each entry point below is
// flattened (everything it calls inlined into it), so the AVX2 one is
// compiled for AVX2 throughout and the baseline one never uses it.
struct WideBvh::Walk {
  template <class Boxes>
  static std::optional<PrimitiveHit> closest(const WideBvh& bvh, const RayLanes& r, const Boxes& boxes,
                                             const Ray& ray, Interval range);
  template <class Boxes>
  static bool any(const WideBvh& bvh, const RayLanes& r, const Boxes& boxes, const Ray& ray, Interval range);

  PATHLAB_FLATTEN static std::optional<PrimitiveHit> closestBaseline(const WideBvh& bvh, const Ray& ray,
                                                                     Interval range) {
    const RayLanes r(ray);
    return closest(bvh, r, BaselineBoxes{r}, ray, range);
  }
  PATHLAB_FLATTEN static bool anyBaseline(const WideBvh& bvh, const Ray& ray, Interval range) {
    const RayLanes r(ray);
    return any(bvh, r, BaselineBoxes{r}, ray, range);
  }
#if PATHLAB_WIDE_BVH_AVX2
  [[gnu::target("avx2"), gnu::flatten]] static std::optional<PrimitiveHit> closestAvx2(const WideBvh& bvh,
                                                                                      const Ray& ray,
                                                                                      Interval range) {
    const RayLanes r(ray);
    return closest(bvh, r, Avx2Boxes(r), ray, range);
  }
  [[gnu::target("avx2"), gnu::flatten]] static bool anyAvx2(const WideBvh& bvh, const Ray& ray, Interval range) {
    const RayLanes r(ray);
    return any(bvh, r, Avx2Boxes(r), ray, range);
  }
#endif
};

std::optional<PrimitiveHit> WideBvh::intersectClosest(const Ray& ray, Interval range) const {
  if (nodes_.empty()) return std::nullopt;
#if PATHLAB_WIDE_BVH_AVX2
  if (avx2_) return Walk::closestAvx2(*this, ray, range);
#endif
  return Walk::closestBaseline(*this, ray, range);
}

bool WideBvh::intersectAny(const Ray& ray, Interval range) const {
  if (nodes_.empty()) return false;
#if PATHLAB_WIDE_BVH_AVX2
  if (avx2_) return Walk::anyAvx2(*this, ray, range);
#endif
  return Walk::anyBaseline(*this, ray, range);
}

template <class Boxes>
std::optional<PrimitiveHit> WideBvh::Walk::closest(const WideBvh& bvh, const RayLanes& r, const Boxes& boxes,
                                                   const Ray& ray, Interval range) {
  struct Pending {
    uint32_t item;
    float tEntry;
  };
  std::array<Pending, kStackSize> stack;
  int size = 0;
  std::optional<PrimitiveHit> closest;
  uint32_t item = 0;
  while (true) {
    if (item & kLeaf) {
      const Leaf& leaf = bvh.leaves_[item & ~kLeaf];
      leafHits(leaf, bvh.packets_, bvh.spherePackets_, bvh.tests_, boxes, r, ray, range, [&](const PrimitiveHit& hit) {
        closest = hit;
        range.max = hit.t;  // from now on only closer hits count
        return false;
      });
    } else {
      alignas(32) float entry[kWidth];
      int mask = boxes(bvh.nodes_[item], range.min, range.max, entry);
      if (mask) {
        // The children hit, nearest first: visit the nearest, stack the rest.
        Pending hit[kWidth];
        int count = 0;
        for (; mask; mask &= mask - 1) {
          const int lane = std::countr_zero(unsigned(mask));
          Pending p{bvh.nodes_[item].child[lane], entry[lane]};
          int k = count++;
          for (; k > 0 && hit[k - 1].tEntry > p.tEntry; --k) hit[k] = hit[k - 1];
          hit[k] = p;
        }
        for (int k = count - 1; k > 0; --k) stack[size++] = hit[k];
        item = hit[0].item;
        continue;
      }
    }
    // Pop the next subtree that can still hold a closer hit.
    while (true) {
      if (size == 0) return closest;
      const Pending next = stack[--size];
      if (next.tEntry <= range.max) {
        item = next.item;
        break;
      }
    }
  }
}

template <class Boxes>
bool WideBvh::Walk::any(const WideBvh& bvh, const RayLanes& r, const Boxes& boxes, const Ray& ray, Interval range) {
  std::array<uint32_t, kStackSize> stack;
  int size = 0;
  uint32_t item = 0;
  while (true) {
    if (item & kLeaf) {
      if (leafHits(bvh.leaves_[item & ~kLeaf], bvh.packets_, bvh.spherePackets_, bvh.tests_, boxes, r, ray, range,
                   [](const PrimitiveHit&) { return true; })) {
        return true;
      }
    } else {
      alignas(32) float entry[kWidth];
      const Node& node = bvh.nodes_[item];
      int mask = boxes(node, range.min, range.max, entry);
      if (mask) {
        item = node.child[std::countr_zero(unsigned(mask))];
        for (mask &= mask - 1; mask; mask &= mask - 1) stack[size++] = node.child[std::countr_zero(unsigned(mask))];
        continue;
      }
    }
    if (size == 0) return false;
    item = stack[--size];
  }
}

}  // namespace pathlab
