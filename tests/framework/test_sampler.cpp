// The framework's sampler (random.h): independent numbers, jittered strata,
// and Owen-scrambled Sobol points whose power-of-two prefixes are stratified
// in every dimension.
#include "suite/doctest_strings.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "util/random.h"

using namespace pathlab;

namespace {

// Whether `points` (2^m of them) form a (0, m, 2)-net: every box of
// 2^a x 2^(m-a) cells holds exactly one point, for every a = 0..m.
bool isNet(const std::vector<Vec2>& points, int m) {
  for (int a = 0; a <= m; ++a) {
    const int columns = 1 << a, rows = 1 << (m - a);
    std::vector<int> count(size_t(columns) * size_t(rows), 0);
    for (const Vec2& p : points) ++count[size_t(int(p.y * float(rows))) * size_t(columns) + size_t(int(p.x * float(columns)))];
    for (int c : count) {
      if (c != 1) return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("sampler: each pixel's first 2^m Sobol samples are a (0, m, 2)-net in every dimension pair, "
          "and stratified in every 1D dimension") {
  for (uint32_t pixel : {0u, 1u, 12345u}) {
    for (int m = 0; m <= 8; ++m) {
      const uint32_t n = 1u << m;
      std::vector<std::vector<Vec2>> pairs(6);
      std::vector<std::vector<int>> strata(3, std::vector<int>(n, 0));
      for (uint32_t i = 0; i < n; ++i) {
        Sampler sampler(pixel, i, 7, SampleSequence::Sobol);
        for (int d = 0; d < 3; ++d) pairs[size_t(d)].push_back(sampler.next2D());
        for (int d = 0; d < 3; ++d) ++strata[size_t(d)][size_t(sampler.next1D() * float(n))];
        for (int d = 3; d < 6; ++d) pairs[size_t(d)].push_back(sampler.next2D());
      }
      for (size_t d = 0; d < pairs.size(); ++d) CHECK_MESSAGE(isNet(pairs[d], m), "pixel ", pixel, ", pair ", d, ", 2^", m);
      for (const std::vector<int>& s : strata) {
        for (int c : s) CHECK(c == 1);
      }
    }
  }
}

TEST_CASE("sampler: Sobol numbers lie in [0, 1) and differ between pixels, dimensions and seeds") {
  Sampler a(3, 5, 1, SampleSequence::Sobol), b(4, 5, 1, SampleSequence::Sobol), c(3, 5, 2, SampleSequence::Sobol);
  const Vec2 a0 = a.next2D(), a1 = a.next2D(), b0 = b.next2D(), c0 = c.next2D();
  CHECK(a0 != a1);
  CHECK(a0 != b0);
  CHECK(a0 != c0);
  for (uint32_t i = 0; i < 4096; ++i) {
    Sampler s(i % 7, i, 3, SampleSequence::Sobol);
    for (int d = 0; d < 8; ++d) {
      const Vec2 u = s.next2D();
      const float v = s.next1D();
      REQUIRE((u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f && v >= 0.0f && v < 1.0f));
    }
  }
}

// An unbiased estimate of a known integral: each pixel's 64 Sobol samples
// give one estimate; pixels are independent randomisations, so the mean of
// 4096 of them has a standard error measured from their spread. |z| < 5
// fails a correct sampler with probability 6e-7 (normal tails; the
// estimates are bounded, so the mean of 4096 is close to normal). The
// spread itself must be far below independent sampling's, which is what a
// low-discrepancy sequence is for.
TEST_CASE("sampler: Sobol estimates are unbiased, with a fraction of independent sampling's variance") {
  // f(u, v) = u v + cos(2 pi u) + v^2 over [0,1)^2: 1/4 + 0 + 1/3.
  const auto f = [](Vec2 u) { return double(u.x) * u.y + std::cos(2.0 * std::numbers::pi * u.x) + double(u.y) * u.y; };
  const double exact = 0.25 + 1.0 / 3.0;
  auto spread = [&](SampleSequence sequence, double* mean) {
    constexpr int kPixels = 4096, kSamples = 64;
    double sum = 0.0, sumSquares = 0.0;
    for (uint32_t p = 0; p < kPixels; ++p) {
      double estimate = 0.0;
      for (uint32_t i = 0; i < kSamples; ++i) {
        Sampler sampler(p, i, 11, sequence);
        sampler.next2D();  // a camera-like first dimension, so the integrand is not the first pair
        estimate += f(sampler.next2D());
      }
      estimate /= kSamples;
      sum += estimate, sumSquares += estimate * estimate;
    }
    *mean = sum / kPixels;
    const double variance = (sumSquares - sum * sum / kPixels) / (kPixels - 1);
    return std::sqrt(variance / kPixels);  // standard error of the mean
  };
  double sobolMean = 0.0, independentMean = 0.0;
  const double sobolError = spread(SampleSequence::Sobol, &sobolMean);
  const double independentError = spread(SampleSequence::Independent, &independentMean);
  CHECK(std::abs(sobolMean - exact) < 5.0 * sobolError);
  CHECK(std::abs(independentMean - exact) < 5.0 * independentError);
  CHECK(sobolError < 0.2 * independentError);  // measured 0.027 (seeds 11, 12, 13): 64 samples of a net
}

TEST_CASE("sampler: stratified samples put one sample in each cell, dimension by dimension, for any count") {
  CHECK(strataColumns(16) == 4);
  CHECK(strataColumns(8) == 2);
  CHECK(strataColumns(12) == 3);
  CHECK(strataColumns(7) == 1);
  for (uint32_t n : {1u, 2u, 5u, 8u, 9u, 12u, 64u, 100u}) {
    const uint32_t columns = strataColumns(n), rows = n / columns;
    for (uint32_t pixel : {0u, 77u}) {
      std::vector<std::vector<int>> cells(4, std::vector<int>(n, 0)), strata(2, std::vector<int>(n, 0));
      std::vector<size_t> cellOf[2];
      for (uint32_t i = 0; i < n; ++i) {
        Sampler sampler(pixel, i, 5, SampleSequence::Stratified, n);
        for (int d = 0; d < 4; ++d) {
          const Vec2 u = sampler.next2D();
          REQUIRE((u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f));
          const size_t cell = size_t(int(u.y * float(rows))) * columns + size_t(int(u.x * float(columns)));
          ++cells[size_t(d)][cell];
          if (d < 2) cellOf[d].push_back(cell);
          if (d < 2) ++strata[size_t(d)][size_t(sampler.next1D() * float(n))];
        }
      }
      for (const auto& dimension : cells) {
        for (int c : dimension) CHECK_MESSAGE(c == 1, n, " samples, pixel ", pixel);
      }
      for (const auto& dimension : strata) {
        for (int c : dimension) CHECK(c == 1);
      }
      // Each dimension deals the cells in its own random order, so the cell
      // of dimension 0 predicts nothing about dimension 1: samples in the
      // same cell in both are the fixed points of a random permutation,
      // about Poisson(1); 32 or more of 64 has probability below 1e-35.
      if (n >= 64) {
        size_t same = 0;
        for (uint32_t i = 0; i < n; ++i) same += cellOf[0][i] == cellOf[1][i];
        CHECK(same < n / 2);
      }
    }
  }
  // Samples past the count (a render that goes on) are independent, still in [0, 1).
  Sampler past(3, 20, 5, SampleSequence::Stratified, 16);
  const Vec2 u = past.next2D();
  CHECK((u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f));
}

// As for Sobol above: |z| < 5 fails a correct sampler with probability 6e-7.
TEST_CASE("sampler: stratified estimates are unbiased, with less variance than independent samples") {
  const auto f = [](Vec2 u) { return double(u.x) * u.y + std::cos(2.0 * std::numbers::pi * u.x) + double(u.y) * u.y; };
  const double exact = 0.25 + 1.0 / 3.0;
  constexpr int kPixels = 4096;
  constexpr uint32_t kSamples = 64;
  double sum = 0.0, sumSquares = 0.0, independentSumSquares = 0.0, independentSum = 0.0;
  for (uint32_t p = 0; p < kPixels; ++p) {
    double estimate = 0.0, independent = 0.0;
    for (uint32_t i = 0; i < kSamples; ++i) {
      Sampler sampler(p, i, 11, SampleSequence::Stratified, kSamples), plain(p, i, 11);
      sampler.next2D(), plain.next2D();
      estimate += f(sampler.next2D()) / kSamples;
      independent += f(plain.next2D()) / kSamples;
    }
    sum += estimate, sumSquares += estimate * estimate;
    independentSum += independent, independentSumSquares += independent * independent;
  }
  const double mean = sum / kPixels;
  const double standardError = std::sqrt((sumSquares - sum * sum / kPixels) / (kPixels - 1) / kPixels);
  const double independentError =
      std::sqrt((independentSumSquares - independentSum * independentSum / kPixels) / (kPixels - 1) / kPixels);
  CHECK(std::abs(mean - exact) < 5.0 * standardError);
  CHECK(standardError < 0.3 * independentError);  // measured 0.21: an 8 x 8 grid, jittered
}
