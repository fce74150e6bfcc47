// Autograder suite for task 10 — a thin-lens camera. Tests run from basic to
// advanced; the first failure is usually the root cause. candidate::f(...)
// is the student's f, computed in the candidate process (calls.h). The
// pinhole rays and the camera frames the candidate receives are the judge's
// own (double precision, rounded to float), so task 1 is not graded again.
//
// No test pins a convention: any uniform disk map (polar or concentric, any
// orientation, either random number as the radius) and any way of mapping
// the disk onto the lens's plane (right/up or up/right, either sign) pass.
#include "suite/doctest_strings.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "calls.h"
#include "check.h"
#include "metamorphic.h"
#include "suite/grading.h"
#include "image_scenes.h"
#include "image_test.h"
#include "statistics.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

using DVec2 = glm::dvec2;

// Chi-square tests fail a correct sampler with probability 1e-4 each.
constexpr double kChiSquareP = 1e-4;

Camera makeLens(Point3 position, Point3 lookAt, Vec3 up, float vfov, float aperture, float focal) {
  Camera c;
  c.position = position;
  c.lookAt = lookAt;
  c.up = up;
  c.vfovDegrees = vfov;
  c.apertureRadius = aperture;
  c.focalDistance = focal;
  return c;
}

// Rotated and moved, so that a lens point left in the camera's frame, or the
// world's axes taken for the camera's, lands off the lens.
std::vector<Camera> someLenses() {
  return {makeLens({1, 2, 3}, {-2, 0.5f, 1}, {0, 1, 0}, 50, 0.2f, 4.0f),
          makeLens({-5, 1, 0.5f}, {3, -1, 2}, {0.2f, 1, -0.1f}, 35, 0.05f, 9.5f),
          makeLens({0, 10, 0}, {0.3f, 0, 0.2f}, {0, 0, 1}, 80, 1.5f, 2.0f)};
}

struct LensFrame {
  DVec3 forward, right, up;
};

LensFrame lensFrameOf(const Camera& camera) {
  LensFrame f;
  f.forward = glm::normalize(DVec3(camera.lookAt) - DVec3(camera.position));
  f.right = glm::normalize(glm::cross(f.forward, DVec3(camera.up)));
  f.up = glm::cross(f.right, f.forward);
  return f;
}

CameraBasis basisOf(const LensFrame& f) { return CameraBasis{Vec3(f.forward), Vec3(f.right), Vec3(f.up)}; }

// The pinhole ray through film point s (image plane at distance 1: s = (x, y)
// in units of that plane, x along right, y along up).
Ray pinholeThrough(const Camera& camera, const LensFrame& f, DVec2 s) {
  return Ray{camera.position, Vec3(glm::normalize(f.forward + s.x * f.right + s.y * f.up))};
}

// The film point (image plane at distance 1) of raster point p.
DVec2 filmPoint(const Camera& camera, Point2 p, IVec2 resolution) {
  const double halfHeight = std::tan(double(camera.vfovDegrees) * std::numbers::pi / 360.0);
  const double halfWidth = halfHeight * resolution.x / resolution.y;
  return {(2.0 * p.x / resolution.x - 1.0) * halfWidth, (1.0 - 2.0 * p.y / resolution.y) * halfHeight};
}

// Where a ray reaches depth `depth` along the view axis (t < 0: never, in front of it).
struct AtDepth {
  double t;
  DVec3 point;
};
AtDepth atDepth(const Ray& ray, const Camera& camera, const LensFrame& f, double depth) {
  const DVec3 o(ray.origin), d(ray.direction);
  const double t = (depth - glm::dot(o - DVec3(camera.position), f.forward)) / glm::dot(d, f.forward);
  return {t, o + t * d};
}

// Chi-square of points against the uniform density on the unit disk, on a
// grid over [-1.05, 1.05]^2 (a point outside the disk lands where the
// density is 0). Cell areas inside the disk by a fine midpoint rule.
ChiSquareResult chiSquareOnDisk(const std::string& name, const std::vector<Point2>& points, int* nonFinite) {
  constexpr int kCells = 24, kSub = 32;
  constexpr double kLo = -1.05, kSize = 2.1 / kCells;
  std::vector<double> observed(kCells * kCells, 0.0), expected(kCells * kCells, 0.0);
  *nonFinite = 0;
  for (const Point2& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      ++*nonFinite;
      continue;
    }
    const int i = int(std::floor((double(p.x) - kLo) / kSize)), j = int(std::floor((double(p.y) - kLo) / kSize));
    if (i < 0 || j < 0 || i >= kCells || j >= kCells) {
      // Far outside: counted in a corner cell, where the disk has no area.
      observed[0] += 1.0;
      continue;
    }
    observed[size_t(j * kCells + i)] += 1.0;
  }
  const double n = double(points.size() - size_t(*nonFinite));
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      int inside = 0;
      for (int b = 0; b < kSub; ++b)
        for (int a = 0; a < kSub; ++a) {
          const double x = kLo + (i + (a + 0.5) / kSub) * kSize, y = kLo + (j + (b + 0.5) / kSub) * kSize;
          inside += x * x + y * y <= 1.0;
        }
      expected[size_t(j * kCells + i)] = n * (double(inside) / (kSub * kSub)) * kSize * kSize / std::numbers::pi;
    }
  ChiSquareResult r = chiSquareTest(observed, expected);
  if (!r.failure.empty() || !(r.pValue > kChiSquareP) || picturesAlways()) {
    r.pictures = writeHistogramPictures(name, observed, expected, kCells, kCells, "x cell", "y cell");
  }
  return r;
}

void checkChiSquare(const ChiSquareResult& r) {
  INFO("chi-square " << r.statistic << " with " << r.degreesOfFreedom << " degrees of freedom, p = " << r.pValue
                     << " " << r.failure << r.pictures);
  CHECK(r.failure.empty());
  CHECK(r.pValue > kChiSquareP);
}

}  // namespace

TEST_CASE("T10.1 disk: every point lies in the unit disk, and the points reach its edge all the way round" *
          grading(2, "return a point of the disk of radius 1 (|p| <= 1) for every u in [0,1)^2, including u = 0; "
                     "the radius must reach 1 as u does (r = sqrt(u), not a constant), and the angle must go "
                     "all the way round (phi = 2 pi u, not pi u)")) {
  std::vector<Vec2> us;
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) us.emplace_back((float(i) + 0.5f) / 64.0f, (float(j) + 0.5f) / 64.0f);
  for (float a : {0.0f, 0.5f, 0.99999994f})
    for (float b : {0.0f, 0.5f, 0.99999994f}) us.emplace_back(a, b);
  const std::vector<Point2> points = candidate::sampleUnitDisk(us);
  HINT("a guard of the test itself: one point comes back for each u asked (the judge checks the answer's "
       "length as it arrives), so it holds for any sampleUnitDisk that returns");
  REQUIRE(points.size() == us.size());
  double largest = 0.0;
  int sectors[8] = {};  // where the points beyond radius 0.7 fall, by angle
  for (size_t k = 0; k < points.size(); ++k) {
    const Point2 p = points[k];
    INFO("u = (" << us[k].x << ", " << us[k].y << ") gave (" << p.x << ", " << p.y << ")");
    HINT("every point must be finite for every u in [0,1)^2, u = 0 and the square's centre included: a 0 / 0 (the "
         "concentric map's a = 0 case left unguarded) or a log or sqrt of a negative gives NaN here");
    REQUIRE(std::isfinite(p.x));
    REQUIRE(std::isfinite(p.y));
    const double r = std::hypot(double(p.x), double(p.y));
    HINT("every point must lie in the unit disk (|p| <= 1): a radius that can pass 1 (2u, or the concentric map "
         "without a = 2u - 1), or a point of the square rather than the disk, fails here");
    REQUIRE(r <= 1.0 + 1e-6);
    largest = std::max(largest, r);
    if (r > 0.7) {
      const double phi = std::atan2(double(p.y), double(p.x)) + std::numbers::pi;
      sectors[std::min(7, int(phi / (std::numbers::pi / 4.0)))]++;
    }
  }
  INFO("the farthest point from the centre is at radius " << largest);
  HINT("the points must reach the disk's edge (radius above 0.98 as u nears its ends): a radius that stays short of "
       "1 (a constant below 1, or halved) fails here");
  CHECK(largest > 0.98);
  for (int s = 0; s < 8; ++s) {
    INFO("sector " << s << " of 8 (by angle) has " << sectors[s] << " points beyond radius 0.7");
    HINT("points near the edge must fall in all 8 sectors of angle: an angle that covers only part of the circle "
         "(in the polar map phi = pi u, not 2 pi u) fails here");
    CHECK(sectors[s] > 0);
  }
}

TEST_CASE("T10.1 disk: the points are uniform by area (chi-square against 1/pi)" *
          grading(4, "dA = r dr dphi: a uniform radius crowds the centre; r = sqrt(u.x) (or the concentric map) "
                     "gives equal areas equal shares")) {
  for (uint64_t seed : {1, 2}) {
    CAPTURE(seed);
    int nonFinite = 0;
    const ChiSquareResult r =
        chiSquareOnDisk("disk-" + std::to_string(seed), candidate::sampleUnitDisk(uniformPoints(200000, 100 + seed)),
                        &nonFinite);
    HINT("every point must be finite: a 0 / 0 (the concentric map's a = 0 case left unguarded) gives NaN here");
    CHECK(nonFinite == 0);
    HINT("the points must be uniform by area over the unit disk (density 1/pi): dA = r dr dphi, so in the polar map "
         "r = u (not sqrt u) crowds the centre; any map that does not give equal areas equal shares, or points "
         "outside the disk, fail here");
    checkChiSquare(r);
  }
}

TEST_CASE("T10.2 lens: rays start on the lens, a disk of the aperture's radius facing the view, spread uniformly" *
          grading(3, "the lens point is camera.position + x right + y up with (x, y) = apertureRadius * "
                     "sampleUnitDisk(uLens): in the world, across the view (basis.right, basis.up), not (x, y, 0) "
                     "and not along forward")) {
  int index = 0;
  for (const Camera& camera : someLenses()) {
    const LensFrame f = lensFrameOf(camera);
    const Ray pinhole = pinholeThrough(camera, f, {0.1, -0.05});
    std::vector<calls::LensQuery> queries;
    for (const Vec2& u : uniformPoints(60000, 200 + uint64_t(index))) queries.emplace_back(pinhole, u);
    const std::vector<Ray> rays = candidate::generateThinLensRays(camera, basisOf(f), queries);
    HINT("a guard of the test itself: one ray comes back for each query (the judge checks the answer's length as it "
         "arrives), so it holds for any generateThinLensRay that returns");
    REQUIRE(rays.size() == queries.size());
    std::vector<Point2> onLens;
    double offPlane = 0.0, farthest = 0.0;
    for (const Ray& ray : rays) {
      const DVec3 v = DVec3(ray.origin) - DVec3(camera.position);
      offPlane = std::max(offPlane, std::abs(glm::dot(v, f.forward)));
      farthest = std::max(farthest, glm::length(v));
      onLens.emplace_back(float(glm::dot(v, f.right) / camera.apertureRadius),
                          float(glm::dot(v, f.up) / camera.apertureRadius));
    }
    CAPTURE(index);
    INFO("camera at " << str(camera.position) << " looking along " << str(Vec3(f.forward)) << ", lens radius "
                      << camera.apertureRadius << ": origins reach " << offPlane
                      << " out of the lens's plane (along forward) and " << farthest << " from its centre");
    HINT("ray origins must lie in the lens's plane, across the view through camera.position: a lens point moved "
         "along forward, or (x, y, 0) added in the world's axes rather than along basis.right and basis.up, fails "
         "here");
    CHECK(offPlane <= 1e-5 * (1.0 + glm::length(DVec3(camera.position))));
    HINT("ray origins must lie within apertureRadius of camera.position: the unit disk scaled by the diameter or "
         "not scaled at all, or a lens point not added to camera.position, fails here");
    CHECK(farthest <= camera.apertureRadius * (1.0 + 1e-5) + 1e-6 * glm::length(DVec3(camera.position)));
    int nonFinite = 0;
    HINT("the origins, measured in aperture radii along basis.right and basis.up, must be uniform over the unit disk: "
         "lens points not uniform by area (r = u in the polar map), a lens tilted or squashed (world axes taken for "
         "the camera's), or a radius other than apertureRadius fails here");
    checkChiSquare(chiSquareOnDisk("lens-" + std::to_string(index), onLens, &nonFinite));
    HINT("every origin must be finite: a NaN from the disk map (the concentric map's a = 0 case left unguarded) "
         "fails here");
    CHECK(nonFinite == 0);
    ++index;
  }
}

namespace {


// Rays through film points from many lens points: each must pass through the
// pinhole ray's point on the plane of focus, and the lens must be open
// (origins spread over at least half its radius).
void checkFocus(const Camera& camera, const std::vector<DVec2>& films, double relativeTolerance, uint64_t seed) {
  const LensFrame f = lensFrameOf(camera);
  constexpr int kLensPoints = 64;
  std::vector<calls::LensQuery> queries;
  const std::vector<Vec2> us = uniformPoints(kLensPoints, seed);
  for (const DVec2& s : films)
    for (const Vec2& u : us) queries.emplace_back(pinholeThrough(camera, f, s), u);
  const std::vector<Ray> rays = candidate::generateThinLensRays(camera, basisOf(f), queries);
  HINT("a guard of the test itself: one ray comes back for each query (the judge checks the answer's length as it "
       "arrives), so it holds for any generateThinLensRay that returns");
  REQUIRE(rays.size() == queries.size());
  CAPTURE(str(camera.position));
  CAPTURE(camera.apertureRadius);
  CAPTURE(camera.focalDistance);
  CAPTURE(camera.vfovDegrees);
  for (size_t k = 0; k < films.size(); ++k) {
    const Ray& pinhole = std::get<0>(queries[k * kLensPoints]);
    // The point in focus, in double from the (float) pinhole ray the candidate got.
    const AtDepth focus = atDepth(pinhole, camera, f, camera.focalDistance);
    const double scale = glm::length(focus.point - DVec3(camera.position)) + camera.apertureRadius +
                         glm::length(DVec3(camera.position));
    double worst = 0.0, spread = 0.0;
    Vec3 worstDirection(0.0f), firstOrigin = rays[k * kLensPoints].origin;
    bool finiteUnit = true, ahead = true;
    for (int j = 0; j < kLensPoints; ++j) {
      const Ray& ray = rays[k * kLensPoints + size_t(j)];
      if (!finite(ray.origin) || !finite(ray.direction) || std::abs(glm::length(ray.direction) - 1.0f) > 1e-5f) {
        finiteUnit = false;
        worstDirection = ray.direction;
        continue;
      }
      const AtDepth reached = atDepth(ray, camera, f, camera.focalDistance);
      if (!(reached.t > 0.0)) ahead = false;
      const double miss = glm::length(reached.point - focus.point);
      if (!(miss <= worst)) worst = miss, worstDirection = ray.direction;
      spread = std::max(spread, double(glm::length(ray.origin - firstOrigin)));
    }
    INFO("film point (" << films[k].x << ", " << films[k].y << ") (image plane at distance 1): the point in focus is "
                        << str(Vec3(focus.point)) << "; your rays pass the plane of focus up to " << worst
                        << " from it (direction " << str(worstDirection) << "), and their origins spread " << spread);
    HINT("every ray must have a finite origin and a unit direction: normalise p - l (lens point to the point in "
         "focus) last; a direction left unnormalised, or a NaN from the disk map or a division by zero, fails here");
    CHECK(finiteUnit);
    HINT("every ray must reach the plane of focus ahead of its origin: a direction from the point in focus back to "
         "the lens point (l - p rather than p - l), or a point in focus behind the camera, fails here");
    CHECK(ahead);
    HINT("every ray from one film point must pass through the pinhole ray's point on the plane of focus, p = o + t d "
         "with t = focalDistance / dot(d, forward): t = focalDistance along the ray, a direction not re-aimed after "
         "moving the origin, or precision lost before normalising p - l fails here");
    CHECK(worst <= relativeTolerance * scale);
    HINT("the lens must be open: the origins of one film point's rays must spread over at least half the aperture "
         "radius; an origin kept at camera.position, a radius shrunk below apertureRadius, or a lens point that "
         "ignores uLens fails here");
    CHECK(spread >= 0.5 * camera.apertureRadius);
  }
}

}  // namespace

TEST_CASE("T10.2 focus: every ray from one film point passes through one point of the plane of focus, the pinhole "
          "ray's" *
          grading(4, "aim from the lens point at p = o + t d with t = focalDistance / dot(d, forward): the plane of "
                     "focus is perpendicular to the view (t = focalDistance along every ray would focus on a sphere "
                     "and blur the image's edges), and the direction must be re-aimed after moving the origin")) {
  Random random(31);
  uint64_t seed = 300;
  for (const Camera& camera : someLenses()) {
    const IVec2 resolution{320, 240};
    std::vector<DVec2> films;
    for (Point2 p : {Point2(160, 120), Point2(0, 0), Point2(320, 240), Point2(0, 240), Point2(320, 0), Point2(300, 20)})
      films.push_back(filmPoint(camera, p, resolution));
    for (int i = 0; i < 6; ++i) {
      films.push_back(filmPoint(camera, Point2(float(random.uniform()) * 320.0f, float(random.uniform()) * 240.0f),
                                resolution));
    }
    checkFocus(camera, films, 2e-5, seed++);
  }
}

TEST_CASE("T10.2 lens of radius 0: the pinhole's rays; a tiny lens: rays next to them" *
          grading(2, "with apertureRadius = 0 the origin is camera.position and the direction the pinhole ray's; "
                     "scale the unit disk by the radius (not the diameter), and let the radius open the lens")) {
  for (Camera camera : someLenses()) {
    const LensFrame f = lensFrameOf(camera);
    std::vector<calls::LensQuery> queries;
    std::vector<Ray> pinholes;
    Random random(41);
    for (int i = 0; i < 200; ++i) {
      const Ray pinhole = pinholeThrough(camera, f, {random.uniform() - 0.5, random.uniform() - 0.5});
      pinholes.push_back(pinhole);
      queries.emplace_back(pinhole, Vec2(float(random.uniform()), float(random.uniform())));
    }
    camera.apertureRadius = 0.0f;
    const std::vector<Ray> rays = candidate::generateThinLensRays(camera, basisOf(f), queries);
    HINT("a guard of the test itself: one ray comes back for each query (the judge checks the answer's length as it "
         "arrives), so it holds for any generateThinLensRay that returns");
    REQUIRE(rays.size() == pinholes.size());
    for (size_t k = 0; k < rays.size(); ++k) {
      INFO("lens radius 0: pinhole ray " << str(pinholes[k].origin) << " -> " << str(pinholes[k].direction)
                                         << ", yours " << str(rays[k].origin) << " -> " << str(rays[k].direction));
      HINT("with apertureRadius = 0 every origin must be camera.position: a lens point not scaled by the radius, or "
           "an offset added to the origin whatever the radius, fails here");
      CHECK(glm::length(rays[k].origin - camera.position) <= 1e-6f * (1.0f + glm::length(camera.position)));
      HINT("with apertureRadius = 0 the direction must be the pinhole ray's own, to 2e-6: a direction left "
           "unnormalised, aimed the wrong way (t < 0), or rebuilt rather than taken from pinholeRay fails here");
      CHECK(glm::length(rays[k].direction - pinholes[k].direction) <= 2e-6f);
    }
    camera.apertureRadius = 1e-4f * camera.focalDistance;
    checkFocus(camera, {{0.0, 0.0}, {0.3, -0.2}}, 2e-5, 400);
  }
}

TEST_CASE("T10.2 extreme lenses: focus a millimetre away or ten kilometres, apertures larger than the focal distance" *
          grading(2, "compute t = focalDistance / dot(d, forward) and p = o + t d, then normalise p - lens point "
                     "last; with a focus point closer than the lens is wide, the direction still aims at it")) {
  const std::vector<DVec2> films = {{0.0, 0.0}, {2.0, -1.5}, {-11.0, 8.0}};  // up to 85 degrees off the axis
  for (float focal : {1e-3f, 0.7f, 1e4f}) {
    for (float aperture : {1e-3f * focal, 0.5f * focal, 10.0f * focal}) {
      checkFocus(makeLens({2, -1, 4}, {1, 0.5f, -3}, {0, 1, 0}, 175, aperture, focal), films, 1e-4, 500);
    }
  }
}

namespace {


// A small flat light facing the camera at depth z, off the axis: through a
// thin lens focused at F it is seen spread over its circle of confusion,
// radius A |1 - z/F| / z on the image plane at distance 1, convolved with
// its own image (radius rho / z). The judge draws film points uniformly over
// the disk of both radii together (every point that can see the light),
// asks the candidate for one lens ray through each, and finds which hit
// the light. The hits' film points then have
//   centre            the light's pinhole image c,
//   mean |s - c|^2    R^2 / 2 + r^2 / 2   (two uniform disks convolved),
//   share of hits     r^2 / (R + r)^2     (the light's etendue: a lens
//                                          spreads the light, never adds).
void checkBlur(const Camera& camera, double depth, DVec2 image, uint64_t seed) {
  const LensFrame f = lensFrameOf(camera);
  const double F = camera.focalDistance, A = camera.apertureRadius;
  const double R = A * std::abs(1.0 - depth / F) / depth;  // circle of confusion, image plane at distance 1
  const double r = R / 3.0;                                // the light's own image
  const double rho = r * depth;                            // its radius in the world
  const DVec3 centre = DVec3(camera.position) + depth * (f.forward + image.x * f.right + image.y * f.up);
  constexpr int kRays = 160000;
  Random random{uint32_t(seed)};
  std::vector<calls::LensQuery> queries;
  std::vector<DVec2> films;
  const std::vector<Vec2> us = uniformPoints(kRays, seed);
  for (int i = 0; i < kRays; ++i) {
    const double radius = (R + r) * std::sqrt(random.uniform()), phi = 2.0 * std::numbers::pi * random.uniform();
    const DVec2 s = image + radius * DVec2(std::cos(phi), std::sin(phi));
    films.push_back(s);
    queries.emplace_back(pinholeThrough(camera, f, s), us[size_t(i)]);
  }
  const std::vector<Ray> rays = candidate::generateThinLensRays(camera, basisOf(f), queries);
  HINT("a guard of the test itself: one ray comes back for each query (the judge checks the answer's length as it "
       "arrives), so it holds for any generateThinLensRay that returns");
  REQUIRE(rays.size() == queries.size());
  std::vector<DVec2> hits;
  for (size_t i = 0; i < rays.size(); ++i) {
    if (!finite(rays[i].direction) || !finite(rays[i].origin)) continue;
    const AtDepth at = atDepth(rays[i], camera, f, depth);
    if (at.t > 0.0 && glm::length(at.point - centre) <= rho) hits.push_back(films[i]);
  }
  const double n = double(hits.size());
  DVec2 mean(0.0);
  for (const DVec2& s : hits) mean += s / std::max(n, 1.0);
  double spread = 0.0;
  for (const DVec2& s : hits) spread += glm::dot(s - mean, s - mean) / std::max(n, 1.0);
  const double measuredR = std::sqrt(std::max(0.0, 2.0 * spread - r * r));
  const double share = r * r / ((R + r) * (R + r));
  const double expectedHits = kRays * share, sigmaHits = std::sqrt(kRays * share * (1.0 - share));
  INFO("a light of radius " << rho << " at depth " << depth << " (focus at " << F << ", lens radius " << A
                            << "), its pinhole image at (" << image.x << ", " << image.y << "): the thin lens spreads "
                            << "it over a circle of radius " << R << " (image plane at distance 1); your rays: "
                            << n << " of " << kRays << " hit it (expected " << expectedHits << " +- " << sigmaHits
                            << "), centred at (" << mean.x << ", " << mean.y << "), circle radius " << measuredR);
  HINT("the share of rays that hit the light must be r^2 / (R + r)^2 (a lens spreads light, never adds it): lens "
       "points beyond the aperture radius (the diameter used), a direction not re-aimed at the plane of focus, or a "
       "wrong point in focus sends hits outside the circle of confusion");
  CHECK(std::abs(n - expectedHits) <= 5.0 * sigmaHits);
  HINT("more than 100 rays must hit the light: rays that miss it altogether (a wrong point in focus, directions "
       "reversed, or rays that are not finite) fail here");
  REQUIRE(n > 100.0);
  // Centre within 0.03 R, radius within 3 %: their standard errors are 0.005 R and 0.4 % (40 seeds measured).
  HINT("the blur must be centred on the light's pinhole image: a shifted circle means the origin moved without "
       "re-aiming the ray at the point in focus, or lens points that cover only part of the disk (phi = pi u in the polar map)");
  CHECK(glm::length(mean - image) <= 0.03 * R);
  HINT("the blur's radius must be the circle of confusion's, R = A |1 - z/F| / z: too small means lens points crowd "
       "the centre (not uniform by area) or a halved aperture, too large the diameter used, and the wrong size off "
       "the axis a focus measured along the ray");
  CHECK(std::abs(measuredR - R) <= 0.03 * R);
}

}  // namespace

TEST_CASE("T10.2 blur: a small light off the plane of focus spreads over the thin lens's circle of confusion" *
          grading(4, "a point at depth z blurs over radius A |1 - z/F| / z (image plane at distance 1): too small a "
                     "circle means the lens points crowd the centre (r = u, not sqrt u) or the radius is halved; "
                     "the wrong size at the image's edge means the focus is measured along the ray; a shifted "
                     "circle means the origin moved without re-aiming the ray")) {
  const Camera camera = makeLens({1, 2, 3}, {-2, 0.5f, 1}, {0, 1, 0}, 60, 0.1f, 5.0f);
  checkBlur(camera, 2.0, {0.05, 0.02}, 600);   // in front of the plane of focus, near the middle
  checkBlur(camera, 15.0, {0.6, -0.4}, 601);   // behind it, near a corner (35 degrees off the axis)
  checkBlur(camera, 3.0, {-0.55, 0.35}, 602);  // in front, towards another corner
}

// ---------------------------------------------------------------- images

namespace {


// Spheres at three depths over a striped floor, and tiny bright lights far
// behind: in focus on the middle sphere, the near one and the far stripes
// blur, and the lights spread into disks.
Scene lensScene(float focalDistance, Vec3 up) {
  Scene scene = sceneFromJson(R"({
    "camera": { "position": [0.4, 1.0, 4.0], "look_at": [-0.2, 0.7, -4], "up": [0, 1, 0], "vfov": 38,
                "aperture_radius": 0.15 },
    "render": { "width": 64, "height": 40, "spp": 32, "max_depth": 2 },
    "materials": {
      "light": { "albedo": [0.75, 0.75, 0.7] }, "dark": { "albedo": [0.1, 0.1, 0.12] },
      "red": { "albedo": [0.8, 0.15, 0.1] }, "green": { "albedo": [0.2, 0.7, 0.25] }, "blue": { "albedo": [0.15, 0.3, 0.85] },
      "bulb": { "albedo": [0, 0, 0], "emission": [30, 25, 12] }
    },
    "meshes": [
      { "name": "stripe 0", "material": "light", "quad": { "corner": [-5, 0, 3], "edge_u": [10, 0, 0], "edge_v": [0, 0, -2] } },
      { "name": "stripe 1", "material": "dark",  "quad": { "corner": [-5, 0, 1], "edge_u": [10, 0, 0], "edge_v": [0, 0, -2] } },
      { "name": "stripe 2", "material": "light", "quad": { "corner": [-5, 0, -1], "edge_u": [10, 0, 0], "edge_v": [0, 0, -2] } },
      { "name": "stripe 3", "material": "dark",  "quad": { "corner": [-5, 0, -3], "edge_u": [10, 0, 0], "edge_v": [0, 0, -2] } },
      { "name": "stripe 4", "material": "light", "quad": { "corner": [-5, 0, -5], "edge_u": [10, 0, 0], "edge_v": [0, 0, -2] } },
      { "name": "stripe 5", "material": "dark",  "quad": { "corner": [-5, 0, -7], "edge_u": [10, 0, 0], "edge_v": [0, 0, -2] } }
    ],
    "spheres": [ { "center": [-0.9, 0.45, 1.6], "radius": 0.45, "material": "red" },
                 { "center": [0.1, 0.5, -1.2], "radius": 0.5, "material": "green" },
                 { "center": [1.2, 0.6, -5.0], "radius": 0.6, "material": "blue" },
                 { "center": [-1.5, 1.8, -8.5], "radius": 0.08, "material": "bulb" },
                 { "center": [0.8, 2.2, -8.5], "radius": 0.08, "material": "bulb" } ],
    "environment": { "color": [0.35, 0.4, 0.5] }
  })", "thin-lens");
  scene.camera.focalDistance = focalDistance;
  scene.camera.up = glm::normalize(up);
  return scene;
}

}  // namespace

TEST_CASE("T10.2 metamorphic: a lens moved, turned and resized with its scene gives the moved rays" *
          grading(1, "the lens lies in the camera's own frame (basis.right, basis.up), its radius and the focal "
                     "distance are lengths of the scene: nothing may be fixed in the world's axes or units")) {
  // The relations (docs/metamorphic.md): a camera moved, turned and
  // resized with its aperture and focal distance gives each pinhole ray and
  // lens sample the ray moved and turned alike. Beside them, the truth:
  // every ray from one film point meets the pinhole ray in the plane of
  // focus (T10.2's focus test, here on the unmoved lens).
  const std::vector<Similarity> relations = {
      {"1000 times smaller", 1e-3},
      {"turned and 1000 times larger", 1e3, rotationAbout({1, -2, 0.5}, 133)},
      {"turned and moved 1000 units away", 1.0, rotationAbout({0, 0, 1}, 90), {1e3, -400, 250}}};
  int index = 0;
  for (const Camera& camera : someLenses()) {
    const LensFrame f = lensFrameOf(camera);
    std::vector<calls::LensQuery> queries;
    for (const Vec2& u : uniformPoints(200, 260 + uint64_t(index++))) {
      queries.emplace_back(pinholeThrough(camera, f, {double(u.x) - 0.5, 0.3 * (double(u.y) - 0.5)}), u);
    }
    const std::vector<Ray> rays = candidate::generateThinLensRays(camera, basisOf(f), queries);
    HINT("a guard of the test itself: one ray comes back for each query");
    REQUIRE(rays.size() == queries.size());
    int unfocused = 0;
    double widest = 0.0;
    for (size_t k = 0; k < rays.size(); ++k) {
      const Ray& pinhole = std::get<0>(queries[k]);
      const AtDepth lens = atDepth(rays[k], camera, f, camera.focalDistance);
      const AtDepth hole = atDepth(pinhole, camera, f, camera.focalDistance);
      if (!(lens.t > 0.0) || glm::length(lens.point - hole.point) > 1e-4 * camera.focalDistance) ++unfocused;
      widest = std::max(widest, glm::length(DVec3(rays[k].origin) - DVec3(camera.position)) / camera.apertureRadius);
    }
    INFO(unfocused << " of " << rays.size() << " rays miss their pinhole ray's point in the plane of focus; the "
                   << "farthest origin is " << widest << " lens radii from the lens's centre");
    HINT("the relations below compare your rays with themselves, so they must first be right: rays start across "
         "the whole lens (up to its radius from camera.position) and every ray from one film point passes through "
         "the pinhole ray's point in the plane of focus");
    REQUIRE(unfocused == 0);
    REQUIRE(widest > 0.9);
    REQUIRE(widest <= 1.0 + 1e-4);
    for (const Similarity& t : relations) {
      Scene moved;
      moved.camera = camera;
      moved = transformed(moved, t);
      std::vector<calls::LensQuery> movedQueries;
      for (const auto& [pinhole, u] : queries) movedQueries.emplace_back(t.ray(pinhole), u);
      const std::vector<Ray> after =
          candidate::generateThinLensRays(moved.camera, basisOf(lensFrameOf(moved.camera)), movedQueries);
      HINT("a guard of the test itself: one ray comes back for each query");
      REQUIRE(after.size() == rays.size());
      int differing = 0;
      for (size_t k = 0; k < rays.size(); ++k) {
        const Ray expected = t.ray(rays[k]);
        const float origin = 1e-5f * float(t.scale) + 1e-6f * glm::length(expected.origin);
        if (!near(after[k].origin, expected.origin, origin) || !near(after[k].direction, expected.direction, 2e-4f)) {
          ++differing;
        }
      }
      CAPTURE(t.name);
      INFO("lens at " << str(camera.position) << ": " << differing << " of " << rays.size()
                      << " rays are not the moved rays");
      HINT("the rays change when the lens and its world are moved, turned or resized together: put the lens point "
           "at camera.position + apertureRadius (x basis.right + y basis.up), aim at the pinhole ray's point at "
           "focalDistance along basis.forward; nothing in the world's axes or in fixed units");
      CHECK(differing == 0);
    }
  }
}

TEST_CASE("T10.2 image: focused on the middle sphere, the near sphere and the far stripes blur" *
          grading(3, "compare your picture with the reference (files named above): sharp everywhere means the lens "
                     "is closed (the radius unused); a shifted picture means the origin moved without re-aiming; "
                     "sharp only at the centre means the focus is measured along each ray")) {
  checkImage({"10-thin-lens", "focus-middle", lensScene(5.2f, Vec3(0, 1, 0)), {.integrator = Integrator::Path}});
}

TEST_CASE("T10.2 image: a rolled camera focused near, the far lights spread into disks" *
          grading(2, "the lens lies across the view (basis.right and basis.up), whatever the roll; the bright "
                     "lights far behind become disks the size of their circle of confusion")) {
  checkImage({"10-thin-lens", "focus-near-rolled", lensScene(2.6f, Vec3(0.3f, 1, 0)), {.integrator = Integrator::Path}});
}
