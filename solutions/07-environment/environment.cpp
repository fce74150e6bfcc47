// Task 7 — environment lighting with importance sampling (reference solution).
#include "tasks/environment.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pathlab {
namespace {

// The index i with cdf[i] <= x < cdf[i + 1] over the n intervals of a CDF of
// n + 1 entries, skipping empty intervals.
int findInterval(const float* cdf, int n, float x) {
  const float* it = std::upper_bound(cdf, cdf + n + 1, x);
  int i = std::clamp(int(it - cdf) - 1, 0, n - 1);
  while (i + 1 < n && cdf[i + 1] <= cdf[i]) ++i;  // never land on a zero-width interval
  while (i > 0 && cdf[i + 1] <= cdf[i]) --i;
  return i;
}

}  // namespace

Point2 directionToEquirect(const Vec3& direction) {
  // Not acos(y): near a pole y = cos(theta) rounds to 1 and theta is lost.
  const float theta = std::atan2(std::sqrt(direction.x * direction.x + direction.z * direction.z), direction.y);
  float phi = std::atan2(direction.z, direction.x);
  if (phi < 0.0f) phi += 2.0f * kPi;
  return {std::min(phi / (2.0f * kPi), 0x1.fffffep-1f), theta / kPi};
}

Vec3 equirectToDirection(Point2 uv) {
  const float phi = 2.0f * kPi * uv.x, theta = kPi * uv.y;
  const float sinTheta = std::sin(theta);
  return {sinTheta * std::cos(phi), std::cos(theta), sinTheta * std::sin(phi)};
}

Color lookupEnvironment(const Image& map, const Vec3& direction) {
  if (map.width == 0 || map.height == 0) return Color(0.0f);
  const Point2 uv = directionToEquirect(direction);
  // Continuous pixel coordinates with pixel centres at integers.
  const float x = uv.x * float(map.width) - 0.5f, y = uv.y * float(map.height) - 0.5f;
  const float x0f = std::floor(x), y0f = std::floor(y);
  const float tx = x - x0f, ty = y - y0f;
  const int x0 = (int(x0f) % map.width + map.width) % map.width;  // wraps at the u seam
  const int x1 = (x0 + 1) % map.width;
  const int y0 = std::clamp(int(y0f), 0, map.height - 1), y1 = std::clamp(int(y0f) + 1, 0, map.height - 1);
  const Color top = glm::mix(map.at(x0, y0), map.at(x1, y0), tx);
  const Color bottom = glm::mix(map.at(x0, y1), map.at(x1, y1), tx);
  return glm::mix(top, bottom, ty);
}

Vec3 sampleUniformSphere(Vec2 u) {
  const float z = 1.0f - 2.0f * u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

EnvironmentDistribution buildEnvironmentDistribution(const Image& map) {
  EnvironmentDistribution d;
  d.width = map.width;
  d.height = map.height;
  d.marginalCdf.assign(size_t(map.height) + 1, 0.0f);
  d.conditionalCdf.assign(size_t(map.height) * size_t(map.width + 1), 0.0f);
  std::vector<double> rowWeight(size_t(map.height), 0.0);
  for (int j = 0; j < map.height; ++j) {
    // sin(theta) at the row's centre: rows near the poles cover less solid angle.
    const double sinTheta = std::sin(std::numbers::pi * (j + 0.5) / map.height);
    float* row = &d.conditionalCdf[size_t(j) * size_t(map.width + 1)];
    double sum = 0.0;
    std::vector<double> prefix(size_t(map.width) + 1, 0.0);
    for (int i = 0; i < map.width; ++i) {
      const double weight = std::max(0.0, double(luminance(map.at(i, j)))) * sinTheta;
      sum += std::isfinite(weight) ? weight : 0.0;
      prefix[size_t(i) + 1] = sum;
    }
    for (int i = 0; i <= map.width; ++i) row[i] = sum > 0.0 ? float(prefix[size_t(i)] / sum) : float(i) / float(map.width);
    rowWeight[size_t(j)] = sum;
    d.totalWeight += sum;
  }
  double running = 0.0;
  for (int j = 0; j < map.height; ++j) {
    running += rowWeight[size_t(j)];
    d.marginalCdf[size_t(j) + 1] = d.totalWeight > 0.0 ? float(running / d.totalWeight) : 0.0f;
  }
  if (d.totalWeight > 0.0) d.marginalCdf.back() = 1.0f;
  return d;
}

std::optional<EnvironmentSample> sampleEnvironment(const EnvironmentDistribution& d, Vec2 u) {
  if (!(d.totalWeight > 0.0) || d.width == 0 || d.height == 0) return std::nullopt;
  // Row by the marginal CDF, then the column by that row's CDF.
  const int j = findInterval(d.marginalCdf.data(), d.height, u.y);
  const float rowStart = d.marginalCdf[size_t(j)], rowWidth = d.marginalCdf[size_t(j) + 1] - rowStart;
  const float* row = &d.conditionalCdf[size_t(j) * size_t(d.width + 1)];
  const int i = findInterval(row, d.width, u.x);
  const float cellStart = row[i], cellWidth = row[i + 1] - cellStart;
  if (!(rowWidth > 0.0f) || !(cellWidth > 0.0f)) return std::nullopt;
  // Re-use the random numbers for a uniform point inside the pixel.
  const float du = std::clamp((u.x - cellStart) / cellWidth, 0.0f, 0x1.fffffep-1f);
  const float dv = std::clamp((u.y - rowStart) / rowWidth, 0.0f, 0x1.fffffep-1f);
  const Point2 uv((float(i) + du) / float(d.width), (float(j) + dv) / float(d.height));
  const float sinTheta = std::sin(kPi * uv.y);
  if (!(sinTheta > 0.0f)) return std::nullopt;  // exactly at a pole
  // p(u, v) over the unit square: the pixel's probability times W * H.
  const float pdfUv = rowWidth * cellWidth * float(d.width) * float(d.height);
  return EnvironmentSample{equirectToDirection(uv), pdfUv / (2.0f * kPi * kPi * sinTheta)};
}

float environmentPdf(const EnvironmentDistribution& d, const Vec3& direction) {
  if (!(d.totalWeight > 0.0) || d.width == 0 || d.height == 0) return 0.0f;
  const Point2 uv = directionToEquirect(direction);
  const int i = std::clamp(int(uv.x * float(d.width)), 0, d.width - 1);
  const int j = std::clamp(int(uv.y * float(d.height)), 0, d.height - 1);
  const float sinTheta = std::sin(kPi * uv.y);
  if (!(sinTheta > 0.0f)) return 0.0f;
  const float rowWidth = d.marginalCdf[size_t(j) + 1] - d.marginalCdf[size_t(j)];
  const float* row = &d.conditionalCdf[size_t(j) * size_t(d.width + 1)];
  const float pdfUv = rowWidth * (row[i + 1] - row[i]) * float(d.width) * float(d.height);
  return pdfUv / (2.0f * kPi * kPi * sinTheta);
}

}  // namespace pathlab
