// Task 7's visual debugger (students don't edit this file: it shows what
// their environment.cpp does with the scene's environment map).
//   samples       the map (tone-mapped) with 2,000 importance samples drawn on it
//   pdf           the sampling pdf per pixel (solid angle, log scale)
//   marginal-cdf  the marginal CDF over rows, plotted
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "tasks/environment.h"
#include "util/random.h"

namespace pathlab {
namespace {

// The scene's map, or a message image when it has none.
const Image* environmentMap(const DebugViewRequest& request, DebugOutput& output) {
  if (request.scene.environment && request.scene.environment->image.width > 0) return &request.scene.environment->image;
  output.image = Image(request.width, 40, Color(0.02f));
  drawText(output.image, Point2(6, 12), "NO ENVIRONMENT MAP IN THIS SCENE", Color(0.9f), 2);
  output.report = "the scene has no environment image (\"environment\": {\"image\": ...})\n";
  return nullptr;
}

// The map scaled to the requested width, tone-mapped x / (1 + x).
Image toneMapped(const Image& map, int width) {
  const int height = std::max(1, width / 2);
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Color c = map.at(x * map.width / width, y * map.height / height);
      image.at(x, y) = c / (Color(1.0f) + c);
    }
  return image;
}

DebugOutput samplesView(const DebugViewRequest& request) {
  DebugOutput output;
  const Image* map = environmentMap(request, output);
  if (!map) return output;
  const EnvironmentDistribution distribution = buildEnvironmentDistribution(*map);
  output.image = toneMapped(*map, std::max(400, request.width));
  constexpr int kSamples = 2000;
  int drawn = 0;
  for (int i = 0; i < kSamples; ++i) {
    Sampler sampler(uint32_t(i), 0, 5);
    std::optional<EnvironmentSample> s = sampleEnvironment(distribution, sampler.next2D());
    if (!s) continue;
    const Point2 uv = directionToEquirect(s->direction);
    drawDot(output.image, Point2(uv.x * float(output.image.width), uv.y * float(output.image.height)), 1.5f,
            Color(1.0f, 0.1f, 0.1f));
    ++drawn;
  }
  char report[96];
  std::snprintf(report, sizeof report, "%d of %d importance samples drawn (red)\n", drawn, kSamples);
  output.report = report;
  return output;
}

DebugOutput pdfView(const DebugViewRequest& request) {
  DebugOutput output;
  const Image* map = environmentMap(request, output);
  if (!map) return output;
  const EnvironmentDistribution distribution = buildEnvironmentDistribution(*map);
  const int width = std::max(400, request.width), height = width / 2;
  output.image = Image(width, height);
  std::vector<float> pdf(size_t(width) * size_t(height));
  float lo = kInfinity, hi = 0.0f;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Point2 uv((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height));
      const float p = environmentPdf(distribution, equirectToDirection(uv));
      pdf[size_t(y) * size_t(width) + size_t(x)] = p;
      if (p > 0.0f) lo = std::min(lo, p), hi = std::max(hi, p);
    }
  for (size_t i = 0; i < pdf.size(); ++i) {
    // log scale between the smallest and largest non-zero pdf
    output.image.pixels[i] = pdf[i] > 0.0f && hi > lo ? colorMap(std::log(pdf[i] / lo) / std::log(hi / lo))
                                                      : Color(0.0f);
  }
  char report[128];
  std::snprintf(report, sizeof report, "pdf (per steradian) from %.3g to %.3g, log colour scale\n", lo, hi);
  output.report = report;
  return output;
}

DebugOutput marginalCdfView(const DebugViewRequest& request) {
  DebugOutput output;
  const Image* map = environmentMap(request, output);
  if (!map) return output;
  const EnvironmentDistribution distribution = buildEnvironmentDistribution(*map);
  const int width = std::max(400, request.width), height = std::max(300, request.height);
  output.image = Image(width, height, Color(0.02f));
  const float left = 40, right = float(width) - 20, top = 30, bottom = float(height) - 40;
  const Color axis(0.6f), curve(0.2f, 0.8f, 1.0f), text(0.9f);
  drawLine(output.image, {left, bottom}, {right, bottom}, axis);
  drawLine(output.image, {left, bottom}, {left, top}, axis);
  const size_t n = distribution.marginalCdf.size();
  for (size_t j = 1; j < n; ++j) {
    auto point = [&](size_t k) {
      return Point2(left + (right - left) * float(k) / float(n - 1), bottom - (bottom - top) * distribution.marginalCdf[k]);
    };
    drawLine(output.image, point(j - 1), point(j), curve);
  }
  drawText(output.image, {left, 8}, "MARGINAL CDF OVER ROWS", text, 2);
  drawText(output.image, {left - 20, top - 4}, "1", text, 2);
  drawText(output.image, {left - 20, bottom - 10}, "0", text, 2);
  drawText(output.image, {left, bottom + 10}, "ZENITH", text, 2);
  drawText(output.image, {right - 60, bottom + 10}, "NADIR", text, 2);
  drawText(output.image, {(left + right) / 2 - 18, bottom + 10}, "ROW", text, 2);
  output.report = "marginal CDF: " + std::to_string(n - 1) + " rows\n";
  return output;
}

}  // namespace

void addEnvironmentViews(std::vector<DebugView>& views) {
  views.push_back({7, "samples", "the environment map with 2,000 importance samples", samplesView});
  views.push_back({7, "pdf", "the importance sampling pdf over the map (log scale)", pdfView});
  views.push_back({7, "marginal-cdf", "the marginal CDF over the map's rows", marginalCdfView});
}

}  // namespace pathlab
