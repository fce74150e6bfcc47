// Autograder suite for task 11 — adaptive sampling. Tests run from basic to
// advanced; the first failure is usually the root cause. candidate::f(...)
// is the student's f, computed in the candidate process (calls.h).
//
// The judge serves the samples, a batch at a time when a pixel asks, so it
// counts each pixel's samples itself; it knows where a correct pixel must
// stop and what it must return, and never takes a count or a variance the
// candidate reports for a fact: an estimate is checked against the mean of
// the samples the judge served, the number of samples against the judge's
// own application of the rule, a mean's noise is capped at what the
// reference's shows (reference-variances.txt), and an image's noise is
// capped by the image test (image_test.h).
// Where the rule's two sides are equal to rounding (1e-9), the judge asks
// nothing about that pixel: any correct way of writing the formula may fall
// either side.
#include "suite/doctest_strings.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "image_calls.h"
#include "calls.h"
#include "check.h"
#include "suite/grading.h"
#include "image_scenes.h"
#include "image_test.h"
#include "reference_noise.h"
#include "statistics.h"
#include "util/image.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

AdaptiveSettings settings(double tolerance, uint32_t batch, uint32_t minSpp, uint32_t maxSpp) {
  AdaptiveSettings s;
  s.tolerance = tolerance;
  s.batch = batch;
  s.minSpp = minSpp;
  s.maxSpp = maxSpp;
  return s;
}

// Several ways a course may set the rule up: a tight tolerance, batches of 8
// to 64, minimums from one batch to four.
std::vector<AdaptiveSettings> someSettings() {
  return {settings(0.1, 16, 32, 512), settings(0.05, 32, 64, 1024), settings(0.2, 8, 8, 128),
          settings(0.02, 64, 64, 256)};
}

// Where a correct samplePixelAdaptively stops on `values` (values.size() ==
// maxSpp), and the mean of the samples up to there: the judge's own Welford
// in double over the same float luminance the candidate sees.
struct Expected {
  uint32_t n = 0;
  bool confident = false;
  bool ambiguous = false;  // some check had both sides equal to within 1e-9: any n from there on is right
  DVec3 mean{0.0};
};

// How far a correct float mean of the first n values may be from the exact
// one: a running float sum (or Welford's update, or pairwise sums) rounds by
// at most about n u max|x| (Higham's bound for recursive summation, u = 2^-24
// the float's unit roundoff); 3 (n + 1) u max|x| per component covers every
// order of summation, far below any mistake in which samples were counted.
float floatMeanTolerance(const std::vector<Color>& values, uint32_t n) {
  float largest = 0.0f;
  for (uint32_t i = 0; i < n && i < values.size(); ++i) largest = std::max(largest, maxComponent(glm::abs(values[i])));
  return 3.0f * float(n + 1) * 0x1p-24f * largest;
}

// `slack`: how close (relative) the rule's two sides count as equal, for `ambiguous`.
Expected expectedStop(const std::vector<Color>& values, const AdaptiveSettings& a, double slack = 1e-9) {
  Expected e;
  double mean = 0.0, m2 = 0.0;
  DVec3 sum(0.0);
  uint32_t n = 0;
  while (n < a.maxSpp && !e.confident) {
    for (uint32_t k = 0; k < a.batch && n < a.maxSpp; ++k) {
      const double x = double(luminance(values[n]));
      sum += DVec3(values[n]);
      ++n;
      const double delta = x - mean;
      mean += delta / n;
      m2 += delta * (x - mean);
    }
    if (n < a.minSpp) continue;
    const double variance = n > 1 ? m2 / (n - 1) : 0.0;
    const double half = 1.96 * std::sqrt(variance / n), bound = a.tolerance * mean;
    if (std::abs(half - bound) <= slack * std::max({std::abs(half), std::abs(bound), 1e-300})) e.ambiguous = true;
    e.confident = half <= bound;
  }
  e.n = n;
  e.mean = sum / double(std::max(1u, n));
  return e;
}

// Sequences of samples of every kind a pixel meets: steady (a lit wall),
// noisy (a soft shadow), heavy-tailed (a caustic: rare samples 100x the
// rest), dark with rare light, coloured (the channels' noise unlike one
// another: the luminance decides, not a channel), each of length maxSpp.
std::vector<std::vector<Color>> someSequences(const AdaptiveSettings& a, Random& random, int count) {
  std::vector<std::vector<Color>> sequences;
  for (int k = 0; k < count; ++k) {
    const int kind = k % 5;
    const double level = std::exp(random.uniform(-3.0, 3.0));
    const Color tint(float(random.uniform(0.2, 1.0)), float(random.uniform(0.2, 1.0)), float(random.uniform(0.2, 1.0)));
    std::vector<Color> values;
    for (uint32_t i = 0; i < a.maxSpp; ++i) {
      double v = 0.0;
      switch (kind) {
        case 0: v = level * (1.0 + random.uniform(-0.1, 0.1)); break;              // steady
        case 1: v = -level * std::log(1.0 - random.uniform()); break;               // noisy: exponential
        case 2: v = random.uniform() < 0.01 ? 100.0 * level : 0.5 * level; break;   // heavy-tailed
        case 3: v = random.uniform() < 0.02 ? 1e-3 * level : 0.0; break;            // dark, rare light
        default: v = level * random.uniform(0.5, 1.5); break;                       // moderate
      }
      if (kind == 4) {  // coloured: a steady red, a noisy green (most of the luminance), a steady blue
        values.push_back(Color(float(v), float(-level * std::log(1.0 - random.uniform())), float(level)));
        continue;
      }
      values.push_back(float(v) * tint);
    }
    sequences.push_back(std::move(values));
  }
  return sequences;
}

}  // namespace

TEST_CASE("T11.1 Welford: the mean and the sample variance of any sequence, as a two-pass sum in double gives them" *
          grading(3, "n <- n + 1; delta = x - mean; mean <- mean + delta / n; M2 <- M2 + delta * (x - mean) with the "
                     "new mean; a sum of squares minus the squared sum loses every digit when the mean is large "
                     "against the spread (1e8 + 0.001)")) {
  Random random(11);
  std::vector<std::vector<double>> sequences;
  for (int k = 0; k < 60; ++k) {
    const int length = 2 + int(random.uniform(0.0, 2000.0));
    const double offset = k % 3 == 0 ? 1e8 : k % 3 == 1 ? 0.0 : -250.0;
    const double spread = k % 3 == 0 ? 1e-3 : std::exp(random.uniform(-5.0, 5.0));
    std::vector<double> values;
    for (int i = 0; i < length; ++i) values.push_back(offset + spread * random.uniform(-1.0, 1.0));
    sequences.push_back(std::move(values));
  }
  const std::vector<calls::Accumulated> results = candidate::addSamples(sequences);
  HINT("addSamples must return one result per sequence it was given (the call failed or lost sequences)");
  REQUIRE(results.size() == sequences.size());
  for (size_t k = 0; k < sequences.size(); ++k) {
    const std::vector<double>& values = sequences[k];
    double mean = 0.0;
    for (double x : values) mean += x / double(values.size());
    double squares = 0.0;
    for (double x : values) squares += (x - mean) * (x - mean);
    const double variance = squares / double(values.size() - 1);
    // (Not a structured binding: Clang 14 cannot capture one in INFO's lambda.)
    const RunningStatistics& stats = std::get<0>(results[k]);
    const double yourVariance = std::get<1>(results[k]);
    INFO("sequence " << k << ": " << values.size() << " values around " << values[0] << ": two-pass mean " << mean
                     << ", sample variance " << variance << "; yours: n " << stats.n << ", mean " << stats.mean
                     << ", sampleVariance " << yourVariance);
    HINT("n counts every sample added: add 1 to n once per sample, before the mean is updated");
    CHECK(stats.n == values.size());
    HINT("the running mean is wrong: mean <- mean + (x - mean) / n with the n that counts this sample");
    CHECK(std::abs(stats.mean - mean) <= 1e-12 * std::max(1.0, std::abs(mean)));  // (1.5e-8 around 1e8)
    // Around 1e8 a double resolves 1.5e-8, 1.5e-5 of the spread: any method's
    // deviations carry that error (Welford and two-pass differ by 1e-5 there);
    // a sum of squares is off by its whole size. Elsewhere, rounding only.
    const double tolerance = values[0] > 1e7 ? 1e-3 : 1e-10;
    HINT("the sample variance is off: M2 <- M2 + delta * (x - mean), delta taken with the old mean and the second "
         "factor with the new one, and the variance M2 / (n - 1); a sum of squares minus the squared sum loses "
         "every digit around 1e8 with a spread of 0.001");
    CHECK(std::abs(yourVariance - variance) <= tolerance * variance);
  }
}

TEST_CASE("T11.1 Welford: n - 1 in the sample variance; one sample or none has variance 0" *
          grading(2, "divide M2 by n - 1, not n (the mean came from the same samples); with n < 2 there is no "
                     "spread to measure: return 0, not 0 / 0")) {
  const std::vector<calls::Accumulated> results = candidate::addSamples({{1.0, 3.0}, {5.0}, {}, {2.0, 2.0, 2.0, 6.0}});
  HINT("addSamples must return one result per sequence it was given, the empty one too");
  REQUIRE(results.size() == 4);
  INFO("{1, 3}: n " << std::get<0>(results[0]).n << ", mean " << std::get<0>(results[0]).mean << ", variance "
                    << std::get<1>(results[0]) << " (expected 2)");
  HINT("the mean of {1, 3} is 2, and its sample variance 2: divide M2 by n - 1 (the mean came from the same "
       "samples), not by n");
  CHECK(std::get<0>(results[0]).mean == doctest::Approx(2.0));
  CHECK(std::get<1>(results[0]) == doctest::Approx(2.0));
  INFO("{5}: mean " << std::get<0>(results[1]).mean << ", variance " << std::get<1>(results[1]) << " (expected 5, 0)");
  HINT("one sample has no spread to measure: its mean is that sample and its variance 0, not M2 / 0 (NaN)");
  CHECK(std::get<0>(results[1]).mean == doctest::Approx(5.0));
  CHECK(std::get<1>(results[1]) == 0.0);
  INFO("{}: n " << std::get<0>(results[2]).n << ", variance " << std::get<1>(results[2]) << " (expected 0, 0)");
  HINT("no samples: n stays 0 and the variance is 0, not 0 / 0 or 0 / -1");
  CHECK(std::get<0>(results[2]).n == 0);
  CHECK(std::get<1>(results[2]) == 0.0);
  INFO("{2, 2, 2, 6}: variance " << std::get<1>(results[3]) << " (expected 4)");
  HINT("{2, 2, 2, 6} has sample variance 4 (M2 = 12 over n - 1 = 3): a variance of 3 divides by n");
  CHECK(std::get<1>(results[3]) == doctest::Approx(4.0));
  // The variance of statistics the judge wrote: M2 / (n - 1).
  RunningStatistics a, b;
  a.n = 10, a.mean = 2.0, a.m2 = 9.0;
  b.n = 1, b.mean = 7.0, b.m2 = 0.0;
  const std::vector<double> variances = candidate::sampleVariances({a, b});
  HINT("sampleVariance, given statistics it did not make, must read them as they are: M2 / (n - 1), and 0 when "
       "n < 2; one answer per statistics given");
  REQUIRE(variances.size() == 2);
  INFO("n 10, M2 9: your variance " << variances[0] << " (expected 1); n 1: " << variances[1] << " (expected 0)");
  CHECK(variances[0] == doctest::Approx(1.0));
  CHECK(variances[1] == 0.0);
}

TEST_CASE("T11.2 rule: stop once 1.96 sigma / sqrt(n) <= tolerance x mean, and not before the minimum" *
          grading(3, "half-width = 1.96 * sqrt(sampleVariance / n); stop when n >= minSpp and half-width <= "
                     "tolerance * mean; a dark pixel (mean 0, some spread) never stops by the rule")) {
  for (const AdaptiveSettings& a : someSettings()) {
    std::vector<RunningStatistics> all;
    std::vector<uint8_t> expected;
    std::vector<std::string> what;
    for (uint32_t n : {a.minSpp, 4 * a.minSpp, a.minSpp + 3 * a.batch}) {
      for (double mean : {1.0, 0.013, 250.0}) {
        for (double side : {0.999, 1.001}) {  // just inside, just outside
          // The variance that puts the half-width at `side` times tolerance x mean.
          const double half = side * a.tolerance * mean, variance = n * (half / 1.96) * (half / 1.96);
          RunningStatistics s;
          s.n = n, s.mean = mean, s.m2 = variance * (n - 1);
          all.push_back(s);
          expected.push_back(side < 1.0 ? 1 : 0);
          what.push_back("n " + std::to_string(n) + ", mean " + std::to_string(mean) + ", half-width " +
                         std::to_string(side) + " x tolerance x mean");
        }
      }
    }
    // No spread at all: the half-width is 0, within any tolerance of a positive mean.
    RunningStatistics flat;
    flat.n = 2 * a.minSpp, flat.mean = 0.4, flat.m2 = 0.0;
    all.push_back(flat);
    expected.push_back(1);
    what.push_back("no spread at all (every sample the same), mean 0.4");
    // Below the minimum, however tight; a mean of 0 with spread; a negative mean.
    RunningStatistics early, dark, negative;
    early.n = a.minSpp - 1, early.mean = 1.0, early.m2 = 1e-12;
    dark.n = 2 * a.minSpp, dark.mean = 0.0, dark.m2 = 1e-6;
    negative.n = 2 * a.minSpp, negative.mean = -1.0, negative.m2 = 1e-9;
    for (const auto& [s, label] : {std::pair{early, "one sample below the minimum, no spread"},
                                   std::pair{dark, "mean 0 with some spread"},
                                   std::pair{negative, "a negative mean"}}) {
      all.push_back(s);
      expected.push_back(0);
      what.push_back(label);
    }
    const std::vector<uint8_t> yours = candidate::confidentEnough(all, a);
    HINT("confidentEnough must answer once per statistics it was given");
    REQUIRE(yours.size() == all.size());
    HINT("the rule is 1.96 sqrt(sampleVariance / n) <= tolerance x mean, and never before minSpp: the line "
         "printed says which case (the half-width just inside or outside, no spread, below the minimum, a mean "
         "of 0 or below) got the wrong answer");
    for (size_t k = 0; k < all.size(); ++k) {
      INFO("tolerance " << a.tolerance << ", min " << a.minSpp << ": " << what[k] << ": expected "
                        << (expected[k] ? "stop" : "go on") << ", yours " << (yours[k] ? "stop" : "go on"));
      CHECK(yours[k] == expected[k]);
    }
  }
}

TEST_CASE("T11.3 pixel: stops after the first whole batch where the rule holds, with the mean of exactly its samples" *
          grading(4, "take whole batches (sample(n) for the next n), check confidentEnough after each, stop at "
                     "maxSpp; the estimate is the colour sum over the samples this pixel took (not over maxSpp); "
                     "the statistics follow luminance(c)")) {
  Random random(23);
  int judged = 0;
  for (const AdaptiveSettings& a : someSettings()) {
    std::vector<std::vector<Color>> sequences = someSequences(a, random, 60);
    // Pixels with no spread at all: a flat colour (the rule holds at the first batch past the minimum),
    // and black (0 <= 0: the rule holds, and ambiguously, so any stop is right).
    sequences.push_back(std::vector<Color>(a.maxSpp, Color(0.3f, 0.2f, 0.1f)));
    sequences.push_back(std::vector<Color>(a.maxSpp, Color(0.0f)));
    const std::vector<candidate::ServedPixel> results = candidate::samplePixels(sequences, a);
    HINT("samplePixels must return one pixel per sequence of samples it was given");
    REQUIRE(results.size() == sequences.size());
    for (size_t k = 0; k < sequences.size(); ++k) {
      const Expected e = expectedStop(sequences[k], a);
      const candidate::ServedPixel& r = results[k];
      CAPTURE(k);
      INFO("tolerance " << a.tolerance << ", batches of " << a.batch << ", " << a.minSpp << " to " << a.maxSpp
                        << " spp; sequence " << k << (k < 60 ? " (kind " + std::to_string(k % 5) + ")" : " (no spread at all)")
                        << ": the rule stops it at n = " << e.n
                        << (e.confident ? " (confident)" : " (the maximum)") << " with mean " << str(Color(e.mean))
                        << "; yours took " << r.served << " samples, said " << r.pixel.samples << ", returned "
                        << str(r.pixel.estimate) << (r.pixel.confident ? " (confident)" : " (not confident)")
                        << (r.overran ? "; it kept asking for samples far past the maximum" : ""));
      HINT("the pixel kept asking for samples far past settings.maxSpp: stop there whatever the rule says");
      REQUIRE_FALSE(r.overran);
      if (e.ambiguous) continue;
      ++judged;
      HINT("the pixel stopped at the wrong n: take whole batches (sample(n) for the next n), check "
           "confidentEnough after each batch, not per sample, and stop after the first batch where it holds or at "
           "maxSpp; the statistics follow luminance(c)");
      CHECK(r.served == e.n);
      HINT("pixel.samples must say how many samples this pixel took, the n it stopped at");
      CHECK(r.pixel.samples == e.n);
      HINT("the estimate is the colour sum over exactly the samples this pixel took, divided by their number "
           "(not by maxSpp, not the luminance's mean)");
      CHECK(near(Vec3(r.pixel.estimate), Vec3(e.mean), floatMeanTolerance(sequences[k], e.n)));
      HINT("a pixel that stopped before maxSpp because the rule held must say confident = true");
      if (e.n < a.maxSpp) CHECK(r.pixel.confident);
    }
  }
  HINT("too few pixels could be judged: most stops were ambiguous, which a correct pixel loop never makes");
  CHECK(judged > 200);
}

TEST_CASE("T11.3 metamorphic: samples 2^40 times brighter or darker stop at the same n, the estimate scaled alike" *
          grading(2, "the rule is relative (half-width against tolerance x mean), so nothing in it may compare a "
                     "variance, a half-width or a mean with a fixed number: a pixel's radiance can be 1e-12 or 1e12")) {
  // The relation (docs/metamorphic.md): scaling every sample by a power of
  // two scales every float exactly, so a correct pixel stops at the same n,
  // as confident, with its estimate scaled exactly alike. Beside it, the
  // truth: unscaled, each pixel stops where the judge's own rule says.
  Random random(29);
  const AdaptiveSettings a = settings(0.05, 32, 64, 1024);
  const std::vector<std::vector<Color>> sequences = someSequences(a, random, 40);
  const std::vector<candidate::ServedPixel> base = candidate::samplePixels(sequences, a, candidate::Serving::AllAtOnce);
  HINT("samplePixels must return one pixel per sequence of samples it was given");
  REQUIRE(base.size() == sequences.size());
  int wrongStops = 0;
  for (size_t k = 0; k < sequences.size(); ++k) {
    const Expected e = expectedStop(sequences[k], a);
    if (!e.ambiguous && base[k].pixel.samples != e.n) ++wrongStops;
  }
  INFO(wrongStops << " of " << sequences.size() << " pixels stop where the rule does not");
  HINT("the relation below compares your pixels with themselves, so they must first stop where the rule says: "
       "after the first whole batch with 1.96 sigma / sqrt(n) <= tolerance x mean, or at the maximum");
  REQUIRE(wrongStops == 0);
  for (const double scale : {0x1p-40, 0x1p40}) {
    std::vector<std::vector<Color>> scaled = sequences;
    for (std::vector<Color>& sequence : scaled)
      for (Color& c : sequence) c *= float(scale);
    const std::vector<candidate::ServedPixel> moved = candidate::samplePixels(scaled, a, candidate::Serving::AllAtOnce);
    HINT("samplePixels must return one pixel per sequence of samples it was given");
    REQUIRE(moved.size() == sequences.size());
    int differing = 0;
    std::ostringstream where;
    for (size_t k = 0; k < sequences.size(); ++k) {
      const AdaptivePixel &before = base[k].pixel, &after = moved[k].pixel;
      const Vec3 expected = Vec3(before.estimate) * float(scale);
      const bool same = after.samples == before.samples && after.confident == before.confident &&
                        near(Vec3(after.estimate), expected, 1e-5f * std::max(1e-30f, maxComponent(glm::abs(expected))));
      if (same) continue;
      if (differing++ < 3) {
        where << " pixel " << k << ": " << before.samples << " samples became " << after.samples << ";";
      }
    }
    CAPTURE(scale);
    INFO(differing << " of " << sequences.size() << " pixels change when every sample is scaled;" << where.str());
    HINT("a pixel stops elsewhere, or its estimate does not scale, when every sample is 2^40 times brighter or "
         "darker: a variance, half-width or mean compared with a fixed number (an epsilon such as 1e-6) breaks "
         "the rule's scale; compare only 1.96 sigma / sqrt(n) with tolerance x mean");
    CHECK(differing == 0);
  }
}

TEST_CASE("T11.3 pixel: never past the maximum; a dark pixel with rare light runs to it and says so" *
          grading(2, "stop at settings.maxSpp whatever the rule says: a pixel whose mean is near 0 never meets "
                     "tolerance x mean; report confident = false there")) {
  Random random(29);
  for (const AdaptiveSettings& a : someSettings()) {
    std::vector<std::vector<Color>> sequences;
    for (int k = 0; k < 20; ++k) {
      std::vector<Color> values;
      for (uint32_t i = 0; i < a.maxSpp; ++i) values.push_back(Color(random.uniform() < 0.03 ? 1e-4f : 0.0f));
      values[size_t(k) % values.size()] = Color(2e-4f);  // never all zero
      sequences.push_back(std::move(values));
    }
    const std::vector<candidate::ServedPixel> results = candidate::samplePixels(sequences, a);
    HINT("samplePixels must return one pixel per sequence of samples it was given");
    REQUIRE(results.size() == sequences.size());
    for (size_t k = 0; k < sequences.size(); ++k) {
      const Expected e = expectedStop(sequences[k], a);
      const candidate::ServedPixel& r = results[k];
      INFO("maximum " << a.maxSpp << ": the rule never holds on this dark pixel (expected n = " << e.n
                      << "); yours asked for " << r.served << (r.overran ? " (and kept asking)" : "") << ", said "
                      << r.pixel.samples << (r.pixel.confident ? ", confident" : ", not confident"));
      HINT("the pixel asked for more than settings.maxSpp samples: stop at the maximum whatever the rule says "
           "(a mean near 0 never meets tolerance x mean)");
      CHECK_FALSE(r.overran);
      CHECK(r.served <= a.maxSpp);
      if (e.ambiguous || e.confident) continue;
      HINT("a dark pixel the rule never stops must run to maxSpp and say so: samples = maxSpp, confident = false");
      CHECK(r.pixel.samples == a.maxSpp);
      CHECK_FALSE(r.pixel.confident);
    }
  }
  // The smallest render there is, -s 1 --adaptive: one sample, and its colour.
  const Color one(0.3f, 0.5f, 0.7f);
  const std::vector<candidate::ServedPixel> single = candidate::samplePixels({{one}}, settings(0.1, 1, 1, 1));
  HINT("with a maximum of 1 sample (-s 1 --adaptive) the pixel takes that one sample and returns its colour: "
       "a batch larger than the maximum is cut to it, and one sample's variance is 0, not 0 / 0");
  REQUIRE(single.size() == 1);
  INFO("a maximum of 1 sample of " << str(Vec3(one)) << ": yours took " << single[0].served << " and returned "
                                   << str(Vec3(single[0].pixel.estimate)));
  CHECK(single[0].served == 1);
  CHECK(near(Vec3(single[0].pixel.estimate), Vec3(one), 1e-6f));
}

TEST_CASE("T11.3 pixel: the rule's bias stays under its bound (many pixels of one skewed distribution)" *
          grading(2, "a pixel that stops when its own samples look good is biased slightly towards those samples; "
                     "the minimum keeps that small. A large bias means the estimate is not the plain mean of the "
                     "samples taken, or the rule stops on one sample's luck (checked every sample, no minimum)")) {
  // 6,000 pixels whose samples are exponential with mean 1 (sigma = mean):
  // the rule stops at n ~ (1.96 / 0.15)^2 = 170 on average (175 measured).
  // Measured on the reference, seeds 1-40: the mean estimate minus 1
  // averages +0.0001, spread 0.0009 over seeds (one run's standard error
  // 0.0010): no bias this test can see. Bound: 0.5 % + 5 standard errors of
  // this run's mean, the estimates' own spread but at most the ceiling
  // (reference_noise.h): +1e10 and -1e10 in turn cannot widen it. Only the
  // estimates are judged here, so each pixel's whole sequence goes with the
  // request, 500 pixels at a time (with all 6,000 in one call the judge and
  // the candidate held 420 MB).
  // Served all at once, the judge does not see which samples a pixel took:
  // an estimate tied to none (a constant 1), or the plain mean of all 1,024
  // (unbiased, and not adaptive), would pass the mean alone. So each
  // estimate must also be the mean of the samples the judge's own rule stops
  // at (the handout pins it: the first whole batch past the minimum where
  // 1.96 s / sqrt(n) <= tolerance x mean, or the maximum), within a float
  // mean's rounding (floatMeanTolerance), and pixel.samples must be that n.
  // Pixels where the rule's two sides are equal to a float's rounding
  // (1e-6: the rule's sides in float, a correct variant, differ from the
  // judge's double by about 1e-7) are not asked (expectedStop's `ambiguous`:
  // none of these 6,000 on the reference).
  const AdaptiveSettings a = settings(0.15, 16, 64, 1024);
  Random random(31);
  MeanEstimate estimates;
  double spp = 0.0;
  int overran = 0, judged = 0, offMean = 0, offCount = 0;
  std::string firstOff;
  for (int batch = 0; batch < 12; ++batch) {
    std::vector<std::vector<Color>> sequences;
    for (int k = 0; k < 500; ++k) {
      std::vector<Color> values;
      for (uint32_t i = 0; i < a.maxSpp; ++i) values.push_back(Color(float(-std::log(1.0 - random.uniform()))));
      sequences.push_back(std::move(values));
    }
    const std::vector<candidate::ServedPixel> results =
        candidate::samplePixels(sequences, a, candidate::Serving::AllAtOnce);
    for (size_t k = 0; k < results.size(); ++k) {
      const candidate::ServedPixel& r = results[k];
      overran += r.overran ? 1 : 0;
      estimates.add(double(r.pixel.estimate.x));
      spp += double(r.pixel.samples) / 6000.0;
      const Expected e = expectedStop(sequences[k], a, 1e-6);
      if (e.ambiguous) continue;
      ++judged;
      const bool meanRight = near(Vec3(r.pixel.estimate), Vec3(e.mean), floatMeanTolerance(sequences[k], e.n));
      offMean += meanRight ? 0 : 1;
      offCount += r.pixel.samples == e.n ? 0 : 1;
      if ((!meanRight || r.pixel.samples != e.n) && firstOff.empty()) {
        firstOff = "pixel " + std::to_string(500 * batch + int(k)) + ": the rule stops it at n = " +
                   std::to_string(e.n) + " with mean " + str(Color(e.mean)) + "; yours returned " +
                   str(r.pixel.estimate) + " and said " + std::to_string(r.pixel.samples) + " samples";
      }
    }
  }
  HINT("a pixel kept asking for samples far past settings.maxSpp: stop there whatever the rule says");
  REQUIRE(overran == 0);
  INFO(judged << " pixels judged: " << offMean << " estimates are not the mean of the samples the rule stops at, "
              << offCount << " say another count; the first: " << firstOff);
  HINT("each estimate must be the mean of exactly the samples the pixel took, up to where the rule stops it (the "
       "first whole batch past the minimum where it holds, or the maximum), and pixel.samples that count: an "
       "estimate of every sample up to the maximum, of some other number of them, or of none fails here");
  CHECK(judged > 5900);
  CHECK(offMean == 0);
  CHECK(offCount == 0);
  limitNoise(estimates, "11-adaptive-sampling");
  HINT("the estimates are biased: the estimate must be the plain mean of the samples taken, and the rule checked "
       "only after whole batches past the minimum (checked after every sample, it stops on one sample's luck)");
  INFO("the mean of your 6,000 pixels' estimates: " << estimates.describe(1.0) << "; your pixels say they took "
                                                     << spp << " samples on average");
  CHECK(std::abs(estimates.mean() - 1.0) <= 0.005 + 5.0 * estimates.judgedStandardError());
}

// ---------------------------------------------------------------- images

namespace {

// The Cornell box with a mirror ball and a glass ball: the glass ball's
// caustic and the light's reflections are where the variance is.
Scene adaptiveBox() { return cornellBox(48, 36, 256, 5, true); }

// The image test: tolerance 0.1 and a minimum of 192 of 256 keep the rule's
// bias below what the test can see. The rule's bias is real: with tolerance
// 0.2 and a minimum of 16, wall pixels that had not yet met a bright path
// stopped low, blocks came out 13 % too dark and 16 of 200 seeds failed;
// with a minimum of 128 none failed, but the whole image's |z| averaged 1.98
// over 100 seeds (max 4.83 of a limit of 5.54); at 192 it averages 1.07
// (max 3.70 in 200 seeds), as an unbiased render's does. The samples' test:
// a minimum of 16, so that quiet pixels can show how little they need.
AdaptiveSettings imageSettings() { return settings(0.1, 16, 192, 256); }
AdaptiveSettings mapSettings() { return settings(0.2, 16, 16, 256); }

}  // namespace

TEST_CASE("T11.3 image: an adaptive render of the box with glass agrees with the converged picture" *
          grading(3, "compare your picture with the reference (files named above): too dark where pixels stopped "
                     "early means dividing by the maximum instead of the samples taken; speckled means pixels "
                     "stopped on too few samples (no minimum, or the rule checked after every sample)")) {
  checkImage({"11-adaptive-sampling", "box-adaptive", adaptiveBox(), {.adaptive = imageSettings()}});
}

TEST_CASE("T11.3 image: the samples go where the variance is, not to the flat walls" *
          grading(3, "each pixel's samples must follow its own noise: the caustic under the glass ball and the "
                     "bright reflections need many, a flat lit wall few. Stopping on the colour of one channel, or "
                     "the same count everywhere, fails")) {
  // The judge renders each pixel's samples itself (with the reference) and
  // serves them to your pixels a batch at a time: the counts are what it served.
  const Scene scene = adaptiveBox();
  Scene seeded = scene;
  seeded.indexPrimitives();
  seeded.render.seed = testSeed(17);
  const std::vector<std::vector<Color>> sequences = pixelSamples(seeded, {}, mapSettings().maxSpp);
  const std::vector<candidate::ServedPixel> pixels = candidate::samplePixels(sequences, mapSettings());
  HINT("samplePixels must return one pixel per sequence of samples it was given");
  REQUIRE(pixels.size() == size_t(scene.render.width) * size_t(scene.render.height));
  std::vector<uint32_t> samples;
  int overran = 0;
  for (const candidate::ServedPixel& p : pixels) {
    samples.push_back(p.served);
    overran += p.overran ? 1 : 0;
  }
  INFO(overran << " pixels asked for samples far past the maximum");
  HINT("pixels kept asking for samples far past settings.maxSpp: stop there whatever the rule says");
  REQUIRE(overran == 0);
  // The reference's relative variance per sample, per pixel: the noisiest
  // tenth and the quietest half of the pixels, from the judge's own files.
  const Image mean = readImage(referenceImagePath("11-adaptive-sampling", "box-adaptive", ".exr"));
  const Image variance = readImage(referenceImagePath("11-adaptive-sampling", "box-adaptive", ".variance.exr"));
  HINT("the judge's reference images do not match this scene: a broken installation, not your code (tell the "
       "course staff)");
  REQUIRE(mean.pixels.size() == samples.size());
  std::vector<std::pair<double, size_t>> noise;
  for (size_t i = 0; i < mean.pixels.size(); ++i) {
    const double m = double(luminance(mean.pixels[i])), v = double(luminance(variance.pixels[i]));
    if (m > 1e-4) noise.emplace_back(v / (m * m), i);
  }
  std::sort(noise.begin(), noise.end());
  REQUIRE(noise.size() > 100);
  double quiet = 0.0, noisy = 0.0;
  const size_t half = noise.size() / 2, tenth = noise.size() / 10;
  for (size_t k = 0; k < half; ++k) quiet += double(samples[noise[k].second]) / double(half);
  for (size_t k = noise.size() - tenth; k < noise.size(); ++k) noisy += double(samples[noise[k].second]) / double(tenth);
  INFO("samples per pixel, as the judge served them: " << noisy << " on average in the noisiest tenth of the "
                                                       << "pixels, " << quiet << " in the quietest half");
  const uint32_t fewest = *std::min_element(samples.begin(), samples.end());
  const uint32_t most = *std::max_element(samples.begin(), samples.end());
  INFO("fewest samples in a pixel " << fewest << ", most " << most << " (the minimum is " << mapSettings().minSpp
                                    << ", the maximum " << mapSettings().maxSpp << ")");
  HINT("a pixel took fewer than minSpp or more than maxSpp samples: never stop before the minimum, always at the "
       "maximum");
  CHECK(fewest >= mapSettings().minSpp);
  CHECK(most <= mapSettings().maxSpp);
  HINT("the samples do not follow the noise: each pixel must stop on its own statistics (of luminance(c), not one "
       "channel), so that the caustic and the reflections take many samples and a flat lit wall few; the same count "
       "everywhere fails");
  CHECK(noisy >= 2.0 * quiet);
  CHECK(quiet < 0.75 * double(mapSettings().maxSpp));
}
