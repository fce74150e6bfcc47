// The converge bench's arithmetic on error curves: a curve is a strategy's
// error against the reference at growing sample counts and times.
#pragma once

#include <optional>
#include <vector>

#include "util/image.h"

namespace pathlab::bench {

struct Point {
  int spp;         // samples per pixel asked for (adaptive: the maximum)
  double samples;  // samples taken, per pixel
  double seconds, rmse, relMse;
  std::optional<double> efficiency;  // 1 / (relMSE x seconds); none at zero error or time
  double shift;                      // meanBlockShift against the reference
};

// The image's systematic error, which relMSE mixes with the noise: the mean
// over blocks (a fifteenth of the shorter side: 40 pixels at 800x600) of
// each block's relative shift in luminance against the reference. The noise
// averages out over a block and then over the blocks, so an unbiased
// strategy's shift is 0 to a fraction of a percent; a strategy that darkens
// what it has not seen yet (task 11's stopping rule) shows, even when its
// relMSE is lower (relMSE rewards a darkened firefly).
double meanBlockShift(const Image& image, const Image& reference);

// 1 / (relMSE x seconds); none at zero error or time.
std::optional<double> efficiencyOf(double relMse, double seconds);

// The least-squares slope of log relMSE against log spp: -1 for independent
// samples (plain Monte Carlo), below -1 where low-discrepancy samples pay off.
std::optional<double> convergenceSlope(const std::vector<Point>& curve);

// A curve at render time `seconds`: its relMSE straight between the two
// points around it in log time and log error (where plain Monte Carlo is a
// line of slope -1), its shift straight in log time; none when the curve does
// not reach that far on both sides.
struct AtTime {
  double relMse = 0.0, shift = 0.0;
};
std::optional<AtTime> curveAtTime(const std::vector<Point>& curve, double seconds);

}  // namespace pathlab::bench
