// Task 5's visual debugger (students don't edit this file: it shows what
// their path_tracing.cpp does).
//   bounces  the light that arrives after exactly 0, 1, 2, ... bounces,
//            side by side, and the full image. Bounce k is the difference
//            of renders with -m k and -m k-1: paths use the same random
//            numbers, so a shorter path is the start of a longer one.
//   paths    the inspected pixel's first 8 paths drawn in the scene:
//            bounce segments coloured by bounce (camera ray white), shadow
//            rays green (reached the light) or red (blocked); every ray,
//            hit, BSDF sample and light sample listed in the report. The
//            GUI draws them from an orbiting viewpoint.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "debug/inspect.h"
#include "render/render.h"
#include "render/task_wiring.h"

namespace pathlab {
namespace {

DebugOutput bouncesView(const DebugViewRequest& request) {
  constexpr int kBounces = 5;  // tiles: bounce 0..4 and the full image
  constexpr int kColumns = 3;
  // Each tile at half the requested size.
  const int width = std::max(8, request.width / 2), height = std::max(8, request.height / 2);
  Scene scene = request.scene;
  scene.render.width = width;
  scene.render.height = height;
  RenderOptions options;
  options.progress = false;
  options.threads = request.threads;

  std::vector<Image> cumulative;
  for (int depth = 0; depth < kBounces; ++depth) {
    scene.render.maxDepth = depth;
    cumulative.push_back(render(scene, options).image);
  }
  scene.render.maxDepth = request.scene.render.maxDepth;
  const Image full = render(scene, options).image;

  Image sheet(kColumns * width, 2 * (height + 20), Color(0.02f));
  std::string report = "mean radiance per bounce:";
  auto place = [&](const Image& tile, int index, const std::string& label) {
    const int x0 = (index % kColumns) * width, y0 = (index / kColumns) * (height + 20);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) sheet.at(x0 + x, y0 + 20 + y) = tile.at(x, y);
    drawText(sheet, Point2(float(x0 + 4), float(y0 + 4)), label, Color(0.9f), 2);
  };
  for (int k = 0; k < kBounces; ++k) {
    Image bounce(width, height);
    double mean = 0.0;
    for (size_t i = 0; i < bounce.pixels.size(); ++i) {
      bounce.pixels[i] = k == 0 ? cumulative[0].pixels[i] : cumulative[size_t(k)].pixels[i] - cumulative[size_t(k - 1)].pixels[i];
      mean += double(luminance(bounce.pixels[i]));
    }
    place(bounce, k, "BOUNCE " + std::to_string(k));
    char entry[48];
    std::snprintf(entry, sizeof entry, " %d: %.4f", k, mean / double(bounce.pixels.size()));
    report += entry;
  }
  place(full, kBounces, "ALL, -M " + std::to_string(request.scene.render.maxDepth));
  return {sheet, report + "\n"};
}

DebugOutput pathsView(const DebugViewRequest& request) {
  Scene scene = request.scene;
  scene.render.width = request.width;
  scene.render.height = request.height;
  const Accelerator accelerator(scene);
  const Lights lights = Lights::fromScene(scene, kLinkedTasks.environment);
  Image image = scenePreview(request, accelerator, 0.3f);
  const int samples = std::min(scene.render.samplesPerPixel, 8);
  const PixelInspection inspection =
      inspectPixel(scene, accelerator, lights, RenderOptions{}, request.inspectedPixel(), samples);

  const CameraProjection projection(request.drawingCamera(), {request.width, request.height});
  const Aabb bounds = accelerator.usesBvh() ? accelerator.bvh().nodes[0].bounds : Aabb{};
  const float escape = std::max(1.0f, glm::length(bounds.max - bounds.min));  // how far to draw a miss
  const Color camera(1.0f), reached(0.1f, 0.9f, 0.1f), blocked(0.9f, 0.05f, 0.05f);
  for (const InspectedSample& sample : inspection.samples) {
    int bounce = 0;
    for (const TracedRay& traced : sample.rays) {
      if (traced.shadow) {
        const float end = std::isfinite(traced.range.max) ? traced.range.max : escape;
        projection.drawSegment(image, traced.ray.origin, traced.ray.at(end), traced.hit ? blocked : reached);
        continue;
      }
      const Color color = bounce == 0 ? camera : colorMap(0.15f + 0.85f * float(bounce - 1) / float(std::max(1, scene.render.maxDepth - 1)));
      const Point3 end = traced.hit ? traced.record.point : traced.ray.at(escape);
      projection.drawSegment(image, traced.ray.origin, end, color);
      ++bounce;
    }
  }
  markInspectedPixel(image, request);
  drawText(image, Point2(6, 6), std::to_string(samples) + " PATHS, -M " + std::to_string(scene.render.maxDepth),
           Color(0.95f), 2);
  return {image, formatInspection(inspection)};
}

}  // namespace

void addPathTracingViews(std::vector<DebugView>& views) {
  views.push_back({5, "bounces", "light after exactly 0, 1, 2, 3, 4 bounces, and the full image", bouncesView});
  views.push_back({5, "paths", "the pixel's paths in the scene, and every ray, hit and sample in words", pathsView,
                   kCameraImage | kUsesPixel | kUsesViewCamera});
}

}  // namespace pathlab
