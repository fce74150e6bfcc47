// ---- 8. sample sequences: independent, stratified, low-discrepancy ---------------------
//
// The same 2D integral estimated with three kinds of points: independent
// random (the 1/sqrt(N) of plain Monte Carlo), jittered on an N-cell grid
// (stratified), and the renderer's Owen-scrambled Sobol points (random.h,
// --sampler sobol). The fitted slopes of log error against log N say how
// fast each converges.
#include <cmath>
#include <numbers>

#include "demo_support.h"

namespace pathlab::demo {
namespace {

// A smooth integrand, and one with an edge (a quarter disk), over [0,1)^2.
double smooth(double u, double v) { return u * v + std::cos(2.0 * std::numbers::pi * u) + v * v; }
double edge(double u, double v) { return u * u + v * v < 1.0 ? 1.0 : 0.0; }

// Least-squares slope of log y against log x.
double logSlope(const std::vector<double>& x, const std::vector<double>& y) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    if (!(y[i] > 0.0)) continue;
    const double a = std::log(x[i]), b = std::log(y[i]);
    n += 1, sx += a, sy += b, sxx += a * a, sxy += a * b;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

Demo sequencesDemo() {
  Demo demo;
  demo.name = "sequences";
  demo.summary = "independent, stratified and Sobol points: the same integral, error against N and its slope";
  demo.parameters = {{"samples", 4096, 16, 65536, true, true, "largest N (the checkpoints are powers of 4)"},
                     {"runs", 64, 4, 1024, true, true, "independent randomisations for the RMS error"},
                     {"edge", 0, 0, 1, true, false, "0: a smooth integrand; 1: a quarter disk (an edge, like a shadow)"},
                     {"seed", 1, 0, 1000, true, false, "random seed"}};
  demo.run = [](const Values& p) {
    const int runs = count(p, "runs");
    const bool withEdge = count(p, "edge") != 0;
    const auto f = withEdge ? edge : smooth;
    const double exact = withEdge ? std::numbers::pi / 4.0 : 0.25 + 1.0 / 3.0;
    const uint64_t seed = uint64_t(count(p, "seed"));
    std::vector<double> ns;
    for (int n = 4; n <= count(p, "samples"); n *= 4) ns.push_back(n);
    const char* names[3] = {"independent", "stratified (jittered grid)", "Sobol (Owen-scrambled)"};
    std::vector<double> squared[3];
    for (auto& s : squared) s.assign(ns.size(), 0.0);
    Uniform uniform(seed);
    for (int run = 0; run < runs; ++run) {
      for (size_t k = 0; k < ns.size(); ++k) {
        const uint32_t n = uint32_t(ns[k]), side = uint32_t(std::lround(std::sqrt(double(n))));
        double sum[3] = {0.0, 0.0, 0.0};
        for (uint32_t i = 0; i < n; ++i) {
          Sampler independent(uint32_t(run), i, seed, SampleSequence::Independent);
          Sampler sobol(uint32_t(run), i, seed, SampleSequence::Sobol);
          const Vec2 a = independent.next2D(), c = sobol.next2D();
          sum[0] += f(a.x, a.y);
          sum[1] += f((double(i % side) + uniform()) / side, (double(i / side) + uniform()) / side);
          sum[2] += f(c.x, c.y);
        }
        for (int s = 0; s < 3; ++s) squared[s][k] += std::pow(sum[s] / n - exact, 2) / runs;
      }
    }
    Plot error{"RMS error over the runs", "N", "RMS error", true, true, false, {}, {}};
    std::string numbers;
    for (int s = 0; s < 3; ++s) {
      std::vector<double> rmse;
      for (double e : squared[s]) rmse.push_back(std::sqrt(e));
      const double slope = logSlope(ns, rmse);
      error.series.push_back(line(ns, rmse, format("%s (slope %.2f)", names[s], slope)));
      numbers += format("%s: RMS error %.3g at N = %d, slope of log error against log N %.2f\n", names[s],
                        rmse.back(), int(ns.back()), slope);
    }
    // The points themselves: 256 of each, with the 16 x 16 strata drawn.
    std::vector<Plot> points;
    for (int s = 0; s < 3; ++s) {
      std::vector<double> x, y;
      for (uint32_t i = 0; i < 256; ++i) {
        Sampler sampler(0, i, seed, s == 2 ? SampleSequence::Sobol : SampleSequence::Independent);
        const Vec2 u = sampler.next2D();
        x.push_back(s == 1 ? (double(i % 16) + u.x) / 16.0 : u.x);
        y.push_back(s == 1 ? (double(i / 16) + u.y) / 16.0 : u.y);
      }
      Plot plot{std::string("256 points: ") + names[s], "u", "v", false, false, true, {}, {}};
      plot.series.push_back(scatter(x, y, ""));
      points.push_back(plot);
    }
    points.push_back(error);
    DemoResult result;
    result.figure = {withEdge ? "Integrating a quarter disk with three kinds of points"
                              : "Integrating a smooth function with three kinds of points",
                     points};
    result.numbers = numbers + "plain Monte Carlo gives -0.5 (error ~ 1/sqrt(N)); evenly spread points do better, " +
                     (withEdge ? "but an edge (a shadow, an object's outline) limits the gain\n"
                               : "most for a smooth integrand\n");
    return result;
  };
  return demo;
}

}  // namespace pathlab::demo
