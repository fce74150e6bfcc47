// Task 4's visual debugger (students don't edit this file: it shows what
// their direct_lighting.cpp does).
//   direct       emission + direct light at the first hit, nothing else
//   shadow-rays  the inspected pixel's shadow rays drawn over the direct
//                image: green reached the light, red was blocked
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "debug/inspect.h"
#include "render/render.h"
#include "render/task_wiring.h"

namespace pathlab {
namespace {

Scene atResolution(const Scene& scene, int width, int height) {
  Scene copy = scene;
  copy.render.width = width;
  copy.render.height = height;
  return copy;
}

// Renders what task 4 computes, from `camera` (the scene's, or the GUI's orbit view).
RenderResult renderDirect(const DebugViewRequest& request, const Camera& camera) {
  Scene scene = atResolution(request.scene, request.width, request.height);
  scene.camera = camera;
  RenderOptions options;
  options.integrator = Integrator::Direct;
  options.progress = false;
  options.threads = request.threads;
  return render(scene, options);
}

DebugOutput directView(const DebugViewRequest& request) {
  char report[96];
  std::snprintf(report, sizeof report, "direct lighting only: %d spp, %d samples per area light\n",
                request.scene.render.samplesPerPixel, request.scene.render.lightSamples);
  return {renderDirect(request, request.scene.camera).image, report};
}

DebugOutput shadowRaysView(const DebugViewRequest& request) {
  const Scene scene = atResolution(request.scene, request.width, request.height);
  Image image = renderDirect(request, request.drawingCamera()).image;
  for (Color& c : image.pixels) c *= 0.5f;  // dim, so the rays stand out

  // Re-trace the pixel with the render's random numbers, recording its rays.
  const IVec2 pixel = request.inspectedPixel();
  const Accelerator accelerator(scene);
  const Lights lights = Lights::fromScene(scene, kLinkedTasks.environment);
  RenderOptions options;
  options.integrator = Integrator::Direct;
  const int samples = std::min(scene.render.samplesPerPixel, 16);
  const PixelInspection inspection = inspectPixel(scene, accelerator, lights, options, pixel, samples);

  const CameraProjection projection(request.drawingCamera(), {request.width, request.height});
  int blocked = 0, free = 0;
  for (const InspectedSample& sample : inspection.samples) {
    for (const TracedRay& traced : sample.rays) {
      if (!traced.shadow) {
        if (request.viewCamera && traced.hit) projection.drawSegment(image, traced.ray.origin, traced.record.point, Color(1.0f, 1.0f, 0.2f));
        continue;
      }
      const float end = std::isfinite(traced.range.max) ? traced.range.max : 1e3f;
      projection.drawSegment(image, traced.ray.origin, traced.ray.at(end),
                             traced.hit ? Color(0.9f, 0.05f, 0.05f) : Color(0.1f, 0.9f, 0.1f));
      traced.hit ? ++blocked : ++free;
    }
  }
  markInspectedPixel(image, request);
  char report[160];
  std::snprintf(report, sizeof report, "pixel %d,%d, %d samples: %d shadow rays reached a light, %d were blocked\n",
                pixel.x, pixel.y, samples, free, blocked);
  return {image, report + formatInspection(inspection)};
}

}  // namespace

void addDirectLightingViews(std::vector<DebugView>& views) {
  views.push_back({4, "direct", "emission and direct light only (no bounces)", directView, kCameraImage});
  views.push_back({4, "shadow-rays", "the inspected pixel's shadow rays: green reached the light, red blocked",
                   shadowRaysView, kCameraImage | kUsesPixel | kUsesViewCamera});
}

}  // namespace pathlab
