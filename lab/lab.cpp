// The sampling lab's test and figure: draw, bin, integrate the pdf over the
// same bins, chi-square, and the five pictures (lab.h).
#include "lab.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "demo_support.h"
#include "util/error.h"
#include "util/image.h"
#include "util/output_file.h"
#include "util/random.h"

namespace pathlab::lab {

using demo::Figure;
using demo::format;
using demo::Plot;
using demo::Series;
using demo::Values;

namespace {

constexpr int kIntervalBins = 50;
constexpr int kPlaneCells = 40;      // per side
constexpr int kPlaneSubdivision = 32;  // midpoints per cell side for the expected counts (sharp edges)
constexpr int kShownPoints = 4000;    // points drawn in the scatter
constexpr double kPi = std::numbers::pi;

// Where a point is drawn: (x, y) of the scatter and the grid lines.
// The sphere is shown as its equal-area map: (phi, cos theta).
Vec2 shownAt(Domain domain, const Vec3& p, Vec2 u) {
  switch (domain) {
    case Domain::Interval: return {p.x, u.x};  // x against the u that made it: the inverse CDF
    case Domain::Plane: return {p.x, p.y};
    case Domain::Sphere: return {std::atan2(p.y, p.x), p.z};
    case Domain::Discrete: return {p.x, u.x};
  }
  return {0.0f, 0.0f};
}

// The bins of a domain: cell index of a point (-1: outside), the expected
// count of every cell for n samples, and the cells' shape for pictures.
struct Bins {
  int columns = 1, rows = 1;
  std::vector<double> counts;
};

int cellOf(Domain domain, const WarpSetup& setup, const Vec3& p) {
  switch (domain) {
    case Domain::Interval: {
      const double t = (double(p.x) - setup.lo.x) / (double(setup.hi.x) - setup.lo.x);
      if (!(t >= 0.0 && t <= 1.0)) return -1;
      return std::min(kIntervalBins - 1, int(t * kIntervalBins));
    }
    case Domain::Plane: {
      const double tx = (double(p.x) - setup.lo.x) / (double(setup.hi.x) - setup.lo.x);
      const double ty = (double(p.y) - setup.lo.y) / (double(setup.hi.y) - setup.lo.y);
      if (!(tx >= 0.0 && tx <= 1.0 && ty >= 0.0 && ty <= 1.0)) return -1;
      return std::min(kPlaneCells - 1, int(ty * kPlaneCells)) * kPlaneCells + std::min(kPlaneCells - 1, int(tx * kPlaneCells));
    }
    case Domain::Discrete: {
      const int k = int(p.x);
      return float(k) == p.x && k >= 0 && k < int(setup.outcomes.size()) ? k : -1;
    }
    case Domain::Sphere: return DirectionHistogram::cellOf(p);
  }
  return -1;
}

// The pdf integrated over every cell, times n (midpoint rule on a sub-grid).
// On the sphere, cells where the pdf varies or its support ends are
// integrated again, finer; `edges` gets the cells on that edge.
std::vector<double> expectedCounts(const WarpSetup& setup, double n, std::vector<int>* edges) {
  if (setup.expectedCounts) return setup.expectedCounts(n);
  switch (setup.domain) {
    case Domain::Sphere: {
      DirectionHistogram::Refinement refinement;
      std::vector<double> counts = DirectionHistogram::expectedRefined(
          setup.pdf, n, setup.sphereSubdivision, std::max(32, 2 * setup.sphereSubdivision), &refinement);
      *edges = std::move(refinement.edges);
      return counts;
    }
    case Domain::Discrete: {
      std::vector<Vec3> outcomes;
      for (size_t k = 0; k < setup.outcomes.size(); ++k) outcomes.emplace_back(float(k), 0.0f, 0.0f);
      std::vector<double> p = setup.pdf(outcomes);
      for (double& v : p) v *= n;
      return p;
    }
    case Domain::Interval: {
      constexpr int kSub = 64;
      const double width = (double(setup.hi.x) - setup.lo.x) / kIntervalBins;
      std::vector<Vec3> points;
      for (int b = 0; b < kIntervalBins; ++b)
        for (int s = 0; s < kSub; ++s) points.emplace_back(float(setup.lo.x + (b + (s + 0.5) / kSub) * width), 0.0f, 0.0f);
      const std::vector<double> pdf = setup.pdf(points);
      std::vector<double> result(kIntervalBins, 0.0);
      for (size_t i = 0; i < pdf.size(); ++i) result[i / kSub] += n * pdf[i] * width / kSub;
      return result;
    }
    case Domain::Plane: {
      const double w = (double(setup.hi.x) - setup.lo.x) / kPlaneCells, h = (double(setup.hi.y) - setup.lo.y) / kPlaneCells;
      std::vector<Vec3> points;
      for (int j = 0; j < kPlaneCells; ++j)
        for (int i = 0; i < kPlaneCells; ++i)
          for (int sj = 0; sj < kPlaneSubdivision; ++sj)
            for (int si = 0; si < kPlaneSubdivision; ++si)
              points.emplace_back(float(setup.lo.x + (i + (si + 0.5) / kPlaneSubdivision) * w),
                                  float(setup.lo.y + (j + (sj + 0.5) / kPlaneSubdivision) * h), 0.0f);
      const std::vector<double> pdf = setup.pdf(points);
      std::vector<double> result(kPlaneCells * kPlaneCells, 0.0);
      const size_t perCell = kPlaneSubdivision * kPlaneSubdivision;
      for (size_t i = 0; i < pdf.size(); ++i) result[i / perCell] += n * pdf[i] * w * h / double(perCell);
      return result;
    }
  }
  return {};
}

// Pixels per cell: about 200 pixels a side, whatever the cell count.
int pixelsPerCell(int cells) { return std::max(1, 200 / cells); }

// A density picture of a grid of cells (row 0 of `values` at the bottom of
// the picture, as the plots' y axes run): white 0 to dark blue `top`, on a
// log scale when `logScale` (a hot spot thousands of times the rest).
Image densityPicture(const std::vector<double>& values, int columns, int rows, double top, bool logScale) {
  const int kScale = pixelsPerCell(columns), kScaleY = pixelsPerCell(rows);
  Image image(columns * kScale, rows * kScaleY);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const double v = std::clamp(values[size_t(j * columns + i)] / std::max(top, 1e-300), 0.0, 1.0);
      const float t = float(logScale ? std::log1p(1e4 * v) / std::log1p(1e4) : v);
      const Color c = glm::mix(Color(1.0f), Color(0.02f, 0.06f, 0.35f), t);
      for (int y = 0; y < kScaleY; ++y)
        for (int x = 0; x < kScale; ++x) image.at(i * kScale + x, (rows - 1 - j) * kScaleY + y) = c;
    }
  return image;
}

// (observed - expected) / sqrt(expected): red too many, blue too few, full at |z| = 5.
Image differencePicture(const std::vector<double>& observed, const std::vector<double>& expected, int columns,
                        int rows) {
  std::vector<double> z(observed.size(), 0.0);
  for (size_t i = 0; i < z.size(); ++i) {
    z[i] = expected[i] > 0.0 ? (observed[i] - expected[i]) / std::sqrt(expected[i]) : (observed[i] > 0.0 ? 5.0 : 0.0);
  }
  const int kScale = pixelsPerCell(columns), kScaleY = pixelsPerCell(rows);
  Image image(columns * kScale, rows * kScaleY);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const float t = float(std::clamp(z[size_t(j * columns + i)] / 5.0, -1.0, 1.0));
      const Color c = t >= 0.0f ? glm::mix(Color(1.0f), Color(0.75f, 0.02f, 0.02f), t)
                                : glm::mix(Color(1.0f), Color(0.02f, 0.1f, 0.75f), -t);
      for (int y = 0; y < kScaleY; ++y)
        for (int x = 0; x < kScale; ++x) image.at(i * kScale + x, (rows - 1 - j) * kScaleY + y) = c;
    }
  return image;
}

Series imageSeries(Image image, std::string label) {
  Series s;
  s.kind = Series::Kind::Image;
  s.image = std::move(image);
  s.label = std::move(label);
  return s;
}

Series barsOf(std::vector<double> y, std::string label) {
  Series s;
  s.kind = Series::Kind::Bars;
  s.y = std::move(y);
  s.label = std::move(label);
  return s;
}

const char* sequenceName(SampleSequence sequence) {
  switch (sequence) {
    case SampleSequence::Independent: return "independent";
    case SampleSequence::Stratified: return "stratified";
    case SampleSequence::Sobol: return "Sobol";
  }
  return "?";
}

// The pdf the sampler reported with each drawn sample against pdf of its
// direction (drawnPdf), into result's pdf counts.
void compareReportedPdfs(const WarpSetup& setup, const std::vector<Vec2>& drawnU, const std::vector<double>& drawnPdf,
                         LabResult* result) {
  for (size_t k = 0; k < drawnU.size(); ++k) {
    const std::optional<double> reported = setup.reportedPdf(drawnU[k]);
    if (!reported) continue;
    ++result->pdfChecked;
    if (std::abs(drawnPdf[k] - *reported) <= kPdfAgreement * *reported && drawnPdf[k] > 0.0) continue;
    ++result->pdfDisagree;
    if (!(drawnPdf[k] > 0.0)) ++result->pdfReadsZero;
  }
}

}  // namespace

std::vector<demo::Parameter> parametersOf(const Warp& warp) {
  std::vector<demo::Parameter> parameters = {
      {"samples", 100000, 1000, 4e6, true, true, "points drawn"},
      {"sequence", 0, 0, 2, true, false, "the points' sequence (the test assumes independent)",
       {"independent", "stratified", "sobol"}},
      // Seed 3: with every default, each warp's reference sits far from the
      // rejection tail (smallest p 0.46; seed 1 gave the annulus p = 0.0005).
      // Any seed rejects a correct warp in 1 run in 1000 (docs/debugger.md).
      {"seed", 3, 0, 1e6, true, false, "random seed"},
      {"grid", 10, 2, 40, true, false, "lines per side of the warped grid"}};
  parameters.insert(parameters.end(), warp.parameters.begin(), warp.parameters.end());
  return parameters;
}

const Warp* findWarp(const std::string& name) {
  const std::vector<Warp>& warps = allWarps();
  const auto found = std::find_if(warps.begin(), warps.end(), [&](const Warp& w) { return w.name == name; });
  return found == warps.end() ? nullptr : &*found;
}

LabResult runWarp(const Warp& warp, const Values& values, const WarpFiles& files) {
  const WarpSetup setup = warp.setup(values, files);
  const int n = demo::count(values, "samples"), gridLines = demo::count(values, "grid");
  const auto sequence = SampleSequence(demo::count(values, "sequence"));
  const uint64_t seed = uint64_t(demo::count(values, "seed"));
  LabResult result;

  // Draw and bin.
  Bins bins;
  if (setup.domain == Domain::Interval) bins.columns = kIntervalBins;
  if (setup.domain == Domain::Plane) bins.columns = bins.rows = kPlaneCells;
  if (setup.domain == Domain::Discrete) bins.columns = int(setup.outcomes.size());
  if (setup.domain == Domain::Sphere) bins.columns = DirectionHistogram::kPhi, bins.rows = DirectionHistogram::kCos;
  bins.counts.assign(size_t(bins.columns * bins.rows), 0.0);
  std::vector<double> shownX, shownY;
  std::vector<double> firstCounts(bins.counts.size(), 0.0);  // a mixture's samples the first strategy drew
  std::vector<Vec3> drawn;  // every binned sample, for its own pdf
  std::vector<Vec2> drawnU;  // and the u that drew it
  std::vector<int> drawnCell;
  drawn.reserve(size_t(n)), drawnU.reserve(size_t(n)), drawnCell.reserve(size_t(n));
  for (int i = 0; i < n; ++i) {
    Sampler sampler(0, uint32_t(i), seed, sequence, uint32_t(n));
    const Vec2 u = sampler.next2D();
    const std::optional<Vec3> p = setup.sample(u);
    if (!p) {
      ++result.noSample;
      continue;
    }
    if (i < kShownPoints) {
      const Vec2 at = shownAt(setup.domain, *p, u);
      shownX.push_back(at.x), shownY.push_back(at.y);
    }
    const int cell = cellOf(setup.domain, setup, *p);
    if (cell < 0) {
      ++result.outside;
      continue;
    }
    bins.counts[size_t(cell)] += 1.0;
    if (setup.drawnByFirst && setup.drawnByFirst(u)) firstCounts[size_t(cell)] += 1.0;
    drawn.push_back(*p), drawnU.push_back(u), drawnCell.push_back(cell);
  }

  // The pdf over the same bins, and the test. A sample with no pdf to match
  // (none drawn, or outside the domain) fails it outright.
  std::vector<int> edges;
  const std::vector<double> expected = expectedCounts(setup, double(n), &edges);
  double total = 0.0;
  for (double e : expected) total += e;
  result.pdfIntegral = total / double(n);
  // A sample in a cell the pdf says holds nothing is a hard failure (as in
  // the suites) when the sample's own pdf is 0 there too. A cell whose
  // midpoints all missed a sharp edge of the pdf, hit by samples with a
  // positive pdf, is the integration's rounding: pooled with the sparse cells.
  const std::vector<double> drawnPdf = setup.pdf(drawn);
  if (setup.reportedPdf) compareReportedPdfs(setup, drawnU, drawnPdf, &result);
  int zeroPdf = 0;
  std::vector<double> tested = expected;
  for (size_t k = 0; k < drawn.size(); ++k) {
    const size_t cell = size_t(drawnCell[k]);
    if (expected[cell] > 0.0) continue;
    if (drawnPdf[k] > 0.0) {
      tested[cell] = 1e-12;
    } else {
      ++zeroPdf;
    }
  }
  // A sampler may return nothing (a BSDF sample reflected below the surface):
  // then its pdf integrates to less than 1 (by more than the 1 % the
  // integration may miss), and the draws that returned nothing are one more
  // cell, expected n (1 - the integral). Otherwise the draws that returned
  // nothing may be no more than that 1 % (a sharp lobe at a grazing angle
  // loses 1 draw in 10,000 below the surface).
  const bool missingMass = result.pdfIntegral < 0.99;
  const bool fewLost = double(result.noSample) <= std::max(0.0, 1.01 - result.pdfIntegral) * double(n);
  std::vector<double> observed = bins.counts;
  if (!edges.empty()) {
    // The cells on the edge of the pdf's support (a light's outline seen from
    // afar, a lobe cut by the horizon): no midpoint rule is accurate there,
    // so they are pooled with the draws that returned nothing, whose
    // expected total is n minus every other cell's.
    result.test = chiSquarePoolingEdges(observed, tested, double(result.noSample), double(n), edges);
  } else {
    if (missingMass) {
      observed.push_back(double(result.noSample));
      tested.push_back(double(n) - total);
    }
    result.test = chiSquareTest(observed, tested);
  }
  if (drawn.empty()) {
    result.test.failure = "no sample to test";
  } else if (zeroPdf > 0) {
    result.test.failure = format("%d samples landed where the pdf is 0 (their own pdf is 0 too)", zeroPdf);
  } else if (result.test.degreesOfFreedom < 1) {
    // Every sample in one cell, where the pdf puts all of it (a mirror, total
    // internal reflection, one lit pixel), or every one in the cells of the
    // support's edge, pooled (a light so far that it covers a few cells):
    // nothing more to test.
    result.test.failure.clear();
    result.test.pValue = 1.0;
  }
  if (result.outside > 0) result.test.failure = format("%d samples landed outside the domain", result.outside);
  if (result.pdfDisagree > 0) {
    result.test.failure = format("%d of %d samples have a pdf (read back from the direction) off the one sampled "
                                 "with it by more than %g%%, %d of them 0", result.pdfDisagree, result.pdfChecked,
                                 100.0 * kPdfAgreement, result.pdfReadsZero);
  }
  result.accepted = result.test.failure.empty() && result.test.pValue > kSignificance && result.pdfIntegral < 1.01 &&
                    (missingMass || fewLost);

  // The figure: samples, the warped grid, histogram, pdf, difference.
  const bool sphereMap = setup.domain == Domain::Sphere;
  const std::string xLabel = sphereMap ? "phi" : "x", yLabel = sphereMap ? "cos theta" : (setup.domain == Domain::Plane ? "y" : "u");
  Plot points{format("%d of %d samples (%s)", std::min(n, kShownPoints), n, sequenceName(sequence)), xLabel, yLabel,
              false, false, setup.domain == Domain::Plane, {}, {}};
  points.series.push_back(demo::scatter(shownX, shownY, ""));
  std::vector<Plot> plots = {points};
  if (setup.domain == Domain::Plane || setup.domain == Domain::Sphere) {
    // The lines u.x = const and u.y = const of the unit square, warped: a
    // fold-over or a seam shows as a line that crosses or jumps.
    Plot grid{"the unit square's grid, warped", xLabel, yLabel, false, false, setup.domain == Domain::Plane, {}, {}};
    constexpr int kSteps = 64;
    const float seamJump = 0.2f * glm::length(setup.hi - setup.lo);
    for (int along = 0; along < 2; ++along)
      for (int k = 0; k <= gridLines; ++k) {
        std::vector<double> xs, ys;
        auto flush = [&] {
          if (xs.size() > 1) grid.series.push_back(demo::line(xs, ys, ""));
          xs.clear(), ys.clear();
        };
        for (int s = 0; s <= kSteps; ++s) {
          const float a = std::min(float(k) / float(gridLines), 0.99999f), b = std::min(float(s) / kSteps, 0.99999f);
          const Vec2 u = along == 0 ? Vec2(a, b) : Vec2(b, a);
          const std::optional<Vec3> p = setup.sample(u);
          if (!p) {
            flush();
            continue;
          }
          const Vec2 at = shownAt(setup.domain, *p, u);
          // A seam: across phi = ±pi on the sphere, from one triangle of a light to the next in the plane.
          if (!xs.empty() && sphereMap && std::abs(at.x - xs.back()) > kPi) flush();
          if (!xs.empty() && !sphereMap && glm::length(Vec2(at.x - xs.back(), at.y - ys.back())) > seamJump) flush();
          xs.push_back(at.x), ys.push_back(at.y);
        }
        flush();
      }
    plots.push_back(grid);
    double top = 0.0;
    for (double e : expected) top = std::max(top, e);
    for (double o : bins.counts) top = std::max(top, 0.5 * o);  // a spike over the pdf still shows
    // A log scale where the pdf spans a wide range (a sun in the sky).
    std::vector<double> positive;
    for (double e : expected) if (e > 0.0) positive.push_back(e);
    std::nth_element(positive.begin(), positive.begin() + ptrdiff_t(positive.size() / 2), positive.end());
    const bool logScale = !positive.empty() && top > 20.0 * positive[positive.size() / 2];
    const std::string scale = logScale ? " (log scale)" : "";
    Plot observedPlot{"histogram of the samples" + scale, "", "", false, false, false, {}, {}};
    observedPlot.series.push_back(imageSeries(densityPicture(bins.counts, bins.columns, bins.rows, top, logScale), ""));
    Plot expectedPlot{"the pdf integrated over each cell" + scale, "", "", false, false, false, {}, {}};
    expectedPlot.series.push_back(imageSeries(densityPicture(expected, bins.columns, bins.rows, top, logScale), ""));
    Plot difference{"difference (red: too many, blue: too few; full at 5 sigma)", "", "", false, false, false, {}, {}};
    difference.series.push_back(imageSeries(differencePicture(bins.counts, expected, bins.columns, bins.rows), ""));
    plots.insert(plots.end(), {observedPlot, expectedPlot, difference});
    if (setup.drawnByFirst && setup.firstExpectedCounts && sphereMap) {
      // Where each sample came from: per cell, the first strategy's share of
      // the samples, and of the pdf (its weight by the balance heuristic).
      const std::vector<double> expectedFirst = setup.firstExpectedCounts(double(n));
      std::vector<double> observedShare(bins.counts.size(), 0.0), expectedShare(bins.counts.size(), 0.0);
      for (size_t i = 0; i < bins.counts.size(); ++i) {
        if (bins.counts[i] > 0.0) observedShare[i] = firstCounts[i] / bins.counts[i];
        if (expected[i] > 0.0) expectedShare[i] = std::clamp(expectedFirst[i] / expected[i], 0.0, 1.0);
      }
      Plot drawnShare{"share drawn by " + setup.firstName + " (white: all by " + setup.secondName + ")", "", "", false,
                      false, false, {}, {}};
      drawnShare.series.push_back(imageSeries(densityPicture(observedShare, bins.columns, bins.rows, 1.0, false), ""));
      Plot pdfShare{setup.firstName + "'s share of the pdf: its balance weight", "", "", false, false, false, {}, {}};
      pdfShare.series.push_back(imageSeries(densityPicture(expectedShare, bins.columns, bins.rows, 1.0, false), ""));
      plots.insert(plots.end(), {drawnShare, pdfShare});
    }
  } else {
    Plot compare{"observed against the integrated pdf", setup.domain == Domain::Discrete ? "outcome" : "x", "count",
                 false, false, false, {}, {}};
    if (setup.domain == Domain::Discrete) {
      compare.categories = setup.outcomes;
      compare.series = {barsOf(expected, "expected"), barsOf(bins.counts, "observed")};
    } else {
      const double width = (double(setup.hi.x) - setup.lo.x) / kIntervalBins;
      Series histogram;
      histogram.kind = Series::Kind::Histogram;
      histogram.label = "observed";
      histogram.x = demo::linspace(setup.lo.x, setup.hi.x, kIntervalBins + 1);
      histogram.y = bins.counts;
      std::vector<double> centres;
      for (int b = 0; b < kIntervalBins; ++b) centres.push_back(setup.lo.x + (b + 0.5) * width);
      compare.series = {histogram, demo::line(centres, expected, "the pdf, integrated over each bin")};
    }
    std::vector<double> z;
    for (size_t i = 0; i < expected.size(); ++i) {
      z.push_back(expected[i] > 0.0 ? (bins.counts[i] - expected[i]) / std::sqrt(expected[i]) : 0.0);
    }
    Plot difference{"(observed - expected) / sqrt(expected)", setup.domain == Domain::Discrete ? "outcome" : "bin",
                    "sigma", false, false, false, setup.domain == Domain::Discrete ? setup.outcomes : std::vector<std::string>{}, {}};
    difference.series.push_back(barsOf(z, ""));
    plots.insert(plots.end(), {compare, difference});
  }
  result.shown.figure = Figure{warp.name + " (" + warp.task + "): " + warp.summary, plots};

  // The numbers, and what a rejection usually means.
  std::ostringstream numbers;
  numbers << format("%s: %d samples (%s), seed %llu\n", warp.name.c_str(), n, sequenceName(sequence),
                    static_cast<unsigned long long>(seed));
  if (!setup.note.empty()) numbers << setup.note << "\n";
  numbers << format("pdf integrates to %.5f over the domain%s\n", result.pdfIntegral,
                    result.pdfIntegral >= 1.01 ? " (more than 1: the pdf is not normalised)"
                    : result.pdfIntegral > 0.99 ? "" : " (the rest is the chance of drawing no sample)");
  if (result.noSample > 0) {
    numbers << format("%d draws returned no sample (the pdf's missing mass predicts %.0f%s)\n", result.noSample,
                      std::max(0.0, 1.0 - result.pdfIntegral) * double(n),
                      missingMass ? ""
                      : fewLost   ? "; no more than the 1 % its integration may miss"
                                  : "; more than the 1 % its integration may miss");
  }
  if (result.pdfChecked > 0 && result.pdfDisagree == 0) {
    numbers << format("the pdf read back from each of %d directions agrees with the one sampled with it to %g%%\n",
                      result.pdfChecked, 100.0 * kPdfAgreement);
  }
  if (!result.test.failure.empty()) {
    numbers << "chi-square: " << result.test.failure << "\n";
  } else {
    numbers << (result.test.degreesOfFreedom < 1
                    ? std::string(edges.empty() ? "every sample in one cell, where the pdf puts all of it: nothing "
                                                  "more to test\n"
                                                : "every sample in the cells on the edge of the pdf's support, "
                                                  "pooled into one (a footprint this small is beyond the grid): "
                                                  "nothing more to test\n")
                    : format("chi-square %.1f with %d degrees of freedom (after pooling sparse cells): p = %.3g\n",
                             result.test.statistic, result.test.degreesOfFreedom, result.test.pValue));
  }
  numbers << (result.accepted ? "ACCEPTED" : "REJECTED")
          << format(": the samples %s the pdf (significance %g%s)\n", result.accepted ? "match" : "do not match",
                    kSignificance, sequence == SampleSequence::Independent ? "" : "; stratified or Sobol points are "
                    "more even than the test assumes, so it rejects less often");
  if (!result.accepted) numbers << "usually: " << setup.mismatchMeans << "\n";
  result.shown.numbers = numbers.str();

  // CSV: one line per cell (and a last line, cell -1, for the draws that
  // returned nothing, when the pdf says some must).
  std::ostringstream csv;
  csv << "cell,column,row,observed,expected\n";
  if (missingMass) csv << "-1,-1,-1," << result.noSample << "," << double(n) - total << "\n";
  for (size_t i = 0; i < expected.size(); ++i) {
    csv << i << "," << int(i) % bins.columns << "," << int(i) / bins.columns << "," << bins.counts[i] << ","
        << expected[i] << "\n";
  }
  result.csv = csv.str();
  return result;
}

}  // namespace pathlab::lab
