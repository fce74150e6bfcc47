// Task 11's visual debugger (students don't edit this file: it shows what
// their adaptive_sampling.cpp does).
//   spp     the scene rendered adaptively by your samplePixelAdaptively,
//           beside its samples-per-pixel map (colour: log2 of the count,
//           from the minimum to the maximum) and why each pixel stopped
//           (green: the rule, darker for more samples; red: the maximum).
//   pixel   the inspected pixel's samples one by one: the running mean
//           (your Welford statistics), its 95 % confidence interval
//           (1.96 sigma / sqrt n), the band the rule asks it to fit in
//           (tolerance x mean), the checks after each batch, and where
//           your samplePixelAdaptively stopped.
// The views sample with tolerance 0.2, batches of 16, 16 to 256 samples per
// pixel.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "render/render.h"
#include "render/task_wiring.h"
#include "tasks/adaptive_sampling.h"

namespace pathlab {
namespace {

// Task 11's defaults, with the views' tolerance and maximum (adaptive_sampling.h).
AdaptiveSettings viewSettings() {
  AdaptiveSettings a;
  a.tolerance = kAdaptiveViewTolerance;
  a.maxSpp = kAdaptiveViewMaxSpp;
  return a;
}

DebugOutput sppView(const DebugViewRequest& request) {
  Scene scene = request.scene;
  scene.render.width = std::max(8, request.width / 2);
  scene.render.height = std::max(8, request.height / 2);
  const AdaptiveSettings settings = viewSettings();
  RenderOptions options;
  options.progress = false;
  options.threads = request.threads;
  options.adaptive = settings;
  const RenderResult result = render(scene, options);
  const SampleMap& map = result.sampleMap;
  const int w = scene.render.width, h = scene.render.height;
  Image why(w, h);
  size_t confident = 0;
  for (size_t i = 0; i < map.samples.size(); ++i) {
    const float t = std::log2(float(std::max(1u, map.samples[i])) / float(settings.minSpp)) /
                    std::max(1.0f, std::log2(float(settings.maxSpp) / float(settings.minSpp)));
    if (map.confident[i]) ++confident;
    why.pixels[i] = map.confident[i] ? Color(0.05f, 0.9f - 0.7f * t, 0.1f) : Color(0.9f, 0.05f, 0.05f);
  }
  TileSheet sheet(3, 1, w, h);
  sheet.place(result.image, 0, "ADAPTIVE RENDER");
  char label[48];
  std::snprintf(label, sizeof label, "SPP %u-%u (LOG)", settings.minSpp, settings.maxSpp);
  sheet.place(sampleMapImage(map, settings.minSpp, settings.maxSpp), 1, label);
  sheet.place(why, 2, "GREEN RULE, RED MAX");
  char report[256];
  std::snprintf(report, sizeof report,
                "tolerance %.3g, batches of %u, %u to %u spp: mean %.1f spp (uniform sampling at the maximum: %u), "
                "%.1f %% of pixels stopped by the rule, %.1f %% at the maximum; %.2f s\n",
                settings.tolerance, settings.batch, settings.minSpp, settings.maxSpp,
                double(result.stats.samples) / double(map.samples.size()), settings.maxSpp,
                100.0 * double(confident) / double(map.samples.size()),
                100.0 * double(map.samples.size() - confident) / double(map.samples.size()), result.stats.seconds);
  return {sheet.image(), report};
}

DebugOutput pixelView(const DebugViewRequest& request) {
  const Scene& scene = request.scene;
  const AdaptiveSettings settings = viewSettings();
  const IVec2 pixel = request.inspectedPixel();
  // The pixel's samples, as the renderer takes them, recorded as your code asks for them.
  const Accelerator accelerator(scene);
  const Lights lights = Lights::fromScene(scene, kLinkedTasks.environment, EnvironmentSampling::Importance);
  const CameraBasis basis = cameraBasis(scene.camera);
  TraceContext context(scene, accelerator, lights, kLinkedTasks.lobes);
  context.pixel = pixel;
  RenderOptions options;
  std::vector<double> values;
  const auto sample = [&](uint32_t i) {
    Color c = estimatePixelSample(context, options, basis, i);
    if (!isFinite(c)) c = Color(0.0f);
    values.push_back(double(luminance(c)));
    return c;
  };
  const AdaptivePixel result = samplePixelAdaptively(sample, settings);

  // The running statistics of those samples by your addSample and sampleVariance.
  const int n = int(values.size());
  std::vector<double> means, halves;
  RunningStatistics stats;
  for (double x : values) {
    addSample(stats, x);
    means.push_back(stats.mean);
    halves.push_back(1.96 * std::sqrt(std::max(0.0, sampleVariance(stats)) / double(std::max(1u, stats.n))));
  }
  const int width = std::max(200, request.width), height = std::max(150, request.height);
  Image image(width, height, Color(0.02f));
  const float left = 50.0f, right = float(width) - 10.0f, top = 30.0f, bottom = float(height) - 30.0f;
  double lo = 0.0, hi = 1e-6;
  for (int i = std::min(n, int(settings.batch)) - 1; i < n; ++i) {  // skip the wild first few
    if (i < 0) continue;
    hi = std::max({hi, means[size_t(i)] + halves[size_t(i)], means[size_t(i)] * (1.0 + settings.tolerance)});
    lo = std::min({lo, means[size_t(i)] - halves[size_t(i)]});
  }
  // Up to twice where the pixel stopped (at most the maximum): a short run fills the plot too.
  const double xMax = double(std::min(settings.maxSpp, std::max(4 * settings.batch, 2 * uint32_t(n))));
  const auto at = [&](double k, double v) {
    const double y = std::clamp((v - lo) / (hi - lo), -0.05, 1.05);
    return Point2(left + float(k / xMax) * (right - left), bottom - float(y) * (bottom - top));
  };
  drawRectOutline(image, Point2(left, top), Point2(right, bottom), Color(0.3f));
  for (uint32_t k = settings.batch; k <= uint32_t(xMax); k += settings.batch) {  // the checks
    const Color tick = k < settings.minSpp ? Color(0.15f) : Color(0.3f, 0.3f, 0.45f);
    drawLine(image, at(k, lo), at(k, lo) - Point2(0.0f, 6.0f), tick);
  }
  for (int i = 1; i < n; ++i) {
    const double a = double(i), b = double(i + 1);
    drawLine(image, at(a, means[size_t(i - 1)] * (1.0 + settings.tolerance)), at(b, means[size_t(i)] * (1.0 + settings.tolerance)),
             Color(0.2f, 0.6f, 0.2f));
    drawLine(image, at(a, means[size_t(i - 1)] * (1.0 - settings.tolerance)), at(b, means[size_t(i)] * (1.0 - settings.tolerance)),
             Color(0.2f, 0.6f, 0.2f));
    drawLine(image, at(a, means[size_t(i - 1)] + halves[size_t(i - 1)]), at(b, means[size_t(i)] + halves[size_t(i)]),
             Color(0.3f, 0.6f, 1.0f));
    drawLine(image, at(a, means[size_t(i - 1)] - halves[size_t(i - 1)]), at(b, means[size_t(i)] - halves[size_t(i)]),
             Color(0.3f, 0.6f, 1.0f));
    drawLine(image, at(a, means[size_t(i - 1)]), at(b, means[size_t(i)]), Color(0.95f));
  }
  if (n > 0) {
    const Point2 stop = at(double(result.samples), double(luminance(result.estimate)));
    drawLine(image, Point2(stop.x, top), Point2(stop.x, bottom), result.confident ? Color(0.2f, 0.9f, 0.2f) : Color(0.9f, 0.1f, 0.1f));
  }
  drawText(image, Point2(4.0f, 6.0f), "MEAN (WHITE), 95% INTERVAL (BLUE), TOLERANCE (GREEN)", Color(0.85f), 1);
  char axis[64];
  std::snprintf(axis, sizeof axis, "0 TO %u SAMPLES", uint32_t(xMax));
  drawText(image, Point2(left, bottom + 10.0f), axis, Color(0.7f), 1);

  char report[320];
  std::snprintf(report, sizeof report,
                "pixel %d,%d: your samplePixelAdaptively took %d samples (it said %u) and stopped %s; estimate "
                "luminance %.4g; at the stop the 95 %% half-width is %.3g against tolerance x mean %.3g "
                "(checks every %u samples from %u)\n",
                pixel.x, pixel.y, n, result.samples, result.confident ? "by the rule" : "at the maximum",
                double(luminance(result.estimate)), n > 0 ? halves.back() : 0.0,
                n > 0 ? settings.tolerance * means.back() : 0.0, settings.batch, settings.minSpp);
  return {image, report};
}

}  // namespace

void addAdaptiveSamplingViews(std::vector<DebugView>& views) {
  views.push_back({11, "spp", "an adaptive render, its samples-per-pixel map, and why each pixel stopped", sppView});
  views.push_back({11, "pixel", "the inspected pixel's running mean, its 95 % interval and the rule's band, sample by sample",
                   pixelView, kUsesPixel});
}

}  // namespace pathlab
