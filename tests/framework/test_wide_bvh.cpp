// The render path's 8-wide tree (wide_bvh.h), with either box test (AVX2 and
// the baseline), answers every query exactly as task 3 does over the same
// binary tree: the same primitive, and t, b1, b2 equal to the last bit, or
// the same blocked/unblocked. Linked with the
// reference tasks, whose triangle test the packets reproduce lane by lane.
#include "suite/doctest_strings.h"

#include <cstring>
#include <string>

#include "meshes.h"
#include "render/accelerator.h"
#include "scene/procedural.h"
#include "util/random.h"
#include "scene/scene_io.h"
#include "render/task_wiring.h"
#include "render/wide_bvh.h"

using namespace pathlab;

namespace {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameHit(const PrimitiveHit& a, const std::optional<PrimitiveHit>& b) {
  return b && a.primitive == b->primitive && sameBits(a.t, b->t) && sameBits(a.b1, b->b1) && sameBits(a.b2, b->b2);
}

// Task 2's answer for one primitive (a slot of its own).
std::optional<PrimitiveHit> hitOn(const Scene& scene, uint32_t primitive, const Ray& ray, Interval range) {
  const uint32_t order[] = {primitive};
  return LeafGeometry(scene, order, kLinkedTasks.primitives).intersect(0, ray, range);
}

// A flat grid of unit squares, two triangles each, in the plane z = 0: rays
// along the axes through integer points cross shared edges and vertices
// exactly, where the watertight test falls back to double precision.
TriangleMesh grid(int n) {
  TriangleMesh mesh;
  for (int y = 0; y <= n; ++y) {
    for (int x = 0; x <= n; ++x) mesh.positions.push_back(Point3(float(x), float(y), 0.0f));
  }
  auto at = [n](int x, int y) { return uint32_t(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      mesh.triangles.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1)});
      mesh.triangles.push_back({at(x, y), at(x + 1, y + 1), at(x, y + 1)});
    }
  }
  return mesh;
}

Scene sceneOf(std::vector<TriangleMesh> meshes, std::vector<Sphere> spheres = {}) {
  Scene scene;
  scene.materials.push_back(Material{.name = "default"});
  scene.meshes = std::move(meshes);
  scene.spheres = std::move(spheres);
  scene.indexPrimitives();
  return scene;
}

// The scenes: tens of thousands of small triangles; spheres among
// triangles; a grid crossed on its edges, with zero-area and duplicate
// triangles; a cloud of spheres; a tree that is a single leaf; one triangle.
std::vector<std::pair<std::string, Scene>> scenes() {
  std::vector<std::pair<std::string, Scene>> out;
  out.emplace_back("scan-like mesh", scanLikeScene());
  out.emplace_back("default box with spheres", defaultScene());
  TriangleMesh edges = grid(12);
  edges.positions.push_back(Point3(3.0f, 3.0f, 0.0f));  // a zero-area triangle on the grid
  edges.triangles.push_back({0, uint32_t(edges.positions.size() - 1), uint32_t(edges.positions.size() - 1)});
  edges.triangles.push_back(edges.triangles[7]);  // a duplicate: the same t twice
  out.emplace_back("grid with shared edges",
                   sceneOf({edges, test::icosphere(2, Point3(6.0f, 6.0f, 2.0f), 1.5f)},
                           {Sphere{Point3(3.0f, 9.0f, 1.0f), 0.75f}, Sphere{Point3(9.0f, 3.0f, -1.0f), 0.5f}}));
  out.emplace_back("one leaf", sceneOf({grid(1)}, {Sphere{Point3(0.5f, 0.5f, 2.0f), 0.25f}}));
  // A cloud of 300 overlapping spheres (leaves of several, so packets of
  // two to four), some nested in one another, one duplicated (a tie).
  std::vector<Sphere> cloud;
  Sampler place(3, 0, 5);
  for (int i = 0; i < 300; ++i) {
    const Vec2 u = place.next2D(), v = place.next2D();
    cloud.push_back({Point3(10.0f * u.x, 10.0f * u.y, 10.0f * v.x), 0.05f + 0.6f * v.y, 0});
    if (i % 25 == 0) cloud.push_back({cloud.back().center, 0.5f * cloud.back().radius, 0});  // nested
  }
  cloud.push_back(cloud[7]);
  out.emplace_back("cloud of spheres", sceneOf({}, cloud));
  TriangleMesh one;
  one.positions = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)};
  one.triangles = {{0, 1, 2}};
  out.emplace_back("one triangle", sceneOf({one}));
  return out;
}

// Rays aimed into the scene's bounds from outside and from inside, with
// some directions exactly along the axes (slab planes, -0 and +0) and some
// origins on the grid's integer points (edges hit exactly). (Not aimed at
// vertices: where several triangles meet, their own tests give t's an ulp
// apart, and which one a walk keeps depends on its order and its rounded
// box entries, in task 3's walk as in this one.)
std::vector<Ray> raysFor(const Scene& scene, int count) {
  Aabb bounds;
  for (const Aabb& b : primitiveBounds(scene)) bounds.grow(b.min), bounds.grow(b.max);
  const Vec3 extent = bounds.extent();
  Sampler sampler(7, 0, 1);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const Vec2 u = sampler.next2D(), v = sampler.next2D(), w = sampler.next2D();
    const Point3 target = bounds.min + Vec3(u.x, u.y, v.x) * extent;
    Point3 origin = bounds.centroid() + (Vec3(v.y, w.x, w.y) - 0.5f) * 3.0f * glm::max(extent, Vec3(1.0f));
    if (i % 4 == 1) origin = bounds.min + Vec3(w.x, w.y, u.x) * extent;  // inside the bounds
    Vec3 direction = target - origin;
    if (i % 8 == 3) {  // along an axis, from an integer point: exactly on edges and in slab planes
      origin = glm::floor(origin) + Vec3(0.0f, 0.0f, 0.0f);
      direction = Vec3(i % 16 == 3 ? -0.0f : 0.0f, 0.0f, origin.z > 0.0f ? -1.0f : 1.0f);
    }
    if (i % 8 == 5) {  // along an axis, lying in a plane of the scene's bounding box (0 * inf = NaN in slab tests)
      const int along = (i / 8) % 3, in = (along + 1 + (i / 24) % 2) % 3;
      origin = target;
      origin[along] = bounds.min[along] - 1.0f;
      origin[in] = (i / 48) % 2 ? bounds.max[in] : bounds.min[in];
      direction = Vec3((i / 96) % 2 ? -0.0f : 0.0f);
      direction[along] = 1.0f;
    }
    if (glm::dot(direction, direction) == 0.0f) direction = Vec3(0.0f, 0.0f, 1.0f);
    rays.push_back(Ray{origin, glm::normalize(direction)});
  }
  return rays;
}

}  // namespace

TEST_CASE("wide BVH: the same closest hit as task 3, to the last bit, and the same blocked rays") {
  for (auto& [sceneName, scene] : scenes()) {
    const std::string& name = sceneName;  // CAPTURE's lambda cannot take a structured binding before clang 16
    CAPTURE(name);
    const std::vector<Aabb> bounds = primitiveBounds(scene);
    const Bvh bvh = buildBvh(bounds);
    REQUIRE(validateBvh(bvh, scene.primitives.size(), &bounds).empty());
    const LeafGeometry geometry(scene, bvh.primitives, kLinkedTasks.primitives);
    // Both box tests: AVX2 where this CPU has it, and the baseline.
    for (auto instructions : {WideBvh::Instructions::Best, WideBvh::Instructions::Baseline}) {
      const WideBvh wide(bvh, geometry, kLinkedTasks.primitives, instructions);
      CAPTURE(wide.usesAvx2());
      size_t hits = 0, blocked = 0, differences = 0, ties = 0;
      const std::vector<Ray> rays = raysFor(scene, 20000);
      for (size_t i = 0; i < rays.size(); ++i) {
        // Unbounded; ending or starting exactly at the first hit (as a shadow
        // ray to a surface does); and ranges that cut through the scene.
        Interval range = i % 3 == 0 ? Interval{0.0f, kInfinity} : Interval{0.01f * float(i % 7), 0.5f + float(i % 11)};
        if (i % 3 == 1) {
          if (auto first = intersectClosest(bvh, geometry, rays[i], {0.0f, kInfinity})) {
            range = i % 2 ? Interval{0.0f, first->t} : Interval{first->t, kInfinity};
          }
        }
        const auto expected = intersectClosest(bvh, geometry, rays[i], range);
        const auto actual = wide.intersectClosest(rays[i], range);
        bool same = expected.has_value() == actual.has_value() &&
                    (!expected || (expected->primitive == actual->primitive && sameHit(*expected, *actual)));
        if (!same && expected && actual && sameBits(expected->t, actual->t)) {
          // A tie: the ray crosses a shared edge or vertex, or a duplicate, at
          // the same t; either primitive is right if task 2 agrees it is hit there.
          same = sameHit(*actual, *hitOn(scene, actual->primitive, rays[i], range));
          ties += same;
        }
        const bool expectedBlocked = intersectAny(bvh, geometry, rays[i], range);
        differences += !same + (expectedBlocked != wide.intersectAny(rays[i], range));
        hits += expected.has_value();
        blocked += expectedBlocked;
      }
      CHECK(differences == 0);
      if (ties) {
        MESSAGE(name, ": ", ties, " rays through shared edges or vertices found another triangle at the same t");
      }
      CHECK(hits > rays.size() / 10);  // the rays do reach the geometry
      CHECK(blocked == hits);          // (with the same ranges, a closest hit exists iff something blocks)
    }
  }
}

TEST_CASE("wide BVH: a leaf's spheres share packets (the cloud's leaves fill several lanes)") {
  for (auto& [name, scene] : scenes()) {
    if (name != "cloud of spheres") continue;
    const Bvh bvh = buildBvh(primitiveBounds(scene));
    const WideBvh wide(bvh, LeafGeometry(scene, bvh.primitives, kLinkedTasks.primitives), kLinkedTasks.primitives);
    CHECK(wide.packetCount() == 0);
    CHECK(wide.spherePacketCount() >= scene.spheres.size() / 4);
    CHECK(wide.spherePacketCount() < scene.spheres.size() * 3 / 4);  // many packets hold two or more
  }
}

TEST_CASE("wide BVH: an empty tree hits nothing; the layout packs up to eight triangles per packet") {
  const WideBvh empty;
  CHECK_FALSE(empty.intersectClosest(Ray{Point3(0.0f), Vec3(0, 0, 1)}, {}));
  CHECK_FALSE(empty.intersectAny(Ray{Point3(0.0f), Vec3(0, 0, 1)}, {}));
  const Scene scene = scanLikeScene();
  const Bvh bvh = buildBvh(primitiveBounds(scene));
  const WideBvh wide(bvh, LeafGeometry(scene, bvh.primitives, kLinkedTasks.primitives), kLinkedTasks.primitives);
  CHECK(wide.nodeCount() < bvh.nodes.size() / 2);
  CHECK(wide.packetCount() >= scene.triangleCount() / WideBvh::kPacketSize);
  CHECK(wide.laneOccupancy() > 0.6);
}

// Geometry a few ulps of FLT_MIN across: 16 / extent overflows to inf, and a
// binning by (centroid - min) * inf would index bin int(NaN). The build must
// stay valid at every scale a float can hold.
TEST_CASE("task 3's build: primitives whose centroids span less than 1e-37 still give a valid tree") {
  for (float size : {1e-37f, 1e-39f, 1e-44f}) {
    std::vector<Aabb> bounds;
    for (int k = 0; k < 40; ++k) {
      const Point3 p(size * float(k % 7) / 7.0f, size * float(k % 5) / 5.0f, size * float(k % 3) / 3.0f);
      bounds.push_back(Aabb{p, p});
    }
    const Bvh bvh = buildBvh(bounds);
    CAPTURE(size);
    CHECK(validateBvh(bvh, bounds.size(), &bounds) == "");
  }
}

// The tree's score (treeCost): the framework's own ordered walk, counted.
TEST_CASE("tree cost: exact counts on a two-leaf tree; a worse tree scores worse; the rays see all of a box") {
  // Two triangles far apart in x, one leaf each under a root: a ray down onto the left one enters
  // the root and the left leaf (2 nodes) and tests 1 triangle; the right leaf's box is missed.
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {10, 0, 0}, {11, 0, 0}, {10, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  const Scene scene = sceneOf({mesh});
  Bvh bvh;
  Aabb left, right, all;
  for (int k = 0; k < 3; ++k) left.grow(mesh.positions[size_t(k)]), right.grow(mesh.positions[size_t(k + 3)]);
  all.grow(left), all.grow(right);
  bvh.nodes = {{all, 1, 0}, {left, 0, 1}, {right, 1, 1}};
  bvh.primitives = {0, 1};
  const LeafGeometry geometry(scene, bvh.primitives, kLinkedTasks.primitives);
  const std::vector<Ray> down = {Ray{{0.2f, 0.2f, 5.0f}, {0.0f, 0.0f, -1.0f}}};
  TreeCost cost = treeCost(bvh, geometry, down);
  CHECK(cost.rays == 1);
  CHECK(cost.nodesPerRay == 2.0);
  CHECK(cost.primitiveTestsPerRay == 1.0);
  CHECK(cost.score() == 12.0);
  // A ray missing the root's box costs nothing; an empty tree or no rays score 0.
  CHECK(treeCost(bvh, geometry, std::vector<Ray>{Ray{{50, 50, 5}, {0, 0, -1}}}).score() == 0.0);
  CHECK(treeCost(Bvh{}, geometry, down).score() == 0.0);
  CHECK(treeCost(bvh, geometry, std::vector<Ray>{}).rays == 0);

  // A 16 x 16 grid (512 triangles): the SAH tree against one leaf per 8 triangles in a chain-like
  // order (the reference tree's leaves re-hung under a left-leaning spine), on rays through the whole
  // box: every ray's first hit is found either way, but the chain visits far more nodes.
  const Scene big = sceneOf({grid(16)});
  std::vector<Aabb> bounds;
  for (const PrimitiveRef& p : big.primitives) {
    Aabb b;
    const TriangleMesh& m = big.meshes[p.mesh];
    for (int k = 0; k < 3; ++k) b.grow(m.positions[m.triangles[p.index][k]]);
    bounds.push_back(b);
  }
  const Bvh good = buildBvh(bounds);
  Aabb box;
  for (const Aabb& b : bounds) box.grow(b);
  const std::vector<Ray> rays = raysThroughBox(box, 32);
  CHECK(rays.size() == 32 * 32);
  const LeafGeometry goodGeometry(big, good.primitives, kLinkedTasks.primitives);
  const TreeCost goodCost = treeCost(good, goodGeometry, rays);
  // Every ray aimed inside the grid hits it; those beyond its edge (the fan is 10 % wider) miss.
  size_t hits = 0;
  for (const Ray& ray : rays) hits += intersectClosest(good, goodGeometry, ray, Interval{}).has_value();
  CHECK(hits > rays.size() * 3 / 4);
  CHECK(hits < rays.size());
  // The chain: leaf k holds slots [8k, 8k + 8); spine node i has leaf i on the left and the rest on the right.
  Bvh chain;
  chain.primitives = good.primitives;
  const uint32_t leaves = uint32_t(chain.primitives.size() / 8);
  auto boundsOf = [&](uint32_t first, uint32_t count) {
    Aabb b;
    for (uint32_t s = first; s < first + count; ++s) b.grow(bounds[chain.primitives[s]]);
    return b;
  };
  chain.nodes.push_back({boundsOf(0, leaves * 8), 0, 0});
  for (uint32_t i = 0; i + 1 < leaves; ++i) {
    const uint32_t at = uint32_t(chain.nodes.size());
    chain.nodes[at == 1 ? 0 : at - 1].leftOrFirst = at;
    chain.nodes.push_back({boundsOf(i * 8, 8), i * 8, 8});  // leaf i
    const bool lastPair = i + 2 == leaves;
    chain.nodes.push_back({boundsOf((i + 1) * 8, (leaves - i - 1) * 8), lastPair ? (i + 1) * 8 : 0, lastPair ? 8u : 0u});
  }
  REQUIRE(validateBvh(chain, chain.primitives.size(), nullptr) == "");
  const TreeCost chainCost = treeCost(chain, LeafGeometry(big, chain.primitives, kLinkedTasks.primitives), rays);
  INFO("SAH tree " << formatTreeCost(goodCost) << "; chain " << formatTreeCost(chainCost));
  CHECK(chainCost.score() > 2.0 * goodCost.score());
  CHECK(goodCost.primitiveTestsPerRay >= 1.0);
}
