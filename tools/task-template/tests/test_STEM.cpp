// Autograder suite for task @N@ — @TITLE@. candidate::f(...) is the student's
// f, computed in the candidate process (calls.h); the judge never runs it.
//
// No test pins a convention: any uniform map onto the triangle (the square
// root, the fold, either random number first) passes.
#include "suite/doctest_strings.h"

#include <cmath>
#include <string>
#include <vector>

#include "calls.h"
#include "check.h"
#include "suite/grading.h"
#include "statistics.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

// The chi-square test fails a correct sampler with probability 1e-4.
constexpr double kChiSquareP = 1e-4;

// Chi-square of points against the density 2 on the triangle (0, 0), (1, 0),
// (0, 1), on a grid of kCells^2 squares over [0, 1]^2: a square is inside
// (its share: its area), halved by the diagonal (half its area) or outside
// (none). A point outside [0, 1]^2 is counted in the far corner's square,
// where the triangle has no area; a non-finite point is counted apart.
ChiSquareResult chiSquareOnTriangle(const std::string& name, const std::vector<Point2>& points, int* nonFinite) {
  constexpr int kCells = 16;
  std::vector<double> observed(kCells * kCells, 0.0), expected(kCells * kCells, 0.0);
  *nonFinite = 0;
  for (const Point2& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      ++*nonFinite;
      continue;
    }
    const int i = int(std::floor(double(p.x) * kCells)), j = int(std::floor(double(p.y) * kCells));
    const bool inSquare = i >= 0 && j >= 0 && i < kCells && j < kCells;
    observed[inSquare ? size_t(j * kCells + i) : observed.size() - 1] += 1.0;
  }
  const double n = double(points.size() - size_t(*nonFinite)), cellArea = 1.0 / (kCells * kCells);
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const double share = i + j + 2 <= kCells ? 1.0 : i + j + 1 == kCells ? 0.5 : 0.0;
      expected[size_t(j * kCells + i)] = n * 2.0 * share * cellArea;
    }
  ChiSquareResult r = chiSquareTest(observed, expected);
  if (!r.failure.empty() || !(r.pValue > kChiSquareP) || picturesAlways()) {
    r.pictures = writeHistogramPictures(name, observed, expected, kCells, kCells, "x cell", "y cell");
  }
  return r;
}

}  // namespace

TEST_CASE("T@N@.1 triangle: the points lie in the triangle, uniform by area (chi-square against 2)" *
          grading(4, "the slice x = 1 - s of the triangle has length s, so s has density 2s: s = sqrt(u.x), not "
                     "u.x (or fold the square along its diagonal)")) {
  const std::vector<Vec2> us = uniformPoints(100000, 1);
  const std::vector<Point2> points = candidate::sampleTriangle(us);
  HINT("a guard of the test itself: one point comes back for each u asked (the judge checks the answer's "
       "length as it arrives), so it holds for any sampleTriangle that returns");
  REQUIRE(points.size() == us.size());
  int outside = 0;
  for (const Point2& p : points) outside += !(p.x >= -1e-6f && p.y >= -1e-6f && p.x + p.y <= 1.0f + 1e-6f);
  INFO(outside << " of " << points.size() << " points outside the triangle (or not finite)");
  HINT("every point must lie in the triangle (0, 0), (1, 0), (0, 1): x >= 0, y >= 0, x + y <= 1");
  CHECK(outside == 0);
  int nonFinite = 0;
  const ChiSquareResult r = chiSquareOnTriangle("triangle", points, &nonFinite);
  INFO("chi-square " << r.statistic << " with " << r.degreesOfFreedom << " degrees of freedom, p = " << r.pValue
                     << " " << r.failure << r.pictures);
  HINT("the points must be uniform by area (density 2): a map whose slices of the triangle get shares other than "
       "their lengths fails here");
  CHECK(r.failure.empty());
  CHECK(r.pValue > kChiSquareP);
}
