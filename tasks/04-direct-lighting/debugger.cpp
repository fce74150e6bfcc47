// Task 4's visual debugger (students don't edit this file: it shows what
// their direct_lighting.cpp does).
//   direct       emission + direct light at the first hit, nothing else
//   shadow-rays  the inspected pixel's shadow rays drawn over the direct
//                image: green reached the light, red was blocked
#include <algorithm>
#include <cstdio>

#include "pathlab/debug_views.h"
#include "pathlab/draw.h"
#include "pathlab/render.h"

namespace pathlab {
namespace {

Scene atResolution(const Scene& scene, int width, int height) {
  Scene copy = scene;
  copy.render.width = width;
  copy.render.height = height;
  return copy;
}

DebugOutput directView(const DebugViewRequest& request) {
  const Scene scene = atResolution(request.scene, request.width, request.height);
  RenderOptions options;
  options.integrator = Integrator::Direct;
  options.progress = false;
  options.threads = request.threads;
  RenderResult result = render(scene, options);
  char report[96];
  std::snprintf(report, sizeof report, "direct lighting only: %d spp, %d samples per area light\n",
                scene.render.samplesPerPixel, scene.render.lightSamples);
  return {result.image, report};
}

DebugOutput shadowRaysView(const DebugViewRequest& request) {
  const Scene scene = atResolution(request.scene, request.width, request.height);
  DebugOutput output = directView(request);
  for (Color& c : output.image.pixels) c *= 0.5f;  // dim, so the rays stand out

  const IVec2 pixel = request.pixel.x < 0 ? IVec2(scene.render.width / 2, scene.render.height / 2) : request.pixel;
  const Accelerator accelerator(scene);
  const Lights lights = Lights::fromScene(scene);
  RenderOptions options;
  options.integrator = Integrator::Direct;
  TraceContext context = makeTraceContext(scene, accelerator, lights, options);
  std::vector<TracedRay> log;
  context.log = &log;
  context.pixel = pixel;
  const CameraBasis basis = cameraBasis(scene.camera);
  const int samples = std::min(scene.render.samplesPerPixel, 16);
  for (int s = 0; s < samples; ++s) renderSample(context, options, basis, uint32_t(s));

  const CameraProjection projection(scene.camera, {scene.render.width, scene.render.height});
  int blocked = 0, free = 0;
  for (const TracedRay& traced : log) {
    if (!traced.shadow) continue;
    const float end = std::isfinite(traced.range.max) ? traced.range.max : 1e3f;
    projection.drawSegment(output.image, traced.ray.origin, traced.ray.at(end),
                           traced.hit ? Color(0.9f, 0.05f, 0.05f) : Color(0.1f, 0.9f, 0.1f));
    traced.hit ? ++blocked : ++free;
  }
  drawRectOutline(output.image, Point2(pixel) - Point2(3.0f), Point2(pixel) + Point2(4.0f), Color(1.0f, 1.0f, 0.2f));
  char report[160];
  std::snprintf(report, sizeof report, "pixel %d,%d, %d samples: %d shadow rays reached a light, %d were blocked\n",
                pixel.x, pixel.y, samples, free, blocked);
  output.report += report;
  return output;
}

}  // namespace

void addDirectLightingViews(std::vector<DebugView>& views) {
  views.push_back({4, "direct", "emission and direct light only (no bounces)", directView});
  views.push_back({4, "shadow-rays", "the inspected pixel's shadow rays: green reached the light, red blocked",
                   shadowRaysView});
}

}  // namespace pathlab
