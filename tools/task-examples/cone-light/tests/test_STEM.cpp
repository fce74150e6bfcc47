// Autograder suite for task @N@ — @TITLE@. candidate::f(...) is the student's
// f, computed in the candidate process (calls.h); the judge never runs it.
//
// No test pins a convention the handout leaves open: any frame around the
// axis, either end of [cos theta_max, 1] for u.x, distance or its square
// first; a direction exactly on the cone's edge may count as inside or not.
#include "suite/doctest_strings.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "calls.h"
#include "check.h"
#include "suite/grading.h"
#include "statistics.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

// The chi-square tests fail a correct sampler with probability 1e-4 each.
constexpr double kChiSquareP = 1e-4;

// The judge's cos(theta_max), in double from the same float inputs.
double judgeCosThetaMax(Point3 x, Point3 center, float radius) {
  const DVec3 toCenter = DVec3(center) - DVec3(x);
  const double sin2 = double(radius) * double(radius) / glm::dot(toCenter, toCenter);
  return sin2 < 1.0 ? std::sqrt(1.0 - sin2) : -1.0;
}

double judgePdf(float cosThetaMax) { return 1.0 / (2.0 * std::numbers::pi * (1.0 - double(cosThetaMax))); }

// Cones of every kind: axes at random and along +-z (where a frame's
// construction is most fragile), half-angles from narrow to wider than a
// hemisphere, and the whole sphere (cosThetaMax = -1).
struct Cone {
  Vec3 axis;
  float cosThetaMax;
};
std::vector<Cone> someCones(uint32_t seed) {
  Random random(seed);
  std::vector<Cone> cones;
  for (float c : {-1.0f, -0.5f, 0.0f, 0.5f, 0.9f, 0.999f}) {
    cones.push_back({Vec3(0.0f, 0.0f, 1.0f), c});
    cones.push_back({Vec3(0.0f, 0.0f, -1.0f), c});
  }
  for (int i = 0; i < 28; ++i) {
    cones.push_back({glm::normalize(Vec3(random.unitVector())), float(random.uniform(-0.9, 0.995))});
  }
  return cones;
}

// Chi-square of directions against the uniform density over the cone, on
// kCells^2 cells of equal solid angle: cos(theta) from the axis in kCells
// bands of [cosThetaMax, 1], phi around it (in the judge's own frame: a
// uniform density is uniform in phi whatever the frame) in kCells sectors.
// A direction outside the cone, or not unit, is counted in a last cell,
// where none is expected.
ChiSquareResult chiSquareOnCone(const std::string& name, const Cone& cone,
                                const std::vector<@STEM@::ConeSample>& samples) {
  constexpr int kCells = 16;
  const int outside = kCells * kCells;
  std::vector<double> observed(size_t(outside) + 1, 0.0), expected(size_t(outside) + 1, 0.0);
  const DVec3 n = glm::normalize(DVec3(cone.axis));
  const DVec3 helper = std::abs(n.x) > 0.5 ? DVec3(0.0, 1.0, 0.0) : DVec3(1.0, 0.0, 0.0);
  const DVec3 s = glm::normalize(glm::cross(helper, n)), t = glm::cross(n, s);
  for (const @STEM@::ConeSample& sample : samples) {
    const DVec3 w(sample.direction);
    const double length = glm::length(w), cosTheta = glm::dot(w, n) / length;
    const double band = (1.0 - cosTheta) / (1.0 - double(cone.cosThetaMax));  // 0 on the axis, 1 at the edge
    if (!(std::abs(length - 1.0) < 1e-3) || !(band >= -1e-6 && band <= 1.0 + 1e-4)) {
      observed[size_t(outside)] += 1.0;
      continue;
    }
    const double phi = std::atan2(glm::dot(w, t), glm::dot(w, s)) + std::numbers::pi;
    const int i = std::clamp(int(band * kCells), 0, kCells - 1);
    const int j = std::clamp(int(phi / (2.0 * std::numbers::pi) * kCells), 0, kCells - 1);
    observed[size_t(i * kCells + j)] += 1.0;
  }
  for (int c = 0; c < outside; ++c) expected[size_t(c)] = double(samples.size()) / outside;
  ChiSquareResult r = chiSquareTest(observed, expected);
  if (!r.failure.empty() || !(r.pValue > kChiSquareP) || picturesAlways()) {
    // (The last cell, the directions outside the cone, is left out of the pictures.)
    observed.pop_back();
    expected.pop_back();
    r.pictures = writeHistogramPictures(name, observed, expected, kCells, kCells, "phi sector", "cos-theta band");
  }
  return r;
}

}  // namespace

TEST_CASE("T@N@.1 cone: cos theta_max of spheres near and far, and -1 from inside or at the centre" *
          grading(4, "a ray from x grazes the sphere where sin(theta) = radius / d: cos(theta_max) = sqrt(1 - "
                     "(radius / d)^2), and -1 when x is on or inside the sphere")) {
  Random random(1);
  std::vector<calls::ConeCosThetaMax::Args> spheres;
  while (spheres.size() < 2000) {
    const Point3 x(random.inCube(5.0)), center(random.inCube(5.0));
    const float radius = float(random.uniform(0.05, 3.0));
    const double ratio = glm::length(DVec3(center) - DVec3(x)) / radius;
    if (std::abs(ratio - 1.0) < 1e-3) continue;  // on the surface, float rounding decides the side
    spheres.push_back({x, center, radius});
  }
  const Point3 c(1.0f, -2.0f, 0.5f);
  spheres.push_back({c, c, 1.0f});                                    // at the centre
  spheres.push_back({c + Point3(0.0f, 0.0f, 1000.0f), c, 1.0f});       // far: cos theta_max near 1
  spheres.push_back({c + Point3(0.0f, 2.0f, 0.0f), c, 1.99f});         // just outside: a cone of nearly 2 pi
  const std::vector<float> got = candidate::coneCosThetaMax(spheres);
  HINT("a guard of the test itself: one answer comes back for each question asked (the judge checks the "
       "answer's length as it arrives), so it holds for any function that returns");
  REQUIRE(got.size() == spheres.size());
  int wrong = 0, wrongInside = 0;
  std::string first;
  for (size_t k = 0; k < spheres.size(); ++k) {
    const auto& [x, center, radius] = spheres[k];
    const double want = judgeCosThetaMax(x, center, radius);
    // sqrt(1 - s^2) near s = 1 amplifies float rounding of s^2 (relative 1e-7) by 1 / (2 cos^2).
    const double tolerance = 2e-6 + 1e-7 / std::max(1e-3, want * want);
    if (!(std::abs(double(got[k]) - want) <= tolerance)) {
      (want == -1.0 ? wrongInside : wrong) += 1;
      if (first.empty()) first = "e.g. x at distance " + std::to_string(glm::length(DVec3(center) - DVec3(x))) +
                                 " from a sphere of radius " + std::to_string(radius) + ": " +
                                 std::to_string(got[k]) + ", not " + std::to_string(want);
    }
  }
  INFO(wrong << " of the spheres seen from outside wrong; " << first);
  HINT("from outside, cos(theta_max) = sqrt(1 - (radius / d)^2); radius / d is sin(theta_max)");
  CHECK(wrong == 0);
  INFO(wrongInside << " of the points on or inside a sphere (or at its centre) not given -1");
  HINT("from inside the sphere every direction hits it: -1 (also at the centre, where d = 0)");
  CHECK(wrongInside == 0);
}

TEST_CASE("T@N@.2 directions: unit, inside the cone, with the cone's pdf, for every axis and width" *
          grading(3, "turn the local direction by a frame whose +z is the axis, and return 1 / (2 pi (1 - "
                     "cos theta_max)) with it")) {
  int notUnit = 0, outsideCone = 0, wrongPdf = 0, total = 0;
  const std::vector<Vec2> us = uniformPoints(400, 2);
  std::vector<Vec2> corners = {Vec2(0.0f), Vec2(0.0f, 0.99999994f), Vec2(0.99999994f, 0.0f), Vec2(0.99999994f)};
  HINT("a guard of the test itself: one answer comes back for each question asked (the judge checks the "
       "answer's length as it arrives), so it holds for any function that returns");
  for (const Cone& cone : someCones(3)) {
    std::vector<Vec2> asked = us;
    asked.insert(asked.end(), corners.begin(), corners.end());
    const std::vector<@STEM@::ConeSample> samples = candidate::sampleCone(cone.axis, cone.cosThetaMax, asked);
    REQUIRE(samples.size() == asked.size());
    for (const @STEM@::ConeSample& s : samples) {
      ++total;
      const double length = glm::length(DVec3(s.direction));
      notUnit += !(std::abs(length - 1.0) < 1e-4);
      outsideCone += !(glm::dot(DVec3(s.direction), DVec3(cone.axis)) / length >= double(cone.cosThetaMax) - 1e-4);
      wrongPdf += !(std::abs(double(s.pdf) / judgePdf(cone.cosThetaMax) - 1.0) < 1e-4);
    }
  }
  INFO(notUnit << " of " << total << " directions not of unit length");
  HINT("each direction must have length 1 (normalize, or build it from sin and cos of the same angle)");
  CHECK(notUnit == 0);
  INFO(outsideCone << " of " << total << " directions outside their cone");
  HINT("cos(theta) from the axis must lie in [cos theta_max, 1], around the axis given, not around +z");
  CHECK(outsideCone == 0);
  INFO(wrongPdf << " of " << total << " pdfs not 1 / (2 pi (1 - cos theta_max))");
  HINT("the pdf of a uniform direction is 1 over the cone's solid angle, 2 pi (1 - cos theta_max)");
  CHECK(wrongPdf == 0);
}

TEST_CASE("T@N@.2 uniform: directions uniform over a cone and one wider than a hemisphere (chi-square)" *
          grading(4, "uniform in solid angle means cos(theta) uniform on [cos theta_max, 1], not theta: the band at "
                     "theta has area 2 pi sin(theta) d(theta)")) {
  const Cone narrow{glm::normalize(Vec3(0.3f, -0.5f, 0.8f)), 0.6f}, wide{glm::normalize(Vec3(-0.7f, 0.1f, -0.2f)), -0.3f};
  const ChiSquareResult a = chiSquareOnCone("cone-narrow", narrow,
                                            candidate::sampleCone(narrow.axis, narrow.cosThetaMax, uniformPoints(100000, 4)));
  INFO("cos theta_max 0.6: chi-square " << a.statistic << " with " << a.degreesOfFreedom << " degrees of freedom, p = "
                                        << a.pValue << " " << a.failure << a.pictures);
  HINT("the directions over a cone of cos theta_max 0.6 are not uniform by solid angle (or some leave the cone)");
  CHECK((a.failure.empty() && a.pValue > kChiSquareP));
  const ChiSquareResult b = chiSquareOnCone("cone-wide", wide,
                                            candidate::sampleCone(wide.axis, wide.cosThetaMax, uniformPoints(100000, 5)));
  INFO("cos theta_max -0.3: chi-square " << b.statistic << " with " << b.degreesOfFreedom << " degrees of freedom, p = "
                                         << b.pValue << " " << b.failure << b.pictures);
  HINT("a cone wider than a hemisphere (cos theta_max < 0) must be sampled as uniformly as a narrow one");
  CHECK((b.failure.empty() && b.pValue > kChiSquareP));
}

TEST_CASE("T@N@.3 pdf: the cone's density inside it and 0 outside, for every axis and width" *
          grading(3, "the pdf is 1 / (2 pi (1 - cos theta_max)) where dot(w, axis) >= cos theta_max, and 0 "
                     "elsewhere")) {
  Random random(6);
  int wrongInside = 0, wrongOutside = 0, inside = 0, outside = 0;
  HINT("a guard of the test itself: one answer comes back for each question asked (the judge checks the "
       "answer's length as it arrives), so it holds for any function that returns");
  for (const Cone& cone : someCones(7)) {
    std::vector<Vec3> directions;
    while (directions.size() < 500) {
      const Vec3 w(random.unitVector());
      // Directions on the cone's edge may go either way: none within 1e-5 of it.
      if (std::abs(double(glm::dot(w, cone.axis)) - double(cone.cosThetaMax)) > 1e-5) directions.push_back(w);
    }
    const std::vector<float> got = candidate::conePdf(cone.axis, cone.cosThetaMax, directions);
    REQUIRE(got.size() == directions.size());
    for (size_t k = 0; k < directions.size(); ++k) {
      if (glm::dot(directions[k], cone.axis) > cone.cosThetaMax) {
        ++inside;
        wrongInside += !(std::abs(double(got[k]) / judgePdf(cone.cosThetaMax) - 1.0) < 1e-4);
      } else {
        ++outside;
        wrongOutside += !(got[k] == 0.0f);
      }
    }
  }
  INFO(wrongInside << " of " << inside << " directions inside their cone given another density");
  HINT("inside the cone the density is the constant 1 / (2 pi (1 - cos theta_max))");
  CHECK(wrongInside == 0);
  INFO(wrongOutside << " of " << outside << " directions outside their cone given a density other than 0");
  HINT("sampleCone never draws a direction outside the cone: its density there is 0");
  CHECK(wrongOutside == 0);
}
