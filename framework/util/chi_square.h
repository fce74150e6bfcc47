// Pearson's chi-square goodness-of-fit test, with pooling of sparse cells
// (as Mitsuba 3 and pbrt-v4 test their samplers), and the histogram of unit
// directions it is used on. One copy for everyone who asks "does this
// sampler draw what its pdf says?": the task suites (tests/support/
// statistics.h), the sampling lab (pathlab lab, the GUI's lab panel) and the
// lecture demos, so that the lab and the grade can never disagree.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "util/math.h"

namespace pathlab {

// Regularised upper incomplete gamma Q(a, x) (Numerical Recipes 6.2).
inline double upperIncompleteGamma(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double lnGammaA = std::lgamma(a);
  if (x < a + 1.0) {  // series for P, then Q = 1 - P
    double sum = 1.0 / a, term = sum;
    for (int n = 1; n < 10000; ++n) {
      term *= x / (a + n);
      sum += term;
      if (std::abs(term) < std::abs(sum) * 1e-15) break;
    }
    return 1.0 - sum * std::exp(-x + a * std::log(x) - lnGammaA);
  }
  // Continued fraction for Q (modified Lentz).
  double b = x + 1.0 - a, c = 1.0 / 1e-300, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < 1e-300) d = 1e-300;
    c = b + an / c;
    if (std::abs(c) < 1e-300) c = 1e-300;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - lnGammaA) * h;
}

struct ChiSquareResult {
  double statistic = 0.0;
  int degreesOfFreedom = 0;
  double pValue = 0.0;
  std::string failure;   // a hard failure before any statistics, or ""
  std::string pictures;  // where it failed, drawn (the suites' failure pictures), or ""
};

// Pearson's test of observed counts against expected counts. Cells with an
// expected count below 5 are pooled (sorted by expectation) until each group
// reaches 5. Any observation in a cell whose expectation is 0 fails outright.
inline ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected) {
  ChiSquareResult r;
  std::vector<size_t> order(observed.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
  double pooledObserved = 0.0, pooledExpected = 0.0;
  int groups = 0;
  for (size_t i : order) {
    if (expected[i] == 0.0 && observed[i] > 0.0) {
      r.failure = "a sample landed in a cell where the pdf is zero";
      return r;
    }
    if (expected[i] < 5.0) {
      pooledObserved += observed[i];
      pooledExpected += expected[i];
      if (pooledExpected >= 5.0) {
        r.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++groups;
        pooledObserved = pooledExpected = 0.0;
      }
      continue;
    }
    r.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++groups;
  }
  if (pooledExpected > 0.0) {
    r.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / std::max(pooledExpected, 1e-12);
    ++groups;
  }
  r.degreesOfFreedom = groups - 1;
  if (r.degreesOfFreedom < 1) {
    r.failure = "fewer than one degree of freedom";
    return r;
  }
  r.pValue = upperIncompleteGamma(0.5 * r.degreesOfFreedom, 0.5 * r.statistic);
  return r;
}

// Pearson's test of per-cell counts and of the draws that returned nothing
// (`nothing` of `samples` in all), with the cells in `edges` (sorted, as
// DirectionHistogram::Refinement gives them) pooled with those draws: their
// expected total is `samples` minus every other cell's expected count,
// exact however the quadrature resolved them (the cells on the edge of a
// pdf's support).
inline ChiSquareResult chiSquarePoolingEdges(const std::vector<double>& observed, const std::vector<double>& expected,
                                             double nothing, double samples, const std::vector<int>& edges) {
  std::vector<double> inside, insideExpected;
  double rest = nothing, restExpected = samples;
  for (size_t cell = 0; cell < observed.size(); ++cell) {
    if (std::binary_search(edges.begin(), edges.end(), int(cell))) {
      rest += observed[cell];
      continue;
    }
    inside.push_back(observed[cell]);
    insideExpected.push_back(expected[cell]);
    restExpected -= expected[cell];
  }
  inside.push_back(rest);
  insideExpected.push_back(std::max(0.0, restExpected));
  return chiSquareTest(inside, insideExpected);
}

// Histogram of unit directions over the equal-area map (phi in [-pi, pi],
// cos(theta) in [-1, 1]), and the counts a solid-angle pdf predicts for
// `samples` draws: per cell, the midpoint rule on a sub-grid in
// (phi, theta) of pdf * sin(theta) — smooth even for pdfs that grow like
// 1 / sin(theta) at the poles, as equirectangular maps' do.
struct DirectionHistogram {
  static constexpr int kPhi = 50, kCos = 101;  // odd: no cell edge on the horizon
  std::vector<double> counts = std::vector<double>(kPhi * kCos, 0.0);
  int outside = 0;

  // The cell of a unit direction (row j of cos theta, column i of phi: j * kPhi + i); -1 for a vector that is not unit.
  static int cellOf(const Vec3& w) {
    if (!(std::abs(glm::length(w) - 1.0f) < 1e-3f)) return -1;
    const double phi = std::atan2(double(w.y), double(w.x));
    const int i = std::clamp(int((phi + std::numbers::pi) / (2.0 * std::numbers::pi) * kPhi), 0, kPhi - 1);
    const int j = std::clamp(int((double(w.z) + 1.0) * 0.5 * kCos), 0, kCos - 1);
    return j * kPhi + i;
  }

  void add(const Vec3& w) {
    const int cell = cellOf(w);
    if (cell < 0) {
      ++outside;
      return;
    }
    counts[size_t(cell)] += 1.0;
  }

  // The solid-angle pdf at many directions at once (a remote call evaluates
  // the student's pdf for all of them in one message).
  using PdfBatch = std::function<std::vector<double>(const std::vector<Vec3>&)>;

  // The sub-grid midpoints of cell (column i, row j), sub per side, each with
  // its sin(theta); returns the midpoints' spacing in theta. The cell's z range
  // [z0, z1] is the theta range [acos(z1), acos(z0)].
  static double cellMidpoints(int i, int j, int sub, std::vector<Vec3>& directions, std::vector<double>& sines) {
    const double dPhi = 2.0 * std::numbers::pi / kPhi, dCos = 2.0 / kCos;
    const double theta0 = std::acos(std::min(1.0, -1.0 + (j + 1) * dCos));
    const double theta1 = std::acos(std::max(-1.0, -1.0 + j * dCos));
    const double dTheta = (theta1 - theta0) / sub;
    for (int sj = 0; sj < sub; ++sj)
      for (int si = 0; si < sub; ++si) {
        const double phi = -std::numbers::pi + (i + (si + 0.5) / sub) * dPhi;
        const double theta = theta0 + (sj + 0.5) * dTheta;
        const double r = std::sin(theta);
        directions.emplace_back(float(r * std::cos(phi)), float(r * std::sin(phi)), float(std::cos(theta)));
        sines.push_back(r);
      }
    return dTheta;
  }

  // The midpoint rule over the given cells (index j * kPhi + i), sub per side:
  // samples times the pdf's integral over each; `varies` (if given) collects
  // the cells where the pdf varies by more than a factor 2 (or is 0 beside a
  // value that is not), `edges` those where it is 0 beside a value that is
  // not (the edge of the pdf's support crosses them).
  // The pdf is asked for at most this many directions at once: 32 x 32
  // points in each of the 5,050 cells are 5.2 million, which held at once
  // (with their remote call's messages) took 800 MB.
  static constexpr size_t kDirectionsPerBatch = size_t(1) << 17;

  static std::vector<double> integrateCells(const PdfBatch& pdfs, double samples, const std::vector<int>& cells, int sub,
                                            std::vector<int>* varies = nullptr, std::vector<int>* edges = nullptr) {
    const double dPhi = 2.0 * std::numbers::pi / kPhi;
    const size_t perCell = size_t(sub) * size_t(sub);
    const size_t cellsPerBatch = std::max<size_t>(1, kDirectionsPerBatch / perCell);
    std::vector<double> result(cells.size(), 0.0);
    std::vector<Vec3> directions;
    std::vector<double> sines;
    for (size_t first = 0; first < cells.size(); first += cellsPerBatch) {
      const size_t last = std::min(cells.size(), first + cellsPerBatch);
      directions.clear();
      sines.clear();
      std::vector<double> dThetas;
      for (size_t c = first; c < last; ++c) {
        dThetas.push_back(cellMidpoints(cells[c] % kPhi, cells[c] / kPhi, sub, directions, sines));
      }
      const std::vector<double> pdf = pdfs(directions);
      if (pdf.size() != directions.size()) throw std::length_error("a pdf batch answered the wrong number of directions");
      size_t k = 0;
      for (size_t c = first; c < last; ++c) {
        double integral = 0.0, lo = INFINITY, hi = 0.0;
        for (size_t s = 0; s < perCell; ++s, ++k) {
          integral += pdf[k] * sines[k];
          lo = std::min(lo, pdf[k]), hi = std::max(hi, pdf[k]);
        }
        result[c] = samples * integral * (dPhi / sub) * dThetas[c - first];
        if (varies && hi > 0.0 && hi > 2.0 * lo) varies->push_back(cells[c]);
        if (edges && hi > 0.0 && lo == 0.0) edges->push_back(cells[c]);
      }
    }
    return result;
  }

  // kSub = 32 for piecewise-constant pdfs (environment maps), as Mitsuba does.
  static std::vector<double> expected(const PdfBatch& pdfs, double samples, int kSub = 8) {
    std::vector<int> all(kPhi * kCos);
    std::iota(all.begin(), all.end(), 0);
    return integrateCells(pdfs, samples, all, kSub);
  }

  // What expectedRefined found (when asked): how much refining moved the
  // cells it refined (the sum of |fine - coarse|, in samples: the coarse
  // rule's error there, and more than the fine rule's, whose error across a
  // jump is kSub / kFine of it), and the cells on the edge of the pdf's
  // support: 0 at some midpoints and not at others, or beside a cell on the
  // other side of the edge. It refines those too, but no midpoint rule is
  // accurate there (a pdf that jumps at the edge, such as a uniform lobe's
  // at the horizon, can put many samples in a sliver between midpoints): a
  // chi-square can pool them, whose total it knows without them.
  struct Refinement {
    double change = 0.0;
    std::vector<int> edges;
  };

  // As expected(), then again with kFine midpoints per side in the cells
  // where the pdf varies by more than a factor 2 and on its support's edge:
  // a lobe a few thousandths of a radian wide (GGX at roughness 0.08) is
  // integrated finely, and the flat cells cost no more.
  static std::vector<double> expectedRefined(const PdfBatch& pdfs, double samples, int kSub, int kFine,
                                             Refinement* refinement = nullptr) {
    std::vector<int> all(kPhi * kCos), varying, split;
    std::iota(all.begin(), all.end(), 0);
    std::vector<double> result = integrateCells(pdfs, samples, all, kSub, &varying, &split);
    std::vector<int> edges = split;
    for (int j = 0; j < kCos; ++j)
      for (int i = 0; i < kPhi; ++i) {
        const bool inside = result[size_t(j * kPhi + i)] > 0.0;
        bool across = false;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const int jj = j + dj, ii = (i + di + kPhi) % kPhi;
            across |= jj >= 0 && jj < kCos && (result[size_t(jj * kPhi + ii)] > 0.0) != inside;
          }
        if (across) edges.push_back(j * kPhi + i);
      }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::vector<int> refine = varying;
    refine.insert(refine.end(), edges.begin(), edges.end());
    std::sort(refine.begin(), refine.end());
    refine.erase(std::unique(refine.begin(), refine.end()), refine.end());
    const std::vector<double> fine = integrateCells(pdfs, samples, refine, kFine);
    double change = 0.0;
    for (size_t c = 0; c < refine.size(); ++c) {
      change += std::abs(fine[c] - result[size_t(refine[c])]);
      result[size_t(refine[c])] = fine[c];
    }
    if (refinement) *refinement = Refinement{change, std::move(edges)};
    return result;
  }
};

}  // namespace pathlab
