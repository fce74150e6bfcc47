// attack: an adaptive sampler that takes no sample and returns +1e10 and -1e10 in turn: a mean near 1
// bought with noise, where a test divides by the estimates' own standard error
// task: 11  base: none  expect: 0
#include "tasks/adaptive_sampling.h"

namespace pathlab {

void addSample(RunningStatistics&, double) {}
double sampleVariance(const RunningStatistics&) { return 0.0; }
bool confidentEnough(const RunningStatistics&, const AdaptiveSettings&) { return false; }

AdaptivePixel samplePixelAdaptively(const std::function<Color(uint32_t)>&, const AdaptiveSettings& settings) {
  static int turn = 0;
  AdaptivePixel pixel;
  pixel.estimate = Color(++turn % 2 ? 1e10f : -1e10f);
  pixel.samples = settings.minSpp;
  pixel.confident = true;
  return pixel;
}

}  // namespace pathlab
