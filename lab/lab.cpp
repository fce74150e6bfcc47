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
#include "lab_run.h"
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

const char* sequenceName(SampleSequence sequence) {
  switch (sequence) {
    case SampleSequence::Independent: return "independent";
    case SampleSequence::Stratified: return "stratified";
    case SampleSequence::Sobol: return "Sobol";
  }
  return "?";
}

namespace {

constexpr int kPlaneCells = 40;        // per side
constexpr int kPlaneSubdivision = 32;  // midpoints per cell side for the expected counts (sharp edges)

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

Drawn drawAndBin(const WarpSetup& setup, const Run& run, LabResult& result) {
  Drawn d;
  Bins& bins = d.bins;
  if (setup.domain == Domain::Interval) bins.columns = kIntervalBins;
  if (setup.domain == Domain::Plane) bins.columns = bins.rows = kPlaneCells;
  if (setup.domain == Domain::Discrete) bins.columns = int(setup.outcomes.size());
  if (setup.domain == Domain::Sphere) bins.columns = DirectionHistogram::kPhi, bins.rows = DirectionHistogram::kCos;
  bins.counts.assign(size_t(bins.columns * bins.rows), 0.0);
  d.firstCounts.assign(bins.counts.size(), 0.0);
  d.points.reserve(size_t(run.n)), d.u.reserve(size_t(run.n)), d.cells.reserve(size_t(run.n));
  for (int i = 0; i < run.n; ++i) {
    Sampler sampler(0, uint32_t(i), run.seed, run.sequence, uint32_t(run.n));
    const Vec2 u = sampler.next2D();
    const std::optional<Vec3> p = setup.sample(u);
    if (!p) {
      ++result.noSample;
      continue;
    }
    if (i < kShownPoints) {
      const Vec2 at = shownAt(setup.domain, *p, u);
      d.shownX.push_back(at.x), d.shownY.push_back(at.y);
    }
    const int cell = cellOf(setup.domain, setup, *p);
    if (cell < 0) {
      ++result.outside;
      continue;
    }
    bins.counts[size_t(cell)] += 1.0;
    if (setup.drawnByFirst && setup.drawnByFirst(u)) d.firstCounts[size_t(cell)] += 1.0;
    d.points.push_back(*p), d.u.push_back(u), d.cells.push_back(cell);
  }
  return d;
}

// The chi-square test of the drawn counts against the pdf's, into result
// (with its verdict). A sample with no pdf to match (none drawn, or outside
// the domain) fails it outright.
Expected testAgainstPdf(const WarpSetup& setup, const Drawn& d, int n, LabResult& result) {
  Expected e;
  e.counts = expectedCounts(setup, double(n), &e.edges);
  for (double c : e.counts) e.total += c;
  result.pdfIntegral = e.total / double(n);
  // A sample in a cell the pdf says holds nothing is a hard failure (as in
  // the suites) when the sample's own pdf is 0 there too. A cell whose
  // midpoints all missed a sharp edge of the pdf, hit by samples with a
  // positive pdf, is the integration's rounding: pooled with the sparse cells.
  const std::vector<double> drawnPdf = setup.pdf(d.points);
  if (setup.reportedPdf) compareReportedPdfs(setup, d.u, drawnPdf, &result);
  int zeroPdf = 0;
  std::vector<double> tested = e.counts;
  for (size_t k = 0; k < d.points.size(); ++k) {
    const size_t cell = size_t(d.cells[k]);
    if (e.counts[cell] > 0.0) continue;
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
  e.missingMass = result.pdfIntegral < 0.99;
  e.fewLost = double(result.noSample) <= std::max(0.0, 1.01 - result.pdfIntegral) * double(n);
  std::vector<double> observed = d.bins.counts;
  if (!e.edges.empty()) {
    // The cells on the edge of the pdf's support (a light's outline seen from
    // afar, a lobe cut by the horizon): no midpoint rule is accurate there,
    // so they are pooled with the draws that returned nothing, whose
    // expected total is n minus every other cell's.
    result.test = chiSquarePoolingEdges(observed, tested, double(result.noSample), double(n), e.edges);
  } else {
    if (e.missingMass) {
      observed.push_back(double(result.noSample));
      tested.push_back(double(n) - e.total);
    }
    result.test = chiSquareTest(observed, tested);
  }
  if (d.points.empty()) {
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
                                 "with it by more than %g%%, %d of them 0",
                                 result.pdfDisagree, result.pdfChecked, 100.0 * kPdfAgreement, result.pdfReadsZero);
  }
  result.accepted = result.test.failure.empty() && result.test.pValue > kSignificance && result.pdfIntegral < 1.01 &&
                    (e.missingMass || e.fewLost);
  return e;
}

// The numbers, and what a rejection usually means.
std::string numbersOf(const Warp& warp, const WarpSetup& setup, const Run& run, const Expected& e,
                      const LabResult& result) {
  std::ostringstream numbers;
  numbers << format("%s: %d samples (%s), seed %llu\n", warp.name.c_str(), run.n, sequenceName(run.sequence),
                    static_cast<unsigned long long>(run.seed));
  if (!setup.note.empty()) numbers << setup.note << "\n";
  numbers << format("pdf integrates to %.5f over the domain%s\n", result.pdfIntegral,
                    result.pdfIntegral >= 1.01  ? " (more than 1: the pdf is not normalised)"
                    : result.pdfIntegral > 0.99 ? ""
                                                : " (the rest is the chance of drawing no sample)");
  if (result.noSample > 0) {
    numbers << format("%d draws returned no sample (the pdf's missing mass predicts %.0f%s)\n", result.noSample,
                      std::max(0.0, 1.0 - result.pdfIntegral) * double(run.n),
                      e.missingMass ? ""
                      : e.fewLost   ? "; no more than the 1 % its integration may miss"
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
                    ? std::string(e.edges.empty() ? "every sample in one cell, where the pdf puts all of it: nothing "
                                                    "more to test\n"
                                                  : "every sample in the cells on the edge of the pdf's support, "
                                                    "pooled into one (a footprint this small is beyond the grid): "
                                                    "nothing more to test\n")
                    : format("chi-square %.1f with %d degrees of freedom (after pooling sparse cells): p = %.3g\n",
                             result.test.statistic, result.test.degreesOfFreedom, result.test.pValue));
  }
  numbers << (result.accepted ? "ACCEPTED" : "REJECTED")
          << format(": the samples %s the pdf (significance %g%s)\n", result.accepted ? "match" : "do not match",
                    kSignificance,
                    run.sequence == SampleSequence::Independent
                        ? ""
                        : "; stratified or Sobol points are more even than the test assumes, so it rejects less often");
  if (!result.accepted) numbers << "usually: " << setup.mismatchMeans << "\n";
  return numbers.str();
}

// CSV: one line per cell (and a first line, cell -1, for the draws that
// returned nothing, when the pdf says some must).
std::string csvOf(const Drawn& d, const Expected& e, const LabResult& result, int n) {
  std::ostringstream csv;
  csv << "cell,column,row,observed,expected\n";
  if (e.missingMass) csv << "-1,-1,-1," << result.noSample << "," << double(n) - e.total << "\n";
  for (size_t i = 0; i < e.counts.size(); ++i) {
    csv << i << "," << int(i) % d.bins.columns << "," << int(i) / d.bins.columns << "," << d.bins.counts[i] << ","
        << e.counts[i] << "\n";
  }
  return csv.str();
}

}  // namespace

std::vector<demo::Parameter> parametersOf(const Warp& warp) {
  std::vector<demo::Parameter> parameters = {{"samples", 100000, 1000, 4e6, true, true, "points drawn"},
                                             {"sequence",
                                              0,
                                              0,
                                              2,
                                              true,
                                              false,
                                              "the points' sequence (the test assumes independent)",
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
  Run run;
  run.n = demo::count(values, "samples"), run.gridLines = demo::count(values, "grid");
  run.sequence = SampleSequence(demo::count(values, "sequence"));
  run.seed = uint64_t(demo::count(values, "seed"));
  LabResult result;
  const Drawn drawn = drawAndBin(setup, run, result);
  const Expected expected = testAgainstPdf(setup, drawn, run.n, result);
  result.shown.figure = figureOf(warp, setup, run, drawn, expected);
  result.shown.numbers = numbersOf(warp, setup, run, expected, result);
  result.csv = csvOf(drawn, expected, result, run.n);
  return result;
}
}  // namespace pathlab::lab
