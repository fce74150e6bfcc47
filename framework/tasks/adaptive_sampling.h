// Task 11 — adaptive sampling: each pixel takes samples until its estimate
// is known well enough, in batches, between a minimum and a maximum.
// Implemented in tasks/11-adaptive-sampling/adaptive_sampling.cpp (the
// student's file; where the task is not the student's, the programs link the
// course's reference in its place).
#pragma once

#include <cstdint>
#include <functional>

#include "util/math.h"

namespace pathlab {

// Running statistics of one number per sample (a pixel's luminance): the
// count, the mean, and M2, the sum of squared deviations from the mean.
struct RunningStatistics {
  uint32_t n = 0;
  double mean = 0.0;
  double m2 = 0.0;
};

// T11.1: Welford's update with one more sample x; the sample variance
// M2 / (n - 1) (0 below two samples).
void addSample(RunningStatistics& stats, double x);
double sampleVariance(const RunningStatistics& stats);

// How a pixel samples: in batches of `batch`, at least minSpp and at most
// maxSpp samples (the renderer makes both multiples of batch, minSpp <=
// maxSpp), stopping after a batch once the 95 % confidence interval of the
// mean is narrow enough: 1.96 sigma / sqrt(n) <= tolerance * mean.
// These defaults are task 11's one set: `pathlab --adaptive` takes its
// batch and minimum from them (-s is the maximum), and the handout quotes
// them (CTest task-defaults checks both).
struct AdaptiveSettings {
  double tolerance = 0.05;
  uint32_t batch = 32;
  uint32_t minSpp = 64;
  uint32_t maxSpp = 1024;
};

// The debugger views (and the GUI's task 11 panel) take the defaults above
// but for a looser tolerance and a lower maximum, so that a view renders in
// seconds: a path-traced pixel's spread is often as large as its mean, and
// at 0.05 it would need ~1,500 samples.
constexpr double kAdaptiveViewTolerance = 0.2;
constexpr uint32_t kAdaptiveViewMaxSpp = 256;

// T11.2: whether statistics taken after a whole batch may stop: n >= minSpp
// and 1.96 sigma / sqrt(n) <= tolerance * mean (sigma^2 the sample variance).
bool confidentEnough(const RunningStatistics& stats, const AdaptiveSettings& settings);

// One pixel's result. `confident`: it stopped by the rule (false: at the maximum).
struct AdaptivePixel {
  Color estimate{0.0f};  // the mean of the colours of the samples taken
  uint32_t samples = 0;  // how many were taken
  bool confident = false;
};

// T11.3: one pixel, adaptively. sample(i) returns the pixel's sample i (call
// it with i = 0, 1, 2, ...: each call traces a new path); the statistics
// follow each sample's luminance. Take whole batches; after each, stop if
// confidentEnough; never take more than settings.maxSpp.
AdaptivePixel samplePixelAdaptively(const std::function<Color(uint32_t)>& sample, const AdaptiveSettings& settings);

}  // namespace pathlab
