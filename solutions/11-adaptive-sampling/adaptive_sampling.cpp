// Task 11 — adaptive sampling (reference solution).
#include "tasks/adaptive_sampling.h"

#include <cmath>

namespace pathlab {

void addSample(RunningStatistics& stats, double x) {
  // Welford: the mean moves by delta / n; M2 grows by the product of the
  // deviations from the old and the new mean (no sum of squares to cancel).
  ++stats.n;
  const double delta = x - stats.mean;
  stats.mean += delta / double(stats.n);
  stats.m2 += delta * (x - stats.mean);
}

double sampleVariance(const RunningStatistics& stats) { return stats.n > 1 ? stats.m2 / double(stats.n - 1) : 0.0; }

bool confidentEnough(const RunningStatistics& stats, const AdaptiveSettings& settings) {
  if (stats.n < settings.minSpp) return false;
  const double halfWidth = 1.96 * std::sqrt(sampleVariance(stats) / double(stats.n));
  return halfWidth <= settings.tolerance * stats.mean;
}

AdaptivePixel samplePixelAdaptively(const std::function<Color(uint32_t)>& sample, const AdaptiveSettings& settings) {
  RunningStatistics stats;
  glm::dvec3 sum(0.0);
  AdaptivePixel pixel;
  while (stats.n < settings.maxSpp && !pixel.confident) {
    for (uint32_t k = 0; k < settings.batch && stats.n < settings.maxSpp; ++k) {
      const Color c = sample(stats.n);
      sum += glm::dvec3(c);
      addSample(stats, double(luminance(c)));
    }
    pixel.confident = confidentEnough(stats, settings);
  }
  pixel.samples = stats.n;
  if (stats.n > 0) pixel.estimate = Color(sum / double(stats.n));
  return pixel;
}

}  // namespace pathlab
