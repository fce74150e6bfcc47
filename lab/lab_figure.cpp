// The sampling lab's figure of a run (lab_run.h): the samples, the unit
// square's grid warped, and the counts against the pdf's, as pictures on the
// plane and the sphere, as bars on an interval or a discrete set.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "demo_support.h"
#include "lab_run.h"

namespace pathlab::lab {

using demo::Figure;
using demo::format;
using demo::Plot;
using demo::Series;

namespace {

constexpr double kPi = std::numbers::pi;

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

// A plot with a title and axis labels, nothing on a log scale.
Plot titled(std::string title, std::string xlabel = "", std::string ylabel = "", bool equalAspect = false) {
  Plot plot;
  plot.title = std::move(title), plot.xlabel = std::move(xlabel), plot.ylabel = std::move(ylabel);
  plot.equalAspect = equalAspect;
  return plot;
}

// The lines u.x = const and u.y = const of the unit square, warped: a
// fold-over or a seam shows as a line that crosses or jumps.
Plot warpedGrid(const WarpSetup& setup, int gridLines, const std::string& xLabel, const std::string& yLabel) {
  const bool sphereMap = setup.domain == Domain::Sphere;
  Plot grid = titled("the unit square's grid, warped", xLabel, yLabel, setup.domain == Domain::Plane);
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
  return grid;
}

// On the plane and the sphere: the histogram, the pdf per cell and their
// difference as pictures, and for a mixture where each sample came from.
std::vector<Plot> cellPictures(const WarpSetup& setup, const Drawn& d, const Expected& e, int n) {
  const Bins& bins = d.bins;
  double top = 0.0;
  for (double c : e.counts) top = std::max(top, c);
  for (double o : bins.counts) top = std::max(top, 0.5 * o);  // a spike over the pdf still shows
  // A log scale where the pdf spans a wide range (a sun in the sky).
  std::vector<double> positive;
  for (double c : e.counts)
    if (c > 0.0) positive.push_back(c);
  std::nth_element(positive.begin(), positive.begin() + ptrdiff_t(positive.size() / 2), positive.end());
  const bool logScale = !positive.empty() && top > 20.0 * positive[positive.size() / 2];
  const std::string scale = logScale ? " (log scale)" : "";
  Plot observedPlot = titled("histogram of the samples" + scale);
  observedPlot.series.push_back(imageSeries(densityPicture(bins.counts, bins.columns, bins.rows, top, logScale), ""));
  Plot expectedPlot = titled("the pdf integrated over each cell" + scale);
  expectedPlot.series.push_back(imageSeries(densityPicture(e.counts, bins.columns, bins.rows, top, logScale), ""));
  Plot difference = titled("difference (red: too many, blue: too few; full at 5 sigma)");
  difference.series.push_back(imageSeries(differencePicture(bins.counts, e.counts, bins.columns, bins.rows), ""));
  std::vector<Plot> plots = {observedPlot, expectedPlot, difference};
  if (setup.drawnByFirst && setup.firstExpectedCounts && setup.domain == Domain::Sphere) {
    // Where each sample came from: per cell, the first strategy's share of
    // the samples, and of the pdf (its weight by the balance heuristic).
    const std::vector<double> expectedFirst = setup.firstExpectedCounts(double(n));
    std::vector<double> observedShare(bins.counts.size(), 0.0), expectedShare(bins.counts.size(), 0.0);
    for (size_t i = 0; i < bins.counts.size(); ++i) {
      if (bins.counts[i] > 0.0) observedShare[i] = d.firstCounts[i] / bins.counts[i];
      if (e.counts[i] > 0.0) expectedShare[i] = std::clamp(expectedFirst[i] / e.counts[i], 0.0, 1.0);
    }
    Plot drawnShare = titled("share drawn by " + setup.firstName + " (white: all by " + setup.secondName + ")");
    drawnShare.series.push_back(imageSeries(densityPicture(observedShare, bins.columns, bins.rows, 1.0, false), ""));
    Plot pdfShare = titled(setup.firstName + "'s share of the pdf: its balance weight");
    pdfShare.series.push_back(imageSeries(densityPicture(expectedShare, bins.columns, bins.rows, 1.0, false), ""));
    plots.insert(plots.end(), {drawnShare, pdfShare});
  }
  return plots;
}

// On an interval or a discrete set: the counts against the pdf's, and the
// difference in standard deviations.
std::vector<Plot> countPlots(const WarpSetup& setup, const Drawn& d, const Expected& e) {
  const bool discrete = setup.domain == Domain::Discrete;
  Plot compare = titled("observed against the integrated pdf", discrete ? "outcome" : "x", "count");
  if (discrete) {
    compare.categories = setup.outcomes;
    compare.series = {barsOf(e.counts, "expected"), barsOf(d.bins.counts, "observed")};
  } else {
    const double width = (double(setup.hi.x) - setup.lo.x) / kIntervalBins;
    Series histogram;
    histogram.kind = Series::Kind::Histogram;
    histogram.label = "observed";
    histogram.x = demo::linspace(setup.lo.x, setup.hi.x, kIntervalBins + 1);
    histogram.y = d.bins.counts;
    std::vector<double> centres;
    for (int b = 0; b < kIntervalBins; ++b) centres.push_back(setup.lo.x + (b + 0.5) * width);
    compare.series = {histogram, demo::line(centres, e.counts, "the pdf, integrated over each bin")};
  }
  std::vector<double> z;
  for (size_t i = 0; i < e.counts.size(); ++i) {
    z.push_back(e.counts[i] > 0.0 ? (d.bins.counts[i] - e.counts[i]) / std::sqrt(e.counts[i]) : 0.0);
  }
  Plot difference = titled("(observed - expected) / sqrt(expected)", discrete ? "outcome" : "bin", "sigma");
  if (discrete) difference.categories = setup.outcomes;
  difference.series.push_back(barsOf(z, ""));
  return {compare, difference};
}

}  // namespace

// The figure: samples, the warped grid, histogram, pdf, difference.
Figure figureOf(const Warp& warp, const WarpSetup& setup, const Run& run, const Drawn& d, const Expected& e) {
  const bool sphereMap = setup.domain == Domain::Sphere;
  const std::string xLabel = sphereMap ? "phi" : "x";
  const std::string yLabel = sphereMap ? "cos theta" : (setup.domain == Domain::Plane ? "y" : "u");
  Plot points =
      titled(format("%d of %d samples (%s)", std::min(run.n, kShownPoints), run.n, sequenceName(run.sequence)), xLabel,
             yLabel, setup.domain == Domain::Plane);
  points.series.push_back(demo::scatter(d.shownX, d.shownY, ""));
  std::vector<Plot> plots = {points};
  if (setup.domain == Domain::Plane || sphereMap) {
    plots.push_back(warpedGrid(setup, run.gridLines, xLabel, yLabel));
    for (Plot& plot : cellPictures(setup, d, e, run.n)) plots.push_back(std::move(plot));
  } else {
    for (Plot& plot : countPlots(setup, d, e)) plots.push_back(std::move(plot));
  }
  return Figure{warp.name + " (" + warp.task + "): " + warp.summary, plots};
}

}  // namespace pathlab::lab
