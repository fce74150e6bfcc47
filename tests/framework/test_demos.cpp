// The lecture demos' numerics (lab/): the inversions they teach must be
// right to the last digit, and every demo must run and say what it shows.
#include "suite/doctest_strings.h"

#include <cmath>

#include "demos.h"

using namespace pathlab::demo;

TEST_CASE("demos: F inverts exactly, Newton with bisection fallback, for u across [0, 1)") {
  CHECK(exampleCdf(0.0) == 0.0);
  CHECK(exampleCdf(2.0) == doctest::Approx(1.0).epsilon(1e-14));
  for (double u : {0.0, 1e-12, 1e-6, 0.01, 0.25, 0.5, 0.77, 0.999, 1.0 - 1e-9, 1.0 - 1e-15}) {
    CAPTURE(u);
    int iterations = 0;
    const double x = invertExampleCdf(u, &iterations);
    CHECK(x >= 0.0);
    CHECK(x <= 2.0);
    CHECK(std::abs(exampleCdf(x) - u) < 1e-12);
    CHECK(iterations < 60);
  }
  // From a poor start Newton overshoots the bracket; bisection takes over.
  bool bisected = false;
  const double fromZero = invertExampleCdf(0.999, nullptr, &bisected, 0.0);
  CHECK(bisected);
  CHECK(std::abs(exampleCdf(fromZero) - 0.999) < 1e-12);
  invertExampleCdf(0.999, nullptr, &bisected);
  CHECK_FALSE(bisected);
  // f is F's derivative (central differences) and positive on [0, 2].
  for (double x = 0.05; x < 2.0; x += 0.05) {
    CHECK((exampleCdf(x + 1e-6) - exampleCdf(x - 1e-6)) / 2e-6 == doctest::Approx(examplePdf(x)).epsilon(1e-6));
    CHECK(examplePdf(x) > 0.15);
  }
}

TEST_CASE("demos: discrete inversion picks block i exactly for u in [cdf[i-1], cdf[i])") {
  const std::vector<double> cdf = {0.1, 0.35, 0.4, 0.7, 0.9, 1.0};
  CHECK(sampleDiscrete(cdf, 0.0) == 0);
  CHECK(sampleDiscrete(cdf, 0.0999) == 0);
  CHECK(sampleDiscrete(cdf, 0.1) == 1);  // a block's top belongs to the next block
  CHECK(sampleDiscrete(cdf, 0.39) == 2);
  CHECK(sampleDiscrete(cdf, 0.4) == 3);
  CHECK(sampleDiscrete(cdf, 0.9999999) == 5);
}

TEST_CASE("demos: each runs at its defaults and fills every plot and its numbers") {
  for (const Demo& demo : allDemos()) {
    CAPTURE(demo.name);
    Values values;
    for (const Parameter& p : demo.parameters) values[p.name] = p.value;
    if (values.count("samples")) values["samples"] = std::min(values["samples"], 20000.0);
    const DemoResult result = demo.run(values);
    CHECK_FALSE(result.figure.plots.empty());
    CHECK_FALSE(result.numbers.empty());
    for (const Plot& plot : result.figure.plots) CHECK_FALSE(plot.series.empty());
  }
}
