// Helpers the demos share: seeded uniform numbers, histograms, formatting.
#pragma once

#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "demos.h"
#include "util/random.h"

namespace pathlab::demo {

// Uniform doubles in [0, 1) with 53 random bits: counter-based, so a demo
// with the same seed draws the same numbers.
class Uniform {
 public:
  explicit Uniform(uint64_t seed) : key_(mix64(seed + 0x51ed2701u)) {}
  double operator()() { return double(mix64(key_ + 0x9e3779b97f4a7c15ULL * ++counter_) >> 11) * 0x1.0p-53; }

 private:
  uint64_t key_;
  uint64_t counter_ = 0;
};

inline std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) v[size_t(i)] = a + (b - a) * double(i) / double(n - 1);
  return v;
}

// A histogram of `values` on [a, b] with `bins` bins, as a density (integrates to 1 over [a, b]).
inline Series densityHistogram(const std::vector<double>& values, double a, double b, int bins, std::string label) {
  Series s;
  s.kind = Series::Kind::Histogram;
  s.label = std::move(label);
  s.x = linspace(a, b, bins + 1);
  s.y.assign(size_t(bins), 0.0);
  for (double v : values) {
    const int i = int((v - a) / (b - a) * bins);
    if (i >= 0 && i < bins) s.y[size_t(i)] += 1.0;
  }
  const double width = (b - a) / bins;
  for (double& h : s.y) h /= double(values.size()) * width;
  return s;
}

inline Series line(std::vector<double> x, std::vector<double> y, std::string label, bool dashed = false) {
  Series s;
  s.kind = Series::Kind::Line;
  s.x = std::move(x);
  s.y = std::move(y);
  s.label = std::move(label);
  s.dashed = dashed;
  return s;
}

inline Series scatter(std::vector<double> x, std::vector<double> y, std::string label) {
  Series s;
  s.kind = Series::Kind::Scatter;
  s.x = std::move(x);
  s.y = std::move(y);
  s.label = std::move(label);
  return s;
}

// printf into a std::string.
inline std::string format(const char* pattern, ...) {
  char buffer[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(buffer, sizeof buffer, pattern, args);
  va_end(args);
  return buffer;
}

inline int count(const Values& values, const char* name) { return int(std::lround(values.at(name))); }

// Pearson's chi-square statistic of observed counts against expected counts.
inline double chiSquare(const std::vector<double>& observed, const std::vector<double>& expected) {
  double chi = 0.0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] > 0.0) chi += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
  }
  return chi;
}

// The demos, one function each (demos_sampling.cpp, demos_rendering.cpp, demos_sequences.cpp).
Demo pdfCdfDemo();
Demo discreteDemo();
Demo annulusDemo();
Demo hemisphereDemo();
Demo piDemo();
Demo renderingEquationDemo();
Demo environmentDemo();
Demo sequencesDemo();

}  // namespace pathlab::demo
