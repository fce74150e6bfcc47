// Task 11's remote calls: the judge's view of the student's
// adaptive_sampling.cpp. The judge sends the numbers (sequences of values,
// statistics); the candidate's functions run on them. A pixel's samples are
// served by the judge a batch at a time, only when the candidate's pixel
// asks for them (protocol.h's asks), so the judge counts every pixel's
// samples itself.
#pragma once

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "wire/call.h"
#include "tasks/adaptive_sampling.h"

namespace pathlab::calls {
// For each sequence: the statistics after addSample of every value, and sampleVariance of them.
using Accumulated = std::tuple<RunningStatistics, double /*sampleVariance*/>;

// samplePixelAdaptively on pixels whose samples the judge serves: pixel k
// starts with the samples the request gives it (its sequence), and past
// those sample(i) asks the judge for more from the first it lacks ((k,
// first): two uint32_t); the judge replies with up to a batch of colours
// (zeros past the pixel's sequence), or with none once the pixel has asked
// for far more than its maximum, which stops it.
PATHLAB_REMOTE_CALL(AddSamples, 1, shape::OnePer<0>, std::vector<Accumulated>(std::vector<std::vector<double>>));
PATHLAB_REMOTE_CALL(SampleVariances, 2, shape::OnePer<0>, std::vector<double>(std::vector<RunningStatistics>));
PATHLAB_REMOTE_CALL(ConfidentEnough, 3, shape::OnePer<0>, std::vector<uint8_t>(std::vector<RunningStatistics>, AdaptiveSettings));
PATHLAB_REMOTE_CALL(SamplePixels, 4, shape::OnePer<0>,
                    std::vector<AdaptivePixel>(std::vector<std::vector<Color>> /*given*/, AdaptiveSettings));
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

// One pixel of samplePixelAdaptively over a sequence the judge chose, and
// what the judge saw of it.
struct ServedPixel {
  AdaptivePixel pixel;   // what samplePixelAdaptively returned
  uint32_t served = 0;   // the samples the judge served it (zeros past the sequence included)
  bool overran = false;  // it asked for far more samples than the maximum: the judge stopped it
};

// How the judge serves a pixel's sequence: a batch at a time when asked (at
// most settings.batch, at least one, per ask), so that `served` counts what
// the pixel took; or all of it with the request, where only the pixels'
// answers are judged (one message instead of a round trip per batch).
enum class Serving { WhenAsked, AllAtOnce };

// samplePixelAdaptively for each sequence: sample(i) is sequence[i].
inline std::vector<ServedPixel> samplePixels(const std::vector<std::vector<Color>>& sequences,
                                             const AdaptiveSettings& settings, Serving serving = Serving::WhenAsked) {
  std::vector<ServedPixel> pixels(sequences.size());
  std::vector<std::vector<Color>> given(sequences.size());
  if (serving == Serving::AllAtOnce) {
    given = sequences;
    for (size_t k = 0; k < pixels.size(); ++k) pixels[k].served = uint32_t(sequences[k].size());
  }
  const uint32_t perAsk = std::max(1u, settings.batch);
  const remote::AskHandler serve = [&](const std::string& question) {
    const auto [k, first] = remote::readAsk<uint32_t, uint32_t>(question, "samples");
    if (k >= pixels.size() || first != pixels[k].served) {
      throw remote::CandidateError("the candidate asked for samples from " + std::to_string(first) + " of pixel " +
                                   std::to_string(k) + " (of " + std::to_string(pixels.size()) + ")" +
                                   (k < pixels.size() ? ", whose next is " + std::to_string(pixels[k].served) : ""));
    }
    // Past the sequence (its maximum), zeros; far past it, the pixel is stopped.
    const std::vector<Color>& values = sequences[k];
    const uint64_t limit = 4ull * values.size() + 1024;
    std::vector<Color> batch;
    if (first >= limit) {
      pixels[k].overran = true;
    } else {
      const uint32_t count = uint32_t(std::min<uint64_t>(perAsk, limit - first));
      for (uint32_t i = first; i < first + count; ++i) batch.push_back(i < values.size() ? values[i] : Color(0.0f));
      pixels[k].served += count;
    }
    wire::Writer reply;
    reply.put(batch);
    return reply.bytes();
  };
  const std::vector<AdaptivePixel> answers = remote::callMany<calls::SamplePixels>({{given, settings}}, &serve).front();
  for (size_t k = 0; k < pixels.size(); ++k) pixels[k].pixel = answers[k];
  return pixels;
}
}  // namespace pathlab::candidate
