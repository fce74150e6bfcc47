// Statistics for the autograder: means with standard errors, and Pearson's
// chi-square goodness-of-fit test (util/chi_square.h) with failure pictures.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "failure_pictures.h"
#include "util/chi_square.h"
#include "util/math.h"

namespace pathlab::test {

// With PATHLAB_NOISE_CATALOG=FILE, appends "<test case>\t<why>" to FILE:
// which ceiling each judged statistic of each test has (tools/grader-validity
// writes the catalogue from it). reference_noise.cpp.
void noteNoiseCeiling(const char* why);

// Running mean and variance (Welford), per colour channel collapsed to one
// number by the caller.
class MeanEstimate {
 public:
  void add(double x) {
    min_ = n_ == 0 ? x : std::min(min_, x);
    max_ = n_ == 0 ? x : std::max(max_, x);
    ++n_;
    const double delta = x - mean_;
    mean_ += delta / double(n_);
    m2_ += delta * (x - mean_);
  }
  // A grey scene's radiance, as the mean of its three channels, which must
  // agree: a correct estimator treats them alike there (one channel alone,
  // as these tests once took, let 1 in green and 0 elsewhere pass "L = 1";
  // an average alone, a red that makes up for a blue). An answer whose
  // channels differ is counted, and makes the mean NaN.
  void addGrey(const Color& c) {
    const double r = c.x, g = c.y, b = c.z, mean = (r + g + b) / 3.0;
    const double spread = std::max({std::abs(r - mean), std::abs(g - mean), std::abs(b - mean)});
    if (!(spread <= 1e-4 * std::abs(mean) + 1e-6)) ++unequalChannels_;
    add(mean);
  }
  size_t count() const { return n_; }
  // NaN, which no comparison passes, once an answer's channels differed.
  double mean() const { return unequalChannels_ == 0 ? mean_ : std::numeric_limits<double>::quiet_NaN(); }
  double variance() const { return n_ > 1 ? m2_ / double(n_ - 1) : 0.0; }
  double standardError() const { return n_ > 0 ? std::sqrt(variance() / double(n_)) : 0.0; }

  // Every sample exactly v (e.g. no light at all: not a mean of 0 from
  // +1e10 and -1e10).
  bool allExactly(double v) const { return n_ > 0 && unequalChannels_ == 0 && min_ == v && max_ == v; }

  // The largest variance per sample a correct estimator can have here
  // (reference_noise.h): the checks judge the mean with at most this much
  // noise, so that noise cannot buy a pass. (Not a hard limit: a correct
  // estimator's sample variance can jump with one rare, large sample.)
  // Every mean that is judged has one (by construction: judgedStandardError
  // and agrees refuse to judge without it, so a new test that forgets it
  // fails on the reference at once). `why` says where it comes from, for
  // docs/grader-validity.md's catalogue (noteNoiseCeiling).
  void setVarianceCeiling(double ceiling, const char* why) {
    ceiling_ = ceiling;
    capped_ = true;
    noteNoiseCeiling(why);
  }
  // Only where what is measured is the framework's own code, never a
  // candidate's answer (tests/framework): its noise is judged as it is. The
  // suites may not call this (suites-call-the-candidate checks).
  void judgeByOwnNoise() { setVarianceCeiling(kInfinity, "none: the framework's own code"); }
  bool tooNoisy() const { return !(variance() <= ceiling_); }
  double judgedStandardError() const {
    if (!capped_) {
      throw std::logic_error("a mean judged by its own noise with no ceiling on it: the test must call limitNoise or "
                             "setVarianceCeiling first (tests/support/reference_noise.h)");
    }
    return n_ > 0 ? std::sqrt(std::min(variance(), ceiling_) / double(n_)) : 0.0;
  }

  // |mean - expected| within `sigmas` standard errors, the estimator's own
  // but at most the ceiling's (plus a tiny absolute slack for zero-variance
  // estimators). Five sigma: a correct estimator fails with probability
  // 5.7e-7 per check.
  bool agrees(double expected, double sigmas = 5.0) const {
    return std::abs(mean() - expected) <= sigmas * judgedStandardError() + 1e-6 * std::max(1.0, std::abs(expected));
  }
  std::string describe(double expected) const {
    std::ostringstream s;
    s << "mean " << mean_ << " +- " << standardError() << " (1 sigma, " << n_ << " samples), expected " << expected
      << ", off by " << (standardError() > 0 ? std::abs(mean_ - expected) / standardError() : 0.0) << " sigma";
    if (unequalChannels_ > 0) {
      s << "; " << unequalChannels_ << " answers have channels that differ, in a grey scene where a correct estimate "
        << "has all three alike";
    }
    if (tooNoisy()) {
      s << "; its variance per sample, " << variance() << ", is above " << ceiling_
        << ", the most a correct estimator has here, so it is judged with " << judgedStandardError()
        << " (samples that are huge, or of the wrong sign?)";
    }
    return s.str();
  }

 private:
  size_t n_ = 0, unequalChannels_ = 0;
  double mean_ = 0.0, m2_ = 0.0;
  double min_ = 0.0, max_ = 0.0;
  double ceiling_ = kInfinity;
  bool capped_ = false;
};

// The test itself and the direction histogram: util/chi_square.h (shared
// with the sampling lab and the demos).
using pathlab::ChiSquareResult;
using pathlab::chiSquareTest;
using pathlab::DirectionHistogram;
using pathlab::upperIncompleteGamma;

// The chi-square test of a direction histogram against the expected counts;
// when it fails (a hard failure, or p <= pLimit) or PATHLAB_IMAGE_PICTURES is
// "always", `pictures` names pictures of the (phi, cos theta) map: observed,
// expected and their difference (failure_pictures.h), saved as NAME-*.
inline ChiSquareResult chiSquareOfDirections(const std::string& name, const DirectionHistogram& histogram,
                                             const std::vector<double>& expected, double pLimit) {
  ChiSquareResult r = chiSquareTest(histogram.counts, expected);
  if (!r.failure.empty() || !(r.pValue > pLimit) || picturesAlways()) {
    r.pictures = writeHistogramPictures(name, histogram.counts, expected, DirectionHistogram::kPhi,
                                        DirectionHistogram::kCos, "phi cell", "cos-theta cell");
  }
  return r;
}

}  // namespace pathlab::test
