// Autograder suite for task 2 — ray–triangle and ray–sphere intersection.
// Expected values come from double-precision computations on the same float
// inputs. Tests run from basic to advanced. candidate::f(...) is the
// student's f, computed in the candidate process (calls.h).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <vector>

#include "check.h"
#include "image_scenes.h"
#include "image_test.h"
#include "grading.h"
#include "meshes.h"
#include "scenes.h"
#include "pathlab/scene_io.h"
#include "calls.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

constexpr Interval kAll{0.0f, kInfinity};

Ray rayTowards(const DVec3& origin, const DVec3& target) {
  return Ray{Point3(origin), Vec3(glm::normalize(target - origin))};
}

// Double-precision oracle on the float inputs: t and barycentrics of the
// ray's crossing with the triangle's plane (Cramer's rule).
struct PlaneHit {
  double t, b1, b2;
};
PlaneHit planeHit(const Ray& ray, const Point3& p0, const Point3& p1, const Point3& p2) {
  DVec3 o(ray.origin), d(ray.direction), a(p0), e1 = DVec3(p1) - a, e2 = DVec3(p2) - a;
  DVec3 p = glm::cross(d, e2);
  double det = glm::dot(e1, p);
  DVec3 s = o - a, q = glm::cross(s, e1);
  return {glm::dot(e2, q) / det, glm::dot(s, p) / det, glm::dot(d, q) / det};
}

// Distinct surface crossings along each ray: hits of several triangles at
// the same t (a shared edge or vertex) are one crossing.
std::vector<int> crossings(const TriangleMesh& mesh, const std::vector<Ray>& rays) {
  std::vector<int> counts;
  for (std::vector<float> ts : candidate::meshHits(mesh, rays)) {
    std::sort(ts.begin(), ts.end());
    int count = 0;
    float last = -1.0f;
    for (float t : ts) {
      if (count == 0 || t > last * (1.0f + 1e-4f)) ++count;
      last = t;
    }
    counts.push_back(count);
  }
  return counts;
}

// Smallest root of the ray–sphere quadratic in double, in range, or -1.
double sphereOracle(const Ray& ray, const Point3& center, float radius, double tMin = 0.0) {
  DVec3 f = DVec3(ray.origin) - DVec3(center), d = glm::normalize(DVec3(ray.direction));
  double b = glm::dot(f, d);
  DVec3 perpendicular = f - b * d;
  double disc = double(radius) * radius - glm::dot(perpendicular, perpendicular);
  if (disc < 0) return -1;
  double c = glm::dot(f, f) - double(radius) * radius;
  double q = -(b + std::copysign(std::sqrt(disc), b));
  double t0 = c / q, t1 = q;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > tMin) return t0;
  if (t1 > tMin) return t1;
  return -1;
}

// A ray from about `distance` away whose line passes `offset` times the
// radius from the sphere's centre.
Ray rayPastSphere(Random& random, const Point3& center, float radius, double distance, double offset) {
  DVec3 axis = random.unitVector();
  DVec3 side = glm::normalize(glm::cross(axis, random.unitVector()));
  DVec3 origin = DVec3(center) + side * (offset * radius) + axis * distance;
  return Ray{Point3(origin), Vec3(-axis)};
}

}  // namespace

// ---------------------------------------------------------------- triangles

TEST_CASE("T2.1 triangle: a ray through the interior hits with the right t and barycentrics" *
          grading(3, "t is the distance along the unit direction; b1, b2 weight p1 and p2 (not p0): "
                     "b1 = e1 / det, b2 = e2 / det, t = tScaled / det")) {
  // Exact case: unit triangle in z = 0, ray straight down onto (0.25, 0.5).
  auto hit = candidate::intersectTriangle(Ray{{0.25f, 0.5f, 2.0f}, {0, 0, -1}}, kAll, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  REQUIRE(hit.has_value());
  CHECK(hit->t == doctest::Approx(2.0f).epsilon(1e-6));
  CHECK(hit->b1 == doctest::Approx(0.25f).epsilon(1e-6));
  CHECK(hit->b2 == doctest::Approx(0.5f).epsilon(1e-6));

  Random random(21);
  for (int i = 0; i < 2000; ++i) {
    Point3 p0(random.inCube(1)), p1(random.inCube(1)), p2(random.inCube(1));
    DVec3 n = glm::cross(DVec3(p1 - p0), DVec3(p2 - p0));
    if (glm::length(n) < 0.05) continue;  // well-shaped triangles only here
    double b1 = random.uniform(0.05, 0.9), b2 = random.uniform(0.05, 0.95 - b1);
    DVec3 target = (1 - b1 - b2) * DVec3(p0) + b1 * DVec3(p1) + b2 * DVec3(p2);
    Ray ray = rayTowards(target + random.unitVector() * random.uniform(0.5, 3.0), target);
    PlaneHit expected = planeHit(ray, p0, p1, p2);
    if (std::abs(glm::dot(glm::normalize(n), DVec3(ray.direction))) < 0.1) continue;  // no grazing here
    auto h = candidate::intersectTriangle(ray, kAll, p0, p1, p2);
    CAPTURE(i);
    REQUIRE(h.has_value());
    CHECK(h->t == doctest::Approx(expected.t).epsilon(1e-4));
    CHECK(std::abs(h->b1 - expected.b1) < 1e-4);
    CHECK(std::abs(h->b2 - expected.b2) < 1e-4);
  }
}

TEST_CASE("T2.1 triangle: rays beside the edges, behind the origin or outside the range miss" *
          grading(3, "reject mixed-sign edge functions; accept only range.min < t < range.max "
                     "(compare tScaled with range * det, minding the sign of det)")) {
  const Point3 p0{0, 0, 0}, p1{1, 0, 0}, p2{0, 1, 0};
  const Vec3 down{0, 0, -1};
  // Inside, as a control: this one must hit.
  REQUIRE(candidate::intersectTriangle(Ray{{0.2f, 0.2f, 1}, down}, kAll, p0, p1, p2).has_value());
  // Beside each of the three edges.
  CHECK_FALSE(candidate::intersectTriangle(Ray{{0.2f, -0.01f, 1}, down}, kAll, p0, p1, p2).has_value());
  CHECK_FALSE(candidate::intersectTriangle(Ray{{-0.01f, 0.2f, 1}, down}, kAll, p0, p1, p2).has_value());
  CHECK_FALSE(candidate::intersectTriangle(Ray{{0.51f, 0.51f, 1}, down}, kAll, p0, p1, p2).has_value());
  // Behind the origin: the triangle is at t = -1.
  CHECK_FALSE(candidate::intersectTriangle(Ray{{0.2f, 0.2f, -1}, down}, kAll, p0, p1, p2).has_value());
  // Range: the hit is at t = 1.
  CHECK_FALSE(candidate::intersectTriangle(Ray{{0.2f, 0.2f, 1}, down}, {0.0f, 0.999f}, p0, p1, p2).has_value());
  CHECK_FALSE(candidate::intersectTriangle(Ray{{0.2f, 0.2f, 1}, down}, {1.001f, kInfinity}, p0, p1, p2).has_value());
  CHECK(candidate::intersectTriangle(Ray{{0.2f, 0.2f, 1}, down}, {0.999f, 1.001f}, p0, p1, p2).has_value());
  // From below (seen from the back side) the same range rules apply.
  CHECK(candidate::intersectTriangle(Ray{{0.2f, 0.2f, -1}, {0, 0, 1}}, kAll, p0, p1, p2).has_value());
  CHECK_FALSE(candidate::intersectTriangle(Ray{{0.2f, 0.2f, -1}, {0, 0, 1}}, {0.0f, 0.5f}, p0, p1, p2).has_value());
}

TEST_CASE("T2.1 triangle: both faces are hit (no back-face culling)" *
          grading(2, "do not reject det < 0: a ray from behind the triangle sees its back face, and "
                     "glass and closed meshes need those hits")) {
  Random random(22);
  for (int i = 0; i < 200; ++i) {
    Point3 p0(random.inCube(1)), p1(random.inCube(1)), p2(random.inCube(1));
    DVec3 n = glm::cross(DVec3(p1 - p0), DVec3(p2 - p0));
    if (glm::length(n) < 0.1) continue;
    DVec3 centroid = (DVec3(p0) + DVec3(p1) + DVec3(p2)) / 3.0;
    DVec3 side = glm::normalize(n) * 2.0;
    CAPTURE(i);
    CHECK(candidate::intersectTriangle(rayTowards(centroid + side, centroid), kAll, p0, p1, p2).has_value());
    CHECK(candidate::intersectTriangle(rayTowards(centroid - side, centroid), kAll, p0, p1, p2).has_value());
  }
}

TEST_CASE("T2.1 triangle: shared edges and vertices of a closed mesh are crossed exactly once (watertight)" *
          grading(4, "a ray through a shared edge must hit at least one of its triangles: no epsilon "
                     "tests, edge functions that give exactly opposite values on the two sides, and a "
                     "double-precision recomputation when an edge function is exactly 0")) {
  // A closed sphere mesh: every ray from outside through an edge or vertex
  // enters once and leaves once.
  const TriangleMesh sphere = icosphere(3, {0.3f, -0.2f, 0.1f}, 1.0f);
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (const glm::uvec3& t : sphere.triangles) {
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  }
  Random random(23);
  std::vector<Ray> rays;
  auto shoot = [&](const DVec3& target) {
    DVec3 inward = glm::normalize(DVec3(0.3, -0.2, 0.1) - target);
    DVec3 direction = glm::normalize(inward + 0.6 * random.unitVector());
    if (glm::dot(direction, inward) < 0.3) direction = inward;
    rays.push_back(rayTowards(target - 3.0 * direction, target));
  };
  for (const auto& [a, b] : edges) {
    DVec3 pa(sphere.positions[a]), pb(sphere.positions[b]);
    shoot(0.5 * (pa + pb));
    shoot(glm::mix(pa, pb, random.uniform()));
  }
  for (const Point3& p : sphere.positions) shoot(DVec3(p));
  const std::vector<int> counts = crossings(sphere, rays);
  int wrong = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    if (counts[i] != 2 && ++wrong <= 5) {
      MESSAGE("ray " << str(rays[i].origin) << " -> " << str(rays[i].direction) << " crossed " << counts[i] << " times");
    }
  }
  INFO(wrong << " of " << rays.size() << " rays through edges and vertices did not cross the closed mesh exactly twice");
  CHECK(wrong == 0);

  // A flat grid whose edges and vertices sit on exact integers: rays
  // through them, straight and tilted, cross it exactly once.
  const TriangleMesh grid = planeGrid(6);
  std::vector<Ray> gridRays;
  for (int y = 1; y < 6; ++y) {
    for (int x = 1; x < 6; ++x) {
      for (DVec3 target : {DVec3(x, y, 0), DVec3(x + 0.5, y, 0), DVec3(x, y + 0.5, 0), DVec3(x + 0.5, y + 0.5, 0)}) {
        for (DVec3 direction : {DVec3(0, 0, -1), glm::normalize(DVec3(0.3, 0.2, -1)), glm::normalize(DVec3(-1, 1, -1))}) {
          gridRays.push_back(Ray{Point3(target - 2.0 * direction), Vec3(direction)});
        }
      }
    }
  }
  int gridWrong = 0;
  for (int n : crossings(grid, gridRays)) gridWrong += n != 1;
  INFO(gridWrong << " of " << gridRays.size() << " rays through grid edges and vertices did not cross it exactly once");
  CHECK(gridWrong == 0);
}

TEST_CASE("T2.1 triangle: a ray lying in the triangle's plane misses, and nothing is NaN" *
          grading(2, "a ray in the plane sees the triangle edge-on: det = e0 + e1 + e2 is 0, which must be "
                     "a miss, not a division by zero")) {
  const Point3 p0{0, 0, 0}, p1{1, 0, 0}, p2{0, 1, 0};
  for (Ray ray : {Ray{{-1, 0.25f, 0}, {1, 0, 0}}, Ray{{0.25f, -1, 0}, {0, 1, 0}},
                  Ray{{-1, -1, 0}, glm::normalize(Vec3(1, 1, 0))}, Ray{{0.1f, 0.1f, 0}, {1, 0, 0}}}) {
    CAPTURE(str(ray.origin));
    CAPTURE(str(ray.direction));
    CHECK_FALSE(candidate::intersectTriangle(ray, kAll, p0, p1, p2).has_value());
  }
  // Control: tilt the first ray slightly out of the plane and it hits, at
  // (0.25, 0.25, 0), well inside (not on an edge, where any answer is fair).
  Ray tilted{{-1, 0.25f, 0.0125f}, glm::normalize(Vec3(1.25f, 0, -0.0125f))};
  auto hit = candidate::intersectTriangle(tilted, kAll, p0, p1, p2);
  REQUIRE(hit.has_value());
  CHECK(std::isfinite(hit->t));
  CHECK(std::isfinite(hit->b1));
  CHECK(std::isfinite(hit->b2));
}

TEST_CASE("T2.1 triangle: zero-area triangles are never hit" *
          grading(2, "a degenerate triangle (collinear or repeated vertices) has no normal; its hit "
                     "would shade with NaN: reject it (det = 0 or a zero cross product)")) {
  struct Tri {
    Point3 p0, p1, p2;
  };
  const Tri degenerate[] = {
      {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}},        // collinear
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}},        // repeated vertex
      {{0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}},  // a point
      {{0, 0, 0}, {4, 0, 0}, {2, 0, 0}},        // collinear, middle vertex last
  };
  for (const Tri& t : degenerate) {
    for (double s : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      DVec3 target = glm::mix(DVec3(t.p0), DVec3(t.p1), s);
      for (DVec3 from : {DVec3(0.1, 0.2, 3), DVec3(-2, 1, 0.5), DVec3(1, -3, -1)}) {
        Ray ray = rayTowards(target + from, target);
        CAPTURE(str(t.p0));
        CAPTURE(str(t.p1));
        CAPTURE(str(t.p2));
        CHECK_FALSE(candidate::intersectTriangle(ray, kAll, t.p0, t.p1, t.p2).has_value());
      }
    }
  }
  // Control: a proper triangle next to them is hit.
  CHECK(candidate::intersectTriangle(Ray{{0.2f, 0.2f, 1}, {0, 0, -1}}, kAll, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}).has_value());
}

TEST_CASE("T2.1 triangle: hits and misses are exact at scales 1e-3..1e5 and far from the origin" *
          grading(3, "no absolute epsilons: thresholds like 1e-6 on det or t lose small triangles and "
                     "misjudge large ones; the watertight test needs none")) {
  Random random(24);
  int checked = 0;
  for (double scale : {1e-3, 1e-1, 1.0, 1e2, 1e5}) {
    for (double away : {0.0, 100.0}) {
      DVec3 offset = random.unitVector() * (away * scale);
      for (int i = 0; i < 300; ++i) {
        Point3 p0(offset + scale * random.inCube(1)), p1(offset + scale * random.inCube(1)),
            p2(offset + scale * random.inCube(1));
        DVec3 a(p0), b(p1), c(p2), n = glm::cross(b - a, c - a);
        if (glm::length(n) < 0.05 * scale * scale) continue;
        DVec3 normal = glm::normalize(n);
        DVec3 from = random.unitVector();
        if (std::abs(glm::dot(from, normal)) < 0.2) from = normal;
        // Inside: every barycentric at least 0.05. Outside: one at most -0.05.
        double b1 = random.uniform(0.05, 0.9), b2 = random.uniform(0.05, 0.95 - b1);
        DVec3 inside = (1 - b1 - b2) * a + b1 * b + b2 * c;
        double o1 = -0.05 - random.uniform(0, 0.5), o2 = random.uniform(0, 0.5);
        DVec3 outside = (1 - o1 - o2) * a + o1 * b + o2 * c;
        double distance = scale * random.uniform(0.5, 5.0);
        Ray hitRay = rayTowards(inside + from * distance, inside);
        Ray missRay = rayTowards(outside + from * distance, outside);
        PlaneHit expected = planeHit(hitRay, p0, p1, p2);
        CAPTURE(scale);
        CAPTURE(away);
        CAPTURE(i);
        auto h = candidate::intersectTriangle(hitRay, kAll, p0, p1, p2);
        REQUIRE(h.has_value());
        CHECK(h->t == doctest::Approx(expected.t).epsilon(1e-4));
        CHECK_FALSE(candidate::intersectTriangle(missRay, kAll, p0, p1, p2).has_value());
        ++checked;
      }
    }
  }
  CHECK(checked > 2000);
}

TEST_CASE("T2.1 triangle: every triangle of a scan-sized mesh (65,024 triangles ~1e-3 across) is hit" *
          grading(3, "triangles ~1e-3 across make det ~ 1e-6: an absolute epsilon such as "
                     "|det| < 1e-6 or t > 1e-4 rejects thousands of true hits")) {
  Scene scene = scanLikeScene();
  const TriangleMesh& mesh = scene.meshes.at(0);
  Random random(25);
  std::vector<calls::IntersectTriangle::Args> tests;
  std::vector<PlaneHit> expected;
  for (const glm::uvec3& t : mesh.triangles) {
    const Point3 &p0 = mesh.positions[t.x], &p1 = mesh.positions[t.y], &p2 = mesh.positions[t.z];
    DVec3 n = glm::cross(DVec3(p1 - p0), DVec3(p2 - p0));
    if (glm::length(n) == 0.0) continue;  // a scanned mesh's degenerate triangles
    DVec3 centroid = (DVec3(p0) + DVec3(p1) + DVec3(p2)) / 3.0;
    DVec3 direction = glm::normalize(glm::normalize(n) + 0.7 * random.unitVector());
    Ray ray = rayTowards(centroid + 0.05 * direction, centroid);
    PlaneHit e = planeHit(ray, p0, p1, p2);
    // The double-precision oracle must agree the ray hits well inside.
    if (e.b1 < 0.01 || e.b2 < 0.01 || e.b1 + e.b2 > 0.99 || e.t <= 0) continue;
    tests.emplace_back(ray, kAll, p0, p1, p2);
    expected.push_back(e);
  }
  const std::vector<std::optional<TriangleHit>> hits = candidate::intersectTriangles(tests);
  const int tested = int(tests.size());
  int missed = 0, wrongT = 0;
  for (size_t i = 0; i < hits.size(); ++i) {
    if (!hits[i]) {
      if (++missed <= 3) {
        MESSAGE("missed triangle " << str(std::get<2>(tests[i])) << " " << str(std::get<3>(tests[i])) << " "
                                   << str(std::get<4>(tests[i])));
      }
    } else if (std::abs(hits[i]->t - expected[i].t) > 1e-4 * expected[i].t) {
      ++wrongT;
    }
  }
  INFO(missed << " misses and " << wrongT << " wrong distances over " << tested << " triangles");
  CHECK(tested > 60000);
  CHECK(missed == 0);
  CHECK(wrongT == 0);
}

// ---------------------------------------------------------------- spheres

TEST_CASE("T2.2 sphere: a ray from outside hits the near side at the right t" *
          grading(3, "solve |o + t d - c|^2 = r^2 for t and return the smaller positive root; b' = f.d "
                     "with f = o - c (not c - o)")) {
  Random random(31);
  for (int i = 0; i < 2000; ++i) {
    Point3 center(random.inCube(10));
    float radius = float(random.uniform(0.1, 3.0));
    Ray ray = rayPastSphere(random, center, radius, radius * random.uniform(1.5, 20.0), random.uniform(0.0, 0.95));
    double expected = sphereOracle(ray, center, radius);
    REQUIRE(expected > 0);
    auto t = candidate::intersectSphere(ray, kAll, center, radius);
    CAPTURE(i);
    REQUIRE(t.has_value());
    CHECK(*t == doctest::Approx(expected).epsilon(1e-4));
  }
}

TEST_CASE("T2.2 sphere: misses beside, behind and outside the range; the far side when the near one is excluded" *
          grading(3, "a negative discriminant is a miss; check both roots against the range, smaller "
                     "first, so a near root below range.min falls through to the far root")) {
  const Point3 c{0, 0, -5};
  const float r = 1.0f;
  const Ray ahead{{0, 0, 0}, {0, 0, -1}};  // roots at t = 4 and t = 6
  REQUIRE(candidate::intersectSphere(ahead, kAll, c, r).has_value());
  CHECK(*candidate::intersectSphere(ahead, kAll, c, r) == doctest::Approx(4.0f));
  CHECK_FALSE(candidate::intersectSphere(Ray{{1.01f, 0, 0}, {0, 0, -1}}, kAll, c, r).has_value());   // beside
  CHECK_FALSE(candidate::intersectSphere(Ray{{0, 0, 0}, {0, 0, 1}}, kAll, c, r).has_value());        // behind
  CHECK_FALSE(candidate::intersectSphere(ahead, {0.0f, 3.9f}, c, r).has_value());                    // too near
  CHECK_FALSE(candidate::intersectSphere(ahead, {6.1f, kInfinity}, c, r).has_value());               // too far
  auto far = candidate::intersectSphere(ahead, {4.5f, kInfinity}, c, r);                             // skip the near root
  REQUIRE(far.has_value());
  CHECK(*far == doctest::Approx(6.0f));
}

TEST_CASE("T2.2 sphere: from inside, the hit is on the far side (origin inside)" *
          grading(2, "inside the sphere one root is negative: return the positive one, t1 = q / a or "
                     "c' / q, whichever is in range")) {
  Random random(32);
  for (int i = 0; i < 1000; ++i) {
    Point3 center(random.inCube(5));
    float radius = float(random.uniform(0.5, 2.0));
    DVec3 origin = DVec3(center) + random.unitVector() * (radius * random.uniform(0.0, 0.9));
    Ray ray{Point3(origin), Vec3(random.unitVector())};
    double expected = sphereOracle(ray, center, radius);
    auto t = candidate::intersectSphere(ray, kAll, center, radius);
    CAPTURE(i);
    REQUIRE(t.has_value());
    CHECK(*t == doctest::Approx(expected).epsilon(1e-4));
  }
}

TEST_CASE("T2.2 sphere: a small sphere far away is hit where it is (no cancellation)" *
          grading(3, "b'^2 - a c' subtracts two huge, nearly equal numbers and loses r^2: use "
                     "r^2 - |f - (b'/a) d|^2, and the stable roots q = -(b' + sign(b') sqrt(D))")) {
  Random random(33);
  int wrong = 0, total = 0;
  for (auto [radius, distance] : {std::pair{0.01, 1e3}, std::pair{1.0, 1e4}, std::pair{1e-3, 50.0}}) {
    for (int i = 0; i < 500; ++i) {
      Point3 center(random.inCube(distance * 0.01));
      double offset = random.uniform(0.0, 1.3);
      if (offset > 0.9 && offset < 1.1) continue;  // leave the tangent band to its own test
      Ray ray = rayPastSphere(random, center, float(radius), distance, offset);
      double expected = sphereOracle(ray, center, float(radius));
      auto t = candidate::intersectSphere(ray, kAll, center, float(radius));
      ++total;
      bool ok = (expected > 0) == t.has_value();
      if (ok && t) ok = std::abs(*t - expected) <= 0.05 * radius + 4e-7 * expected;
      if (!ok && ++wrong <= 3) {
        MESSAGE("radius " << radius << " at distance " << distance << ", offset " << offset << " r: expected "
                          << (expected > 0 ? std::to_string(expected) : "a miss") << ", got "
                          << (t ? std::to_string(*t) : "a miss"));
      }
    }
  }
  INFO(wrong << " of " << total << " rays at small far spheres were wrong");
  CHECK(wrong == 0);
}

TEST_CASE("T2.2 sphere: tangent rays — just inside hits, just outside misses, never NaN" *
          grading(2, "the discriminant of a near-tangent ray is tiny: compute it without cancellation and "
                     "treat D < 0 as a miss before taking sqrt")) {
  Random random(34);
  for (int i = 0; i < 500; ++i) {
    Point3 center(random.inCube(3));
    float radius = float(random.uniform(0.2, 2.0));
    Ray inside = rayPastSphere(random, center, radius, 5.0 * radius, 1.0 - 1e-3);
    Ray outside = rayPastSphere(random, center, radius, 5.0 * radius, 1.0 + 1e-3);
    Ray exact = rayPastSphere(random, center, radius, 5.0 * radius, 1.0);
    CAPTURE(i);
    auto hit = candidate::intersectSphere(inside, kAll, center, radius);
    REQUIRE(hit.has_value());
    CHECK(std::isfinite(*hit));
    CHECK(*hit == doctest::Approx(sphereOracle(inside, center, radius)).epsilon(1e-3));
    CHECK_FALSE(candidate::intersectSphere(outside, kAll, center, radius).has_value());
    auto grazing = candidate::intersectSphere(exact, kAll, center, radius);
    if (grazing) CHECK(std::isfinite(*grazing));
  }
}

TEST_CASE("T2.2 sphere: a ray starting on the surface finds the far side going in, nothing going out" *
          grading(2, "from a point on the surface one root is ~0; with range.min just above it, return the "
                     "far root -2 b' when heading in, and no hit when heading out")) {
  Random random(35);
  for (double radius : {1e-3, 1.0, 1e3}) {
    for (int i = 0; i < 300; ++i) {
      Point3 center(random.inCube(radius * 10));
      DVec3 normal = random.unitVector();
      Point3 origin(DVec3(center) + normal * radius);
      DVec3 in = -normal + 0.8 * random.unitVector();
      if (glm::dot(in, normal) > -0.3) in = -normal;
      in = glm::normalize(in);
      Interval range{float(1e-4 * radius), kInfinity};
      CAPTURE(radius);
      CAPTURE(i);
      auto t = candidate::intersectSphere(Ray{origin, Vec3(in)}, range, center, float(radius));
      REQUIRE(t.has_value());
      CHECK(*t == doctest::Approx(-2.0 * radius * glm::dot(in, normal)).epsilon(1e-3));
      CHECK_FALSE(candidate::intersectSphere(Ray{origin, Vec3(-in)}, range, center, float(radius)).has_value());
    }
  }
}

// ---------------------------------------------------------------- surface points

TEST_CASE("T2.3 triangle surface point: position from barycentrics, normal from the winding" *
          grading(2, "point = b0 p0 + b1 p1 + b2 p2 with b0 = 1 - b1 - b2; geometric normal = "
                     "normalize(cross(p1 - p0, p2 - p0)); shading normal = geometric without vertex normals")) {
  Random random(41);
  for (int i = 0; i < 500; ++i) {
    Point3 p0(random.inCube(5)), p1(random.inCube(5)), p2(random.inCube(5));
    DVec3 n = glm::cross(DVec3(p1 - p0), DVec3(p2 - p0));
    if (glm::length(n) < 0.1) continue;
    float b1 = float(random.uniform(0, 0.6)), b2 = float(random.uniform(0, 0.4));
    SurfacePoint s = candidate::triangleSurfacePoint(TriangleHit{1.0f, b1, b2}, p0, p1, p2, nullptr);
    DVec3 point = (1.0 - b1 - b2) * DVec3(p0) + double(b1) * DVec3(p1) + double(b2) * DVec3(p2);
    CAPTURE(i);
    INFO("expected point " << str(Vec3(point)) << ", got " << str(s.point));
    CHECK(glm::length(DVec3(s.point) - point) < 1e-5);
    INFO("expected normal " << str(Vec3(glm::normalize(n))) << ", got " << str(s.geometricNormal));
    CHECK(near(s.geometricNormal, Vec3(glm::normalize(n)), 1e-5f));
    CHECK(near(s.shadingNormal, s.geometricNormal, 1e-6f));
  }
}

TEST_CASE("T2.3 triangle surface point: vertex normals are interpolated and decide the outside" *
          grading(2, "shading normal = normalize(b0 n0 + b1 n1 + b2 n2); if it points against the geometric "
                     "normal, flip the geometric one; if it is zero, use the geometric normal")) {
  const Point3 p0{0, 0, 0}, p1{1, 0, 0}, p2{0, 1, 0};  // winding normal +z
  const Vec3 up[3] = {glm::normalize(Vec3(-0.3f, 0, 1)), glm::normalize(Vec3(0.3f, 0, 1)), Vec3(0, 0, 1)};
  SurfacePoint s = candidate::triangleSurfacePoint(TriangleHit{1.0f, 0.5f, 0.25f}, p0, p1, p2, up);
  Vec3 expected = glm::normalize(0.25f * up[0] + 0.5f * up[1] + 0.25f * up[2]);
  INFO("expected shading normal " << str(expected) << ", got " << str(s.shadingNormal));
  CHECK(near(s.shadingNormal, expected, 1e-5f));
  CHECK(near(s.geometricNormal, Vec3(0, 0, 1), 1e-6f));

  // Vertex normals pointing down: the geometric normal follows them.
  const Vec3 down[3] = {Vec3(0, 0, -1), glm::normalize(Vec3(0.2f, 0, -1)), Vec3(0, 0, -1)};
  s = candidate::triangleSurfacePoint(TriangleHit{1.0f, 0.2f, 0.3f}, p0, p1, p2, down);
  CHECK(s.shadingNormal.z < -0.9f);
  CHECK(near(s.geometricNormal, Vec3(0, 0, -1), 1e-6f));

  // Opposite normals cancel: fall back to the geometric normal, never NaN.
  const Vec3 opposite[3] = {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(0, 0, 1)};
  s = candidate::triangleSurfacePoint(TriangleHit{1.0f, 0.5f, 0.0f}, p0, p1, p2, opposite);
  REQUIRE(finite(s.shadingNormal));
  CHECK(near(s.shadingNormal, s.geometricNormal, 1e-6f));
  CHECK(std::abs(glm::length(s.geometricNormal) - 1.0f) < 1e-6f);
}

TEST_CASE("T2.4 sphere surface point: on the sphere, with the outward unit normal" *
          grading(2, "normal = normalize(ray.at(t) - center), outward even when the ray starts inside; "
                     "re-project the point onto the sphere: center + radius * normal")) {
  Random random(42);
  for (int i = 0; i < 500; ++i) {
    Point3 center(random.inCube(100));
    float radius = float(random.uniform(0.01, 10.0));
    bool fromInside = i % 2 == 0;
    Ray ray = fromInside ? Ray{Point3(DVec3(center) + random.unitVector() * (0.5 * radius)), Vec3(random.unitVector())}
                         : rayPastSphere(random, center, radius, radius * 3.0, random.uniform(0, 0.9));
    double t = sphereOracle(ray, center, radius);
    REQUIRE(t > 0);
    SurfacePoint s = candidate::sphereSurfacePoint(ray, float(t), center, radius);
    DVec3 expectedNormal = glm::normalize(DVec3(ray.origin) + t * DVec3(ray.direction) - DVec3(center));
    CAPTURE(i);
    INFO("expected normal " << str(Vec3(expectedNormal)) << ", got " << str(s.geometricNormal));
    // The hit point carries float rounding of the coordinates (~1e-7 of their
    // size); divided by a small radius that bends the normal a little.
    const double scale = glm::length(DVec3(ray.origin)) + glm::length(DVec3(center)) + t;
    CHECK(glm::length(DVec3(s.geometricNormal) - expectedNormal) < 1e-5 + 4e-7 * scale / radius);
    CHECK(near(s.shadingNormal, s.geometricNormal, 1e-6f));
    double off = std::abs(glm::length(DVec3(s.point) - DVec3(center)) - radius);
    CHECK(off <= 1e-6 * (radius + glm::length(DVec3(center))));
  }
}

// ---------------------------------------------------------------- images

namespace {

// Triangles seen from both sides, a mesh with vertex normals and one whose
// vertex normals point against its winding (the normals decide the
// outside), spheres seen from outside and the enclosing sky sphere seen from
// inside. The normals view shows each shading normal as a colour.
Scene surfacesScene() {
  Scene scene = sceneFromJson(R"({
    "camera": { "position": [0, 1.0, 4], "look_at": [0, 0.6, 0], "up": [0, 1, 0], "vfov": 45 },
    "render": { "width": 64, "height": 48, "spp": 16 },
    "materials": { "grey": { "albedo": [0.6, 0.6, 0.6] }, "orange": { "albedo": [0.8, 0.5, 0.2] } },
    "meshes": [
      { "name": "floor", "material": "grey", "quad": { "corner": [-3, 0, 3], "edge_u": [6, 0, 0], "edge_v": [0, 0, -6] } },
      { "name": "facing the camera", "material": "orange",
        "quad": { "corner": [-2.0, 0.3, -0.5], "edge_u": [0.8, 0, 0], "edge_v": [0, 0.8, 0.2] } },
      { "name": "facing away", "material": "orange",
        "quad": { "corner": [-1.1, 1.1, -0.5], "edge_u": [0.8, 0, 0.1], "edge_v": [0, -0.8, 0] } }
    ],
    "spheres": [ { "center": [0.0, 0.3, 1.0], "radius": 0.3, "material": "orange" },
                 { "center": [0, 0, 0], "radius": 20, "material": "grey" } ],
    "lights": [ { "type": "point", "position": [1.5, 2.5, 2.5], "intensity": [6, 6, 6] } ]
  })", "surfaces");
  scene.meshes.push_back(smoothSphere(1, Point3(0.9f, 0.5f, -0.2f), 0.5f, 1));
  TriangleMesh inverted = smoothSphere(1, Point3(1.7f, 0.3f, 0.9f), 0.3f, 1);
  for (glm::uvec3& t : inverted.triangles) std::swap(t.y, t.z);  // wound inwards; the normals say outwards
  scene.meshes.push_back(inverted);
  return scene;
}

}  // namespace

TEST_CASE("T2.3 image: triangles from both sides, vertex normals and spheres from inside and out" *
          grading(4, "compare your pictures with the references (files named above): in the normals view a wrong colour "
                     "is a wrong normal (not interpolated, not unit, or not turned to the vertex normals' side); "
                     "holes are missed hits (culled back faces, a sphere from inside)")) {
  checkImage({"02-intersection", "surfaces-normals", surfacesScene(), {.integrator = Integrator::Normals}});
  checkImage({"02-intersection", "surfaces-lit", surfacesScene(), {.integrator = Integrator::Direct}});
}
