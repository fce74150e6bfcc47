// Demos 1-5: inversion sampling (continuous and discrete), the annulus,
// the hemisphere, and Monte Carlo estimation of pi.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "demo_support.h"

namespace pathlab::demo {

// ---- 1. pdf and cdf ----------------------------------------------------------

double examplePdf(double x) { return 0.6 * std::pow(x - 1.0, 3) - 0.3 * x * x - 0.1 * x + 1.0; }

double exampleCdf(double x) { return 3.0 / 20.0 * std::pow(x, 4) - 0.7 * x * x * x + 17.0 / 20.0 * x * x + 0.4 * x; }

double invertExampleCdf(double u, int* iterations, bool* usedBisection, double start) {
  double lo = 0.0, hi = 2.0, x = start >= 0.0 ? start : 2.0 * u;  // F is close to linear: 2u is a good first guess
  bool bisected = false;
  int step = 0;
  for (; step < 100; ++step) {
    const double residual = exampleCdf(x) - u;
    if (std::abs(residual) < 1e-13) break;
    (residual < 0.0 ? lo : hi) = x;  // F is increasing: the root stays in [lo, hi]
    if (hi - lo < 1e-15) break;
    double next = x - residual / examplePdf(x);  // Newton: F'(x) = f(x)
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);  // Newton left the bracket: bisect instead
      bisected = true;
    }
    x = next;
  }
  if (iterations) *iterations = step;
  if (usedBisection) *usedBisection = bisected;
  return x;
}

Demo pdfCdfDemo() {
  Demo demo;
  demo.name = "pdf-cdf";
  demo.summary = "inversion sampling of f(x) = 0.6(x-1)^3 - 0.3x^2 - 0.1x + 1 on [0, 2]: histogram over the pdf";
  demo.parameters = {{"samples", 100000, 100, 1e7, true, true, "samples drawn"},
                     {"bins", 50, 5, 200, true, false, "histogram bins"},
                     {"seed", 1, 0, 1000, true, false, "random seed"}};
  demo.run = [](const Values& p) {
    const int n = count(p, "samples"), bins = count(p, "bins");
    Uniform uniform(uint64_t(count(p, "seed")));
    std::vector<double> xs(static_cast<size_t>(n));
    long totalIterations = 0;
    int bisections = 0, worst = 0;
    double mean = 0.0;
    for (double& x : xs) {
      int iterations = 0;
      bool bisected = false;
      x = invertExampleCdf(uniform(), &iterations, &bisected);
      totalIterations += iterations;
      bisections += bisected;
      worst = std::max(worst, iterations);
      mean += x / n;
    }
    Plot histogram{"samples x = F^-1(u) against the pdf", "x", "density", false, false, false, {}, {}};
    histogram.series.push_back(densityHistogram(xs, 0.0, 2.0, bins, "histogram of samples"));
    const std::vector<double> grid = linspace(0.0, 2.0, 200);
    std::vector<double> pdf, cdf;
    for (double x : grid) pdf.push_back(examplePdf(x)), cdf.push_back(exampleCdf(x));
    histogram.series.push_back(line(grid, pdf, "f(x)"));

    Plot inversion{"inversion: u on the y axis -> x = F^-1(u)", "x", "u = F(x)", false, false, false, {}, {}};
    inversion.series.push_back(line(grid, cdf, "F(x) = 3/20 x^4 - 7/10 x^3 + 17/20 x^2 + 4/10 x"));
    for (double u : {0.1, 0.3, 0.5, 0.7, 0.9}) {
      const double x = invertExampleCdf(u);
      inversion.series.push_back(line({0.0, x, x}, {u, u, 0.0}, "", true));
    }

    // Chi-square over the bins: expected counts from the CDF.
    std::vector<double> observed(static_cast<size_t>(bins), 0.0), expected(static_cast<size_t>(bins), 0.0);
    for (double x : xs) observed[size_t(std::min(bins - 1, int(x / 2.0 * bins)))] += 1.0;
    for (int i = 0; i < bins; ++i) expected[size_t(i)] = n * (exampleCdf(2.0 * (i + 1) / bins) - exampleCdf(2.0 * i / bins));
    DemoResult result;
    result.figure = {"Inversion sampling: F(x) = u solved by Newton's method with a bisection fallback",
                     {histogram, inversion}};
    result.numbers = format("samples: %d\n", n) +
                     format("integral of f over [0, 2]: F(2) = %.12f\n", exampleCdf(2.0)) +
                     format("Newton steps per sample: mean %.2f, max %d; bisection fallbacks: %d\n",
                            double(totalIterations) / n, worst, bisections) +
                     format("sample mean %.5f, exact mean 0.77333 (integral of x f(x))\n", mean) +
                     format("chi-square %.1f with %d degrees of freedom (expected about %d)\n",
                            chiSquare(observed, expected), bins - 1, bins - 1);
    return result;
  };
  return demo;
}

// ---- 2. discrete inversion -------------------------------------------------------

size_t sampleDiscrete(const std::vector<double>& cdf, double u) {
  // Binary search: the first block whose top is above u.
  return size_t(std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin());
}

Demo discreteDemo() {
  Demo demo;
  demo.name = "discrete";
  demo.summary = "discrete inversion: a PMF stacked into CDF blocks, binary search, observed vs expected";
  demo.parameters = {{"samples", 10000, 10, 1e7, true, true, "samples drawn"},
                     {"seed", 1, 0, 1000, true, false, "random seed"}};
  demo.run = [](const Values& p) {
    const std::vector<double> pmf = {0.1, 0.25, 0.05, 0.3, 0.2, 0.1};
    std::vector<double> cdf;
    double total = 0.0;
    for (double q : pmf) cdf.push_back(total += q);
    cdf.back() = 1.0;  // exactly 1, so u in [0, 1) always lands in a block
    const int n = count(p, "samples");
    Uniform uniform(uint64_t(count(p, "seed")));
    std::vector<double> observed(pmf.size(), 0.0), expected;
    std::vector<double> shownU, shownIndex;
    for (int i = 0; i < n; ++i) {
      const double u = uniform();
      const size_t k = sampleDiscrete(cdf, u);
      observed[k] += 1.0;
      if (i < 300) shownU.push_back(u), shownIndex.push_back(double(k));
    }
    for (double q : pmf) expected.push_back(q * n);

    Plot blocks{"CDF as stacked blocks: u picks the block it falls in", "outcome i", "u", false, false, false, {}, {}};
    for (size_t k = 0; k < pmf.size(); ++k) {
      const double bottom = k == 0 ? 0.0 : cdf[k - 1];
      const double x0 = double(k) - 0.4, x1 = double(k) + 0.4;
      blocks.series.push_back(line({x0, x1, x1, x0, x0}, {bottom, bottom, cdf[k], cdf[k], bottom},
                                   format("block %zu: [%.2f, %.2f)", k, bottom, cdf[k])));
    }
    blocks.series.push_back(scatter(shownIndex, shownU, "first 300 draws"));

    Plot frequencies{"observed against expected", "outcome i", "count", false, false, false, {}, {}};
    for (size_t k = 0; k < pmf.size(); ++k) frequencies.categories.push_back(std::to_string(k));
    Series expectedBars, observedBars;
    expectedBars.kind = observedBars.kind = Series::Kind::Bars;
    expectedBars.label = "expected n p_i";
    expectedBars.y = expected;
    observedBars.label = "observed";
    observedBars.y = observed;
    frequencies.series = {expectedBars, observedBars};

    DemoResult result;
    result.figure = {"Discrete inversion (\"stacking blocks\")", {blocks, frequencies}};
    result.numbers = format("PMF 0.10 0.25 0.05 0.30 0.20 0.10, %d samples\n", n);
    for (size_t k = 0; k < pmf.size(); ++k) {
      result.numbers += format("  outcome %zu: observed %.0f, expected %.1f\n", k, observed[k], expected[k]);
    }
    result.numbers += format("chi-square %.2f with %zu degrees of freedom (5%% critical value 11.07)\n",
                             chiSquare(observed, expected), pmf.size() - 1);
    result.numbers += format("binary search: at most %d comparisons for %zu outcomes\n",
                             int(std::ceil(std::log2(double(pmf.size())))) + 1, pmf.size());
    return result;
  };
  return demo;
}

// ---- 3. annulus ---------------------------------------------------------------------

Demo annulusDemo() {
  Demo demo;
  demo.name = "annulus";
  demo.summary = "uniform points in an annulus: r = sqrt(q r2^2 + (1-q) r1^2) against the naive r = r1 + q (r2 - r1)";
  demo.parameters = {{"r1", 0.3, 0.0, 0.95, false, false, "inner radius"},
                     {"r2", 1.0, 0.1, 1.0, false, false, "outer radius"},
                     {"points", 3000, 100, 50000, true, true, "points drawn in each scatter"},
                     {"seed", 1, 0, 1000, true, false, "random seed"}};
  demo.run = [](const Values& p) {
    const double r2 = p.at("r2"), r1 = std::min(p.at("r1"), 0.95 * r2);
    const int n = count(p, "points");
    constexpr int kRings = 10, kDensitySamples = 200000;
    auto correct = [&](double q) { return std::sqrt(q * r2 * r2 + (1.0 - q) * r1 * r1); };
    auto naive = [&](double q) { return r1 + q * (r2 - r1); };
    Uniform uniform(uint64_t(count(p, "seed")));
    auto scatterOf = [&](auto radius, const char* title) {
      std::vector<double> xs, ys;
      for (int i = 0; i < n; ++i) {
        const double r = radius(uniform()), phi = 2.0 * std::numbers::pi * uniform();
        xs.push_back(r * std::cos(phi)), ys.push_back(r * std::sin(phi));
      }
      Plot plot{title, "x", "y", false, false, true, {}, {}};
      plot.series.push_back(scatter(xs, ys, ""));
      return plot;
    };
    // Density per ring relative to uniform: count / (expected count for the ring's area).
    auto ringDensity = [&](auto radius) {
      std::vector<double> counts(kRings, 0.0);
      for (int i = 0; i < kDensitySamples; ++i) {
        const int ring = std::min(kRings - 1, int((radius(uniform()) - r1) / (r2 - r1) * kRings));
        counts[size_t(ring)] += 1.0;
      }
      std::vector<double> density;
      for (int k = 0; k < kRings; ++k) {
        const double a = r1 + (r2 - r1) * k / kRings, b = r1 + (r2 - r1) * (k + 1) / kRings;
        density.push_back(counts[size_t(k)] / (kDensitySamples * (b * b - a * a) / (r2 * r2 - r1 * r1)));
      }
      return density;
    };
    std::vector<double> ringCentres;
    for (int k = 0; k < kRings; ++k) ringCentres.push_back(r1 + (r2 - r1) * (k + 0.5) / kRings);
    const std::vector<double> good = ringDensity(correct), bad = ringDensity(naive);
    Plot density{"points per unit area, per ring (1 = uniform)", "radius", "density / uniform", false, false, false, {}, {}};
    density.series.push_back(line(ringCentres, good, "r = sqrt(q r2^2 + (1-q) r1^2)"));
    density.series.push_back(line(ringCentres, bad, "r = r1 + q (r2 - r1)"));
    density.series.push_back(line({r1, r2}, {1.0, 1.0}, "uniform", true));

    DemoResult result;
    result.figure = {"Uniform sampling of an annulus",
                     {scatterOf(correct, "r = sqrt(q r2^2 + (1-q) r1^2): uniform"),
                      scatterOf(naive, "r = r1 + q (r2 - r1): crowds the inside"), density}};
    result.numbers = format("r1 = %.2f, r2 = %.2f, %d samples per density curve\n", r1, r2, kDensitySamples) +
                     format("inner/outer ring density, square-root mapping: %.3f (uniform: 1)\n", good.front() / good.back()) +
                     format("inner/outer ring density, naive mapping: %.3f (theory: about %.3f)\n", bad.front() / bad.back(),
                            ringCentres.back() / ringCentres.front()) +
                     "why: the area between r and r + dr grows like r dr, so P(radius < r) = (r^2 - r1^2)/(r2^2 - r1^2); invert it\n";
    return result;
  };
  return demo;
}

// ---- 4. hemisphere ---------------------------------------------------------------

Demo hemisphereDemo() {
  Demo demo;
  demo.name = "hemisphere";
  demo.summary = "uniform and cosine-weighted hemisphere sampling: points and cos(theta) histograms against the pdf";
  demo.parameters = {{"samples", 20000, 100, 1e6, true, true, "directions drawn"},
                     {"bins", 20, 5, 100, true, false, "histogram bins"},
                     {"seed", 1, 0, 1000, true, false, "random seed"}};
  demo.run = [](const Values& p) {
    const int n = count(p, "samples"), bins = count(p, "bins");
    Uniform uniform(uint64_t(count(p, "seed")));
    const double pi = std::numbers::pi;
    // Uniform: cos(theta) = u1, pdf 1/(2 pi) per steradian. Cosine: Malley's
    // method, a uniform disk point lifted to the hemisphere, pdf cos(theta)/pi.
    std::vector<double> uniformCos, cosineCos, ux, uy, cx, cy;
    for (int i = 0; i < n; ++i) {
      const double u1 = uniform(), u2 = uniform();
      const double z = u1, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * pi * u2;
      uniformCos.push_back(z);
      const double cr = std::sqrt(u1), cz = std::sqrt(std::max(0.0, 1.0 - u1));
      cosineCos.push_back(cz);
      if (i < 3000) {
        ux.push_back(r * std::cos(phi)), uy.push_back(r * std::sin(phi));
        cx.push_back(cr * std::cos(phi)), cy.push_back(cr * std::sin(phi));
      }
    }
    Plot top1{"uniform: seen from above (x, y)", "x", "y", false, false, true, {}, {scatter(ux, uy, "")}};
    Plot top2{"cosine-weighted: seen from above", "x", "y", false, false, true, {}, {scatter(cx, cy, "")}};
    Plot histograms{"cos(theta): histograms against the pdfs", "cos(theta)", "density", false, false, false, {}, {}};
    histograms.series.push_back(densityHistogram(uniformCos, 0.0, 1.0, bins, "uniform samples"));
    histograms.series.push_back(densityHistogram(cosineCos, 0.0, 1.0, bins, "cosine samples"));
    histograms.series.push_back(line({0.0, 1.0}, {1.0, 1.0}, "uniform: p(cos) = 1", true));
    histograms.series.push_back(line({0.0, 1.0}, {0.0, 2.0}, "cosine: p(cos) = 2 cos", true));

    double meanUniform = 0.0, meanCosine = 0.0;
    for (int i = 0; i < n; ++i) meanUniform += uniformCos[size_t(i)] / n, meanCosine += cosineCos[size_t(i)] / n;
    // Pitfall 1: rand()/RAND_MAX reaches 1.0 when rand() returns RAND_MAX.
    const double drawsPerImage = 1920.0 * 1080.0 * 1024.0 * 10.0;
    // Pitfall 2: float trigonometry on doubles. sin(theta) from cos(theta)
    // near the pole: in float, cos(theta) = 1 - 1e-8 rounds to 1.
    const double c = 1.0 - 1e-8;
    const float cf = float(c);
    const double sinDouble = std::sqrt(1.0 - c * c);
    const float sinFloat = std::sqrt(1.0f - cf * cf);
    double worstAngle = 0.0;
    for (int i = 0; i < 100000; ++i) {
      const double phi = 2.0 * pi * uniform() * 1000.0;  // a large angle, as phi = 2 pi u k for k > 1 gives
      worstAngle = std::max(worstAngle, std::abs(double(std::sin(float(phi))) - std::sin(phi)));
    }
    DemoResult result;
    result.figure = {"Sampling the hemisphere", {top1, top2, histograms}};
    result.numbers =
        format("%d directions each\n", n) +
        format("mean cos(theta): uniform %.4f (exact 1/2), cosine %.4f (exact 2/3)\n", meanUniform, meanCosine) +
        format("pitfall: u = rand()/RAND_MAX is exactly 1.0 once every %.3g calls (RAND_MAX = %d);\n", double(RAND_MAX) + 1.0,
               RAND_MAX) +
        format("  a 1920x1080 render at 1024 spp with 10 numbers per sample draws %.3g of them: about %.0f values of 1.0,\n",
               drawsPerImage, drawsPerImage / (double(RAND_MAX) + 1.0)) +
        "  and floor(u * n) = n indexes past the end of an array. Use (rand() + 0.5) / (RAND_MAX + 1.0), or better a real generator.\n" +
        format("pitfall: sin(theta) from cos(theta) = 1 - 1e-8: double %.3g, float %.3g (the float cosine rounded to 1)\n",
               sinDouble, double(sinFloat)) +
        format("pitfall: sinf on a double angle near 2 pi x 1000: worst error %.2g (the angle lost its low bits in float)\n",
               worstAngle);
    return result;
  };
  return demo;
}

// ---- 5. Monte Carlo pi --------------------------------------------------------------

Demo piDemo() {
  Demo demo;
  demo.name = "pi";
  demo.summary = "Monte Carlo pi by rejection: the points, the running estimate, error against N with the 1/sqrt(N) line";
  demo.parameters = {{"samples", 100000, 100, 1e7, true, true, "points per run"},
                     {"runs", 20, 2, 200, true, true, "independent runs for the error curve"},
                     {"seed", 1, 0, 1000, true, false, "random seed"}};
  demo.run = [](const Values& p) {
    const int n = count(p, "samples"), runs = count(p, "runs");
    const double pi = std::numbers::pi;
    Uniform uniform(uint64_t(count(p, "seed")));
    // Checkpoints N = 10, 20, 50, 100, ... for the running estimate and the error.
    std::vector<int> checkpoints;
    for (int decade = 10; decade <= n; decade *= 10)
      for (int m : {1, 2, 5})
        if (decade * m <= n) checkpoints.push_back(decade * m);
    std::vector<double> squaredError(checkpoints.size(), 0.0), firstRun;
    std::vector<double> insideX, insideY, outsideX, outsideY;
    double lastEstimate = 0.0;
    for (int run = 0; run < runs; ++run) {
      long hits = 0;
      size_t next = 0;
      for (int i = 1; i <= n; ++i) {
        const double x = uniform(), y = uniform();
        const bool inside = x * x + y * y < 1.0;
        hits += inside;
        if (run == 0 && i <= 2000) (inside ? insideX : outsideX).push_back(x), (inside ? insideY : outsideY).push_back(y);
        if (next < checkpoints.size() && i == checkpoints[next]) {
          const double estimate = 4.0 * double(hits) / i;
          squaredError[next] += (estimate - pi) * (estimate - pi) / runs;
          if (run == 0) firstRun.push_back(estimate);
          ++next;
        }
      }
      if (run == 0) lastEstimate = 4.0 * double(hits) / n;
    }
    std::vector<double> ns(checkpoints.begin(), checkpoints.end()), rmse, predicted;
    for (size_t k = 0; k < ns.size(); ++k) {
      rmse.push_back(std::sqrt(squaredError[k]));
      predicted.push_back(std::sqrt(pi * (4.0 - pi) / ns[k]));  // 4 x Bernoulli(pi/4): variance pi (4 - pi)
    }
    Plot points{"2,000 points: inside the quarter circle or not", "x", "y", false, false, true, {}, {}};
    points.series.push_back(scatter(insideX, insideY, "inside"));
    points.series.push_back(scatter(outsideX, outsideY, "outside"));
    std::vector<double> arcX, arcY;
    for (double t : linspace(0.0, pi / 2, 100)) arcX.push_back(std::cos(t)), arcY.push_back(std::sin(t));
    points.series.push_back(line(arcX, arcY, ""));
    Plot running{"running estimate (run 1)", "N", "estimate of pi", true, false, false, {}, {}};
    running.series.push_back(line(ns, firstRun, "4 x inside / N"));
    running.series.push_back(line({ns.front(), ns.back()}, {pi, pi}, "pi", true));
    Plot error{"RMS error over the runs", "N", "RMS error", true, true, false, {}, {}};
    error.series.push_back(line(ns, rmse, format("measured (%d runs)", runs)));
    error.series.push_back(line(ns, predicted, "sqrt(pi (4 - pi) / N)", true));

    DemoResult result;
    result.figure = {"Monte Carlo estimation of pi", {points, running, error}};
    result.numbers = format("N = %d: estimate %.6f, error %.2e\n", n, lastEstimate, lastEstimate - pi) +
                     format("RMS error at N = %d over %d runs: %.3e; predicted sqrt(pi (4 - pi) / N) = %.3e\n", n, runs,
                            rmse.back(), predicted.back()) +
                     "the error falls as 1/sqrt(N): 100x the points for one more digit\n";
    return result;
  };
  return demo;
}

}  // namespace pathlab::demo
