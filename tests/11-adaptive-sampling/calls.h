// Task 11's remote calls: the judge's view of the student's
// adaptive_sampling.cpp. The judge sends the numbers (sequences of samples,
// statistics); the candidate's functions run on them.
#pragma once

#include <tuple>
#include <vector>

#include "../remote/call.h"
#include "tasks/adaptive_sampling.h"

namespace pathlab::calls {
// For each sequence: the statistics after addSample of every value, and sampleVariance of them.
using Accumulated = std::tuple<RunningStatistics, double /*sampleVariance*/>;
// One pixel of samplePixelAdaptively over a sequence the judge chose: what it
// returned, and how many samples it asked for (counted by the framework's
// wrapper; past the sequence it stops the pixel and says so).
struct SampledPixel {
  AdaptivePixel pixel;
  uint32_t calls = 0;
  bool overran = false;  // asked for far more samples than the maximum
};

PATHLAB_REMOTE_CALL(AddSamples, 1, shape::OnePer<0>, std::vector<Accumulated>(std::vector<std::vector<double>>));
PATHLAB_REMOTE_CALL(SampleVariances, 2, shape::OnePer<0>, std::vector<double>(std::vector<RunningStatistics>));
PATHLAB_REMOTE_CALL(ConfidentEnough, 3, shape::OnePer<0>, std::vector<uint8_t>(std::vector<RunningStatistics>, AdaptiveSettings));
PATHLAB_REMOTE_CALL(SamplePixels, 4, shape::OnePer<0>, std::vector<SampledPixel>(std::vector<std::vector<Color>>, AdaptiveSettings));
}  // namespace pathlab::calls

namespace pathlab::wire {
template <>
struct Fields<RunningStatistics> {
  static auto tie(RunningStatistics& s) { return std::tie(s.n, s.mean, s.m2); }
};
template <>
struct Fields<AdaptivePixel> {
  static auto tie(AdaptivePixel& s) { return std::tie(s.estimate, s.samples, s.confident); }
};
template <>
struct Fields<calls::SampledPixel> {
  static auto tie(calls::SampledPixel& s) { return std::tie(s.pixel, s.calls, s.overran); }
};
}  // namespace pathlab::wire

namespace pathlab::candidate {
inline std::vector<calls::Accumulated> addSamples(const std::vector<std::vector<double>>& sequences) {
  return remote::call<calls::AddSamples>(sequences);
}
inline std::vector<double> sampleVariances(const std::vector<RunningStatistics>& stats) {
  return remote::call<calls::SampleVariances>(stats);
}
inline std::vector<uint8_t> confidentEnough(const std::vector<RunningStatistics>& stats,
                                            const AdaptiveSettings& settings) {
  return remote::call<calls::ConfidentEnough>(stats, settings);
}
// samplePixelAdaptively for each sequence: sample(i) is sequence[i].
inline std::vector<calls::SampledPixel> samplePixels(const std::vector<std::vector<Color>>& sequences,
                                                     const AdaptiveSettings& settings) {
  return remote::call<calls::SamplePixels>(sequences, settings);
}
}  // namespace pathlab::candidate
