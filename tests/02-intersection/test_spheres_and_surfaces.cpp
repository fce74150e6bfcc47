// Autograder suite for task 2, part 2: ray–sphere intersection (T2.2) and
// surface points (T2.3, T2.4), then the task's images. Part 1, the triangle
// test (T2.1), is test_intersection.cpp.
// Expected values come from double-precision computations on the same float
// inputs. Tests run from basic to advanced. candidate::f(...) is the
// student's f, computed in the candidate process (calls.h).
#include "suite/doctest_strings.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <vector>

#include "check.h"
#include "image_scenes.h"
#include "image_test.h"
#include "suite/grading.h"
#include "meshes.h"
#include "scenes.h"
#include "scene/scene_io.h"
#include "calls.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

constexpr Interval kAll{0.0f, kInfinity};

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

// ---------------------------------------------------------------- spheres

TEST_CASE("T2.2 sphere: a ray from outside hits the near side at the right t" *
          grading(3, "solve |o + t d - c|^2 = r^2 for t and return the smaller positive root; b' = f.d "
                     "with f = o - c (not c - o)")) {
  Random random(31);
  for (int i = 0; i < 2000; ++i) {
    Point3 center(random.inCube(10));
    float radius = float(random.uniform(0.1, 3.0));
    // Every other ray starts close to the sphere (both roots may then be
    // shorter than the radius): the nearer root is still the one.
    const double distance = radius * (i % 2 ? random.uniform(1.5, 20.0) : random.uniform(0.2, 1.5));
    Ray ray = rayPastSphere(random, center, radius, distance, random.uniform(0.0, 0.95));
    if (glm::length(DVec3(ray.origin) - DVec3(center)) < 1.01 * radius) continue;  // outside only
    double expected = sphereOracle(ray, center, radius);
    HINT("a check of the test itself: the judge's double-precision solve finds that its ray, built to pass "
         "within the radius, hits the sphere (no code of yours runs here); a failure is the judge's, not yours");
    REQUIRE(expected > 0);
    auto t = candidate::intersectSphere(ray, kAll, center, radius);
    CAPTURE(i);
    HINT("a ray from outside whose line passes within 0.95 r of the centre must hit: a miss points to f = c - "
         "o instead of o - c (both roots come out negative), a wrong discriminant, or a root in range that was "
         "rejected");
    REQUIRE(t.has_value());
    HINT("t must be the smaller positive root, the distance to the near side (to 1e-4 relative), also when the "
         "ray starts close to the sphere: the far root, or roots from a formula that mixes b = 2 f.d with the "
         "b' = f.d form, fail here");
    CHECK(*t == doctest::Approx(expected).epsilon(1e-4));
  }
}

TEST_CASE("T2.2 sphere: misses beside, behind and outside the range; the far side when the near one is excluded" *
          grading(3, "a negative discriminant is a miss; check both roots against the range, smaller "
                     "first, so a near root below range.min falls through to the far root")) {
  const Point3 c{0, 0, -5};
  const float r = 1.0f;
  const Ray ahead{{0, 0, 0}, {0, 0, -1}};  // roots at t = 4 and t = 6
  HINT("a ray straight at the sphere, with roots t = 4 and t = 6, must hit at the near root 4: a miss or 6 "
       "means the roots are wrong (f = c - o negates them) or the larger root was returned first");
  REQUIRE(candidate::intersectSphere(ahead, kAll, c, r).has_value());
  CHECK(*candidate::intersectSphere(ahead, kAll, c, r) == doctest::Approx(4.0f));
  HINT("a ray passing 1.01 r from the centre must miss: a negative discriminant is a miss, so a hit means a "
       "wrong discriminant, |D| used, or the sign of D tested the wrong way round");
  CHECK_FALSE(candidate::intersectSphere(Ray{{1.01f, 0, 0}, {0, 0, -1}}, kAll, c, r).has_value());   // beside
  HINT("a sphere behind the ray (roots t = -4 and -6) must miss: roots below range.min = 0 are not hits, so "
       "a hit means a negative root, or its absolute value, was returned");
  CHECK_FALSE(candidate::intersectSphere(Ray{{0, 0, 0}, {0, 0, 1}}, kAll, c, r).has_value());        // behind
  HINT("with the range (0, 3.9) or (6.1, inf) neither root (4 or 6) is inside it, so there is no hit: each "
       "root must be checked against both range.min and range.max before it is returned");
  CHECK_FALSE(candidate::intersectSphere(ahead, {0.0f, 3.9f}, c, r).has_value());                    // too near
  CHECK_FALSE(candidate::intersectSphere(ahead, {6.1f, kInfinity}, c, r).has_value());               // too far
  auto far = candidate::intersectSphere(ahead, {4.5f, kInfinity}, c, r);                             // skip the near root
  HINT("with range.min = 4.5 between the roots the answer is the far root 6: a near root below range.min "
       "must fall through to the far root, not end in a miss or be returned anyway");
  REQUIRE(far.has_value());
  CHECK(*far == doctest::Approx(6.0f));
}

TEST_CASE("T2.2 sphere: the range is open — a root exactly at range.min or range.max does not count" *
          grading(2, "return the smaller root r with range.min < r < range.max (range.contains): a root equal "
                     "to an end of the range is outside it, so the other root may be the answer")) {
  // Roots at exactly t = 2 and t = 8, in float and double, for any method.
  const Ray ray{{0, 0, 0}, {0, 0, -1}};
  const Point3 c{0, 0, -5};
  const float r = 3.0f;
  auto hit = [&](float lo, float hi) { return candidate::intersectSphere(ray, {lo, hi}, c, r); };
  HINT("with the range (0, inf) the answer is the near root, exactly t = 2 (exact in float for any correct "
       "formula): a miss or another value means the roots are wrong or the far root was returned");
  REQUIRE(hit(0.0f, kInfinity).has_value());
  CHECK(*hit(0.0f, kInfinity) == 2.0f);
  HINT("a root equal to range.min is outside the open range: with the range (2, inf) the answer is the far "
       "root 8, so 2 means t >= range.min was used instead of t > range.min, and a miss that the far root "
       "was not tried");
  REQUIRE(hit(2.0f, kInfinity).has_value());  // the near root is excluded: the far one
  CHECK(*hit(2.0f, kInfinity) == 8.0f);
  HINT("with the roots 2 and 8 exactly at the ends of (0, 2), (2, 8) and (8, inf) there is no hit: a hit "
       "means an end of the range was counted as inside it (<= or >= instead of range.contains)");
  CHECK_FALSE(hit(0.0f, 2.0f).has_value());
  CHECK_FALSE(hit(2.0f, 8.0f).has_value());
  CHECK_FALSE(hit(8.0f, kInfinity).has_value());
  HINT("one float inside the range a root counts: range.min just below 2 must give 2, and range.max just "
       "above 8 must give 8; a miss or the other root means an epsilon or a shrunken range, or a root "
       "rounded off its exact value");
  REQUIRE(hit(std::nextafter(2.0f, 0.0f), kInfinity).has_value());
  CHECK(*hit(std::nextafter(2.0f, 0.0f), kInfinity) == 2.0f);
  REQUIRE(hit(3.0f, std::nextafter(8.0f, 9.0f)).has_value());
  CHECK(*hit(3.0f, std::nextafter(8.0f, 9.0f)) == 8.0f);
  // From inside (the origin at the centre): the roots are -3 and 3.
  const Ray inside{{0, 0, -5}, {0, 0, -1}};
  HINT("from the centre the roots are -3 and 3: with 3 exactly at range.max (0, 3) or at range.min (3, inf) "
       "there is no hit; a hit means an end of the range was counted as inside it, or the negative root was "
       "returned");
  CHECK_FALSE(candidate::intersectSphere(inside, {0.0f, 3.0f}, c, r).has_value());
  CHECK_FALSE(candidate::intersectSphere(inside, {3.0f, kInfinity}, c, r).has_value());
  HINT("from the centre (roots -3 and 3) the range (0, 3 + one float) holds the root 3: a miss means the "
       "search stopped at the negative root instead of trying the other one, or an epsilon narrowed the "
       "range");
  REQUIRE(candidate::intersectSphere(inside, {0.0f, std::nextafter(3.0f, 4.0f)}, c, r).has_value());
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
    HINT("from inside the sphere the near root is negative and the far one positive: a miss means the negative "
         "root ended the search instead of falling through to the positive one (t1 = q / a or c' / q, "
         "whichever is in range)");
    REQUIRE(t.has_value());
    HINT("t must be the positive root, the distance to the far side (to 1e-4 relative): the negative root "
         "returned without a range check, or a root from a wrong formula, fails here");
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
    HINT("a ray passing 0.999 r from the centre must hit: a miss means the discriminant of this near-tangent "
         "ray came out negative, from a wrong formula for it or one that loses its tiny value to cancellation");
    REQUIRE(hit.has_value());
    HINT("a hit near or at tangency must have a finite t, never NaN or Inf: treat D < 0 as a miss before "
         "taking sqrt, and test roots with range.contains, which a NaN fails");
    CHECK(std::isfinite(*hit));
    HINT("t must be the near root to 1e-3 relative: near tangency the two roots are close, so the far root, or "
         "a root that lost precision (a discriminant or root formula with cancellation), fails here");
    CHECK(*hit == doctest::Approx(sphereOracle(inside, center, radius)).epsilon(1e-3));
    HINT("a ray passing 1.001 r from the centre must miss: a hit means the discriminant came out >= 0 instead "
         "of negative, from a wrong formula for it (b = 2 f.d mixed with the b' = f.d form) or cancellation");
    CHECK_FALSE(candidate::intersectSphere(outside, kAll, center, radius).has_value());
    auto grazing = candidate::intersectSphere(exact, kAll, center, radius);
    HINT("a hit near or at tangency must have a finite t, never NaN or Inf: treat D < 0 as a miss before "
         "taking sqrt, and test roots with range.contains, which a NaN fails");
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
      HINT("from a point on the surface heading in, with range.min = 1e-4 r just above the root ~0, the far root "
           "must be found: a miss means the near root ended the search instead of falling through, or an "
           "absolute epsilon rejected the far root of a small sphere");
      REQUIRE(t.has_value());
      HINT("heading in from the surface, t must be the far root -2 r dot(d, n), the chord's length, to 1e-3 at "
           "radii 1e-3 to 1e3: the near root ~0 returned, or a far root that lost precision to cancellation, "
           "fails here");
      CHECK(*t == doctest::Approx(-2.0 * radius * glm::dot(in, normal)).epsilon(1e-3));
      HINT("heading out from the surface the roots are ~0 and negative, both below range.min = 1e-4 r: a hit "
           "means range.min was ignored (the root ~0, positive by rounding, was returned) or a negative root was "
           "accepted");
      CHECK_FALSE(candidate::intersectSphere(Ray{origin, Vec3(-in)}, range, center, float(radius)).has_value());
    }
  }
  // Exactly on the surface and tangent to it: both roots are t = 0, outside
  // (0, inf): no hit.
  for (Vec3 direction : {Vec3(0, 0, 1), Vec3(0, -1, 0), Vec3(0, 0.6f, -0.8f)}) {
    CAPTURE(str(direction));
    HINT("exactly on the surface and tangent to it both roots are t = 0, outside (0, inf): a hit means t = 0 "
         "was counted (t >= range.min), or a NaN root from 0 / 0 (c' / q with q = 0) slipped past the range "
         "test");
    CHECK_FALSE(candidate::intersectSphere(Ray{{3.0f, 1.0f, 2.0f}, direction}, kAll, {1.0f, 1.0f, 2.0f}, 2.0f)
                    .has_value());
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
    HINT("the point must be b0 p0 + b1 p1 + b2 p2 with b0 = 1 - b1 - b2 (to 1e-5): weights on the wrong "
         "vertices (b1 belongs to p1, b2 to p2) or a wrong b0 fails here");
    CHECK(glm::length(DVec3(s.point) - point) < 1e-5);
    INFO("expected normal " << str(Vec3(glm::normalize(n))) << ", got " << str(s.geometricNormal));
    HINT("the geometric normal must be the unit normalize(cross(p1 - p0, p2 - p0)): the opposite winding (the "
         "cross product's factors swapped) or a missing normalize fails here");
    CHECK(near(s.geometricNormal, Vec3(glm::normalize(n)), 1e-5f));
    HINT("without vertex normals (normals == nullptr) the shading normal must equal the geometric normal: a "
         "shading normal left unset, flipped or not normalised fails here");
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
  HINT("the shading normal must be normalize(b0 n0 + b1 n1 + b2 n2), the vertex normals blended with the "
       "hit's barycentrics: weights on the wrong vertices, a missing normalize, or the geometric normal kept "
       "instead fails here");
  CHECK(near(s.shadingNormal, expected, 1e-5f));
  HINT("when the blended vertex normal is on the winding's side the geometric normal stays the unit winding "
       "normal (+z here): replacing it with the shading normal, or flipping it, fails here");
  CHECK(near(s.geometricNormal, Vec3(0, 0, 1), 1e-6f));

  // Vertex normals pointing down: the geometric normal follows them.
  const Vec3 down[3] = {Vec3(0, 0, -1), glm::normalize(Vec3(0.2f, 0, -1)), Vec3(0, 0, -1)};
  s = candidate::triangleSurfacePoint(TriangleHit{1.0f, 0.2f, 0.3f}, p0, p1, p2, down);
  HINT("with all vertex normals pointing down (against the winding) the shading normal must follow them: "
       "turning it to the winding's side fails here");
  CHECK(s.shadingNormal.z < -0.9f);
  HINT("when the blended vertex normal points against the winding normal the geometric normal must be "
       "flipped to its side (-z here): the vertex normals decide the outside, so a geometric normal left on "
       "the winding's side fails");
  CHECK(near(s.geometricNormal, Vec3(0, 0, -1), 1e-6f));

  // Opposite normals cancel: fall back to the geometric normal, never NaN.
  const Vec3 opposite[3] = {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(0, 0, 1)};
  s = candidate::triangleSurfacePoint(TriangleHit{1.0f, 0.5f, 0.0f}, p0, p1, p2, opposite);
  HINT("when the vertex normals cancel (their blend is the zero vector) the shading normal must fall back to "
       "the geometric normal: normalising the zero vector gives NaN");
  REQUIRE(finite(s.shadingNormal));
  CHECK(near(s.shadingNormal, s.geometricNormal, 1e-6f));
  HINT("when the vertex normals cancel the geometric normal must stay a unit vector: one replaced by, or "
       "scaled with, the zero blended normal fails here");
  CHECK(std::abs(glm::length(s.geometricNormal) - 1.0f) < 1e-6f);
}

TEST_CASE("T2.4 sphere surface point: on the sphere, with the outward unit normal" *
          grading(2, "normal = normalize(ray.at(t) - center), outward even when the ray starts inside; "
                     "re-project the point onto the sphere: center + radius * normal (from far away, ray.at(t) "
                     "misses the surface by t times the float rounding)")) {
  Random random(42);
  // 500 rays from near the sphere (half from inside), then 200 from 1e3 to
  // 1e4 away: there o + t d lands off the surface by ~t * 6e-8, far more
  // than the re-projected point's rounding.
  for (int i = 0; i < 700; ++i) {
    Point3 center(random.inCube(100));
    float radius = float(random.uniform(0.01, 10.0));
    bool fromInside = i < 500 && i % 2 == 0;
    const double distance = i < 500 ? radius * 3.0 : random.uniform(1e3, 1e4);
    Ray ray = fromInside ? Ray{Point3(DVec3(center) + random.unitVector() * (0.5 * radius)), Vec3(random.unitVector())}
                         : rayPastSphere(random, center, radius, distance, random.uniform(0, 0.9));
    double t = sphereOracle(ray, center, radius);
    HINT("a check of the test itself: the judge's double-precision solve finds the ray's hit on the sphere (no "
         "code of yours runs here); a failure is the judge's, not yours");
    REQUIRE(t > 0);
    SurfacePoint s = candidate::sphereSurfacePoint(ray, float(t), center, radius);
    DVec3 expectedNormal = glm::normalize(DVec3(ray.origin) + t * DVec3(ray.direction) - DVec3(center));
    CAPTURE(i);
    INFO("expected normal " << str(Vec3(expectedNormal)) << ", got " << str(s.geometricNormal));
    // The hit point carries float rounding of the coordinates (~1e-7 of their
    // size); divided by a small radius that bends the normal a little.
    const double scale = glm::length(DVec3(ray.origin)) + glm::length(DVec3(center)) + t;
    HINT("the normal must be the outward unit normalize(ray.at(t) - center), outward also when the ray starts "
         "inside: a normal flipped towards the ray, not normalised, or taken from the wrong point fails here");
    CHECK(glm::length(DVec3(s.geometricNormal) - expectedNormal) < 1e-5 + 4e-7 * scale / radius);
    HINT("on a sphere the shading normal must equal the geometric normal: a shading normal left unset or "
         "different fails here");
    CHECK(near(s.shadingNormal, s.geometricNormal, 1e-6f));
    double off = std::abs(glm::length(DVec3(s.point) - DVec3(center)) - radius);
    HINT("the point must lie on the sphere to float rounding: re-project it as center + radius * normal, since "
         "from far away ray.at(t) misses the surface by about t times the float rounding");
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
