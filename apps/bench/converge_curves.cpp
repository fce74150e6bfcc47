#include "converge_curves.h"

#include <algorithm>
#include <cmath>

#include "util/math.h"

namespace pathlab::bench {

double meanBlockShift(const Image& image, const Image& reference) {
  const int size = std::max(1, std::min(reference.width, reference.height) / 15);
  double sum = 0.0;
  int blocks = 0;
  for (int y0 = 0; y0 + size <= reference.height; y0 += size) {
    for (int x0 = 0; x0 + size <= reference.width; x0 += size) {
      double ours = 0.0, theirs = 0.0;
      for (int y = y0; y < y0 + size; ++y) {
        for (int x = x0; x < x0 + size; ++x) {
          ours += luminance(image.at(x, y));
          theirs += luminance(reference.at(x, y));
        }
      }
      if (!(theirs > 1e-6 * size * size)) continue;  // a black block has no relative shift
      sum += ours / theirs - 1.0;
      ++blocks;
    }
  }
  return blocks > 0 ? sum / blocks : 0.0;
}

std::optional<double> efficiencyOf(double relMse, double seconds) {
  if (!(relMse > 0.0) || !(seconds > 0.0) || !std::isfinite(relMse)) return std::nullopt;
  return 1.0 / (relMse * seconds);
}

std::optional<double> convergenceSlope(const std::vector<Point>& curve) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const Point& p : curve) {
    if (!(p.relMse > 0.0) || !std::isfinite(p.relMse)) continue;
    const double x = std::log(p.samples), y = std::log(p.relMse);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double denominator = n * sxx - sx * sx;
  if (n < 3 || !(denominator > 0.0)) return std::nullopt;
  return (n * sxy - sx * sy) / denominator;
}

std::optional<AtTime> curveAtTime(const std::vector<Point>& curve, double seconds) {
  for (size_t k = 0; k + 1 < curve.size(); ++k) {
    const Point &a = curve[k], &b = curve[k + 1];
    if (!(a.seconds <= seconds && seconds <= b.seconds)) continue;
    if (!(a.relMse > 0.0 && b.relMse > 0.0 && a.seconds > 0.0) || b.seconds == a.seconds) return std::nullopt;
    const double f = std::log(seconds / a.seconds) / std::log(b.seconds / a.seconds);
    return AtTime{std::exp(std::log(a.relMse) + f * std::log(b.relMse / a.relMse)), a.shift + f * (b.shift - a.shift)};
  }
  return std::nullopt;
}

}  // namespace pathlab::bench
