// Task 11 — adaptive sampling
//
// Goal: spend samples where the error is. A flat, evenly lit wall is known
// to 5 % after a few dozen samples; a caustic under a glass ball needs
// thousands. Each pixel keeps running statistics of its samples and stops,
// batch by batch, once a 95 % confidence interval says its mean is known
// well enough. Handout: tasks/11-adaptive-sampling/README.md
//
// Functions to write (declared in framework/tasks/adaptive_sampling.h):
//   T11.1 addSample, sampleVariance    Welford's running mean and variance
//   T11.2 confidentEnough              the stopping rule
//   T11.3 samplePixelAdaptively        one pixel: batches, the rule, the estimate
//
// Check your work:
//   ./build/pathlab media/scenes/cornell-mirror-glass.json --adaptive 0.05 -s 1024 -o adaptive.png
//   ./build/pathlab debug --task 11 --view spp media/scenes/cornell-mirror-glass.json -o spp.png
//   ctest --test-dir build -R 11-adaptive-sampling --output-on-failure
#include "tasks/adaptive_sampling.h"

#include <cmath>

#include "util/todo.h"

namespace pathlab {

// T11.1 — Running statistics (Welford, 1962).
//
// The mean of n samples and their sample variance
//   mean = (1/n) sum x_k,     s^2 = (1/(n-1)) sum (x_k - mean)^2
// need every sample, or sums of x and x^2, whose difference loses all its
// digits when the mean is large against the spread (1e8 + 0.001: the sums
// agree in every digit a double has). Welford updates the mean and
// M2 = sum (x_k - mean)^2 with each new sample instead:
//   n     <- n + 1
//   delta  = x - mean            (the old mean)
//   mean  <- mean + delta / n
//   M2    <- M2 + delta * (x - mean)     (the new mean)
// The sample variance divides M2 by n - 1, not n: the mean was estimated
// from the same samples, which leaves n - 1 degrees of freedom (dividing by
// n is biased low, by a factor (n-1)/n). Below two samples it is 0.
void addSample(RunningStatistics& stats, double x) {
  // TODO(T11.1): Welford's update.
  PATHLAB_TODO("T11.1");
  (void)stats, (void)x;
}

double sampleVariance(const RunningStatistics& stats) {
  // TODO(T11.1): M2 / (n - 1).
  PATHLAB_TODO("T11.1");
  (void)stats;
  return 0.0;
}

// T11.2 — The stopping rule.
//
// By the central limit theorem the mean of n samples is about normal with
// standard deviation sigma / sqrt(n); with 95 % confidence the true mean is
// within I = 1.96 sigma / sqrt(n) of it. A pixel may stop once
//   n >= settings.minSpp   and   I <= settings.tolerance * mean
// (sigma^2: the sample variance). The minimum matters twice: sigma itself
// is an estimate, wild after a handful of samples (four samples that all
// missed a small light say sigma = 0), and it bounds the rule's bias (the
// handout explains).
//
// PITFALL: a dark pixel (mean near 0) must not stop on a tolerance of 0 *
// mean: with any spread it never does, and runs to the maximum.
bool confidentEnough(const RunningStatistics& stats, const AdaptiveSettings& settings) {
  // TODO(T11.2): the rule.
  PATHLAB_TODO("T11.2");
  (void)stats, (void)settings;
  return false;
}

// T11.3 — One pixel, adaptively.
//
//   repeat while fewer than settings.maxSpp samples were taken:
//     take a batch of settings.batch samples: c = sample(i) for the next i
//       (0, 1, 2, ...), add c to the colour sum, and luminance(c) to the
//       statistics
//     if confidentEnough(statistics): stop (confident)
//   estimate = colour sum / the number of samples taken
//
// The rule is checked after whole batches only: checked after every
// sample, it would stop at the first lucky sample, and every check is one
// more chance for the noise to look small (the bias grows with the checks).
// settings.maxSpp is a multiple of the batch, and the last word: a pixel
// that never converges (a firefly in a dark corner) stops there.
//
// PITFALL: divide by the samples this pixel took, not by settings.maxSpp;
// report that count in `samples` (the renderer's samples-per-pixel map).
AdaptivePixel samplePixelAdaptively(const std::function<Color(uint32_t)>& sample, const AdaptiveSettings& settings) {
  // TODO(T11.3): batches, the rule, the estimate.
  PATHLAB_TODO("T11.3");
  (void)sample, (void)settings;
  return {};
}

}  // namespace pathlab
