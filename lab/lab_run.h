// One run of a warp in the sampling lab, between its test (lab.cpp: draw,
// bin, integrate the pdf over the same bins, chi-square) and its figure
// (lab_figure.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "lab.h"
#include "util/sampling.h"

namespace pathlab::lab {

constexpr int kIntervalBins = 50;
constexpr int kShownPoints = 4000;  // points drawn in the scatter

// The bins of a domain: cell index of a point (-1: outside), the expected
// count of every cell for n samples, and the cells' shape for pictures.
struct Bins {
  int columns = 1, rows = 1;
  std::vector<double> counts;
};

// What a run drew: the binned counts, the points shown, and every binned
// sample with the u that drew it (for its own pdf).
struct Drawn {
  Bins bins;
  std::vector<double> shownX, shownY;
  std::vector<double> firstCounts;  // a mixture's samples the first strategy drew, per cell
  std::vector<Vec3> points;
  std::vector<Vec2> u;
  std::vector<int> cells;
};

// The run's settings, read once from the values.
struct Run {
  int n = 0, gridLines = 0;
  SampleSequence sequence = SampleSequence::Independent;
  uint64_t seed = 0;
};

// The pdf over the same bins, and what the test made of it.
struct Expected {
  std::vector<double> counts;
  std::vector<int> edges;  // cells on the edge of the pdf's support
  double total = 0.0;
  bool missingMass = false;  // the pdf integrates to less than 0.99: draws may return nothing
  bool fewLost = false;      // or no more draws returned nothing than the integration may miss
};

// Where a point is drawn: (x, y) of the scatter and the grid lines. The
// sphere is shown as its equal-area map: (phi, cos theta).
Vec2 shownAt(Domain domain, const Vec3& p, Vec2 u);
const char* sequenceName(SampleSequence sequence);

// The figure: samples, the warped grid, histogram, pdf, difference.
demo::Figure figureOf(const Warp& warp, const WarpSetup& setup, const Run& run, const Drawn& d, const Expected& e);

}  // namespace pathlab::lab
