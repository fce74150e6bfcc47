// The candidate's side of task 11's calls: the linked adaptive_sampling.cpp.
#include <stdexcept>

#include "wire/server.h"
#include "serve_images.h"
#include "calls.h"

namespace pathlab::remote {
namespace {

// Thrown by a pixel's sample function when the judge serves no more (the
// pixel asked for far more samples than its maximum: a loop with no
// maximum): the pixel stops there.
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
  server.serve<calls::SamplePixels>([](const std::vector<std::vector<Color>>& given, const AdaptiveSettings& settings) {
    std::vector<AdaptivePixel> results;
    for (uint32_t k = 0; k < given.size(); ++k) {
      std::vector<Color> served = given[k];  // pixel k's samples, as far as the judge has served them
      const auto sample = [&](uint32_t i) {
        while (i >= served.size()) {
          wire::Writer question;
          question.put(k);
          question.put(uint32_t(served.size()));
          const std::vector<Color> batch = wire::Reader(ask(question.bytes())).get<std::vector<Color>>();
          if (batch.empty()) throw Overrun{};
          served.insert(served.end(), batch.begin(), batch.end());
        }
        return served[i];
      };
      AdaptivePixel pixel;
      try {
        pixel = samplePixelAdaptively(sample, settings);
      } catch (const Overrun&) {
      }
      results.push_back(pixel);
    }
    return results;
  });
}

}  // namespace pathlab::remote
