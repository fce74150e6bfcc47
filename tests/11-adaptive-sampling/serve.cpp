// The candidate's side of task 11's calls: the linked adaptive_sampling.cpp.
#include <stdexcept>

#include "../remote/server.h"
#include "../remote/serve_images.h"
#include "calls.h"

namespace pathlab::remote {
namespace {

// Thrown by a pixel's sample function when the pixel asks for far more
// samples than its maximum (a loop with no maximum): the pixel stops there.
struct Overrun {};

}  // namespace

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::AddSamples>([](const std::vector<std::vector<double>>& sequences) {
    std::vector<calls::Accumulated> results;
    for (const std::vector<double>& values : sequences) {
      RunningStatistics stats;
      for (double x : values) addSample(stats, x);
      results.emplace_back(stats, sampleVariance(stats));
    }
    return results;
  });
  server.serve<calls::SampleVariances>([](const std::vector<RunningStatistics>& all) {
    std::vector<double> variances;
    for (const RunningStatistics& stats : all) variances.push_back(sampleVariance(stats));
    return variances;
  });
  server.serve<calls::ConfidentEnough>([](const std::vector<RunningStatistics>& all, const AdaptiveSettings& settings) {
    std::vector<uint8_t> verdicts;
    for (const RunningStatistics& stats : all) verdicts.push_back(confidentEnough(stats, settings) ? 1 : 0);
    return verdicts;
  });
  server.serve<calls::SamplePixels>([](const std::vector<std::vector<Color>>& sequences, const AdaptiveSettings& settings) {
    std::vector<calls::SampledPixel> results;
    for (const std::vector<Color>& values : sequences) {
      calls::SampledPixel result;
      // Past the judge's sequence (its maximum), zeros; far past it, the pixel is stopped.
      const uint64_t limit = 4ull * values.size() + 1024;
      const auto sample = [&](uint32_t i) {
        if (++result.calls > limit) throw Overrun{};
        return i < values.size() ? values[i] : Color(0.0f);
      };
      try {
        result.pixel = samplePixelAdaptively(sample, settings);
      } catch (const Overrun&) {
        result.overran = true;
      }
      results.push_back(result);
    }
    return results;
  });
}

}  // namespace pathlab::remote
