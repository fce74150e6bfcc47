// Task 1's visual debugger (students don't edit this file: it shows what
// their camera_rays.cpp does).
//   directions  each pixel's centre ray direction as a colour, 0.5 + 0.5 d
//   samples     the inspected pixel and its neighbours, magnified, with the
//               sample positions the renderer uses (red: outside the pixel)
#include <algorithm>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "tasks/camera_rays.h"
#include "util/parallel.h"
#include "util/random.h"

namespace pathlab {
namespace {

DebugOutput directionsView(const DebugViewRequest& request) {
  const Camera& camera = request.scene.camera;
  const CameraBasis basis = cameraBasis(camera);
  const IVec2 resolution{request.width, request.height};
  Image image(request.width, request.height);
  forEachPixel(request.width, request.height, request.threads, [&](int x, int y) {
    Point2 raster = pixelSamplePosition({x, y}, Vec2(0.5f));
    Ray ray = generateCameraRay(camera, basis, raster, resolution);
    // Display colour 0.5 + 0.5 d, stored linear so the PNG shows exactly that.
    Vec3 display = glm::clamp(0.5f * (ray.direction + Vec3(1.0f)), 0.0f, 1.0f);
    image.at(x, y) = {srgbToLinear(display.x), srgbToLinear(display.y), srgbToLinear(display.z)};
  });
  return {image, ""};
}

DebugOutput samplesView(const DebugViewRequest& request) {
  constexpr int kPixels = 4;  // a kPixels x kPixels neighbourhood
  const int cell = std::max(16, std::min(request.width, request.height) / kPixels);
  const int renderWidth = request.scene.render.width, renderHeight = request.scene.render.height;
  const IVec2 centre = request.inspectedPixel();
  const IVec2 first = glm::clamp(centre - IVec2(kPixels / 2), IVec2(0),
                                 glm::max(IVec2(0), IVec2(renderWidth, renderHeight) - IVec2(kPixels)));
  const int spp = std::min(request.scene.render.samplesPerPixel, 256);

  Image image(kPixels * cell, kPixels * cell, Color(0.02f));
  const Color gridColor(0.3f), inside(0.2f, 0.8f, 1.0f), outside(1.0f, 0.05f, 0.05f);
  int outsideCount = 0;
  for (int py = 0; py < kPixels; ++py) {
    for (int px = 0; px < kPixels; ++px) {
      const IVec2 pixel = first + IVec2(px, py);
      const Point2 cellMin(float(px * cell), float(py * cell));
      if (pixel == centre) fillRect(image, cellMin, cellMin + Point2(float(cell)), Color(0.08f));
      drawRectOutline(image, cellMin, cellMin + Point2(float(cell - 1)), gridColor);
      const uint32_t pixelIndex = uint32_t(pixel.y) * uint32_t(renderWidth) + uint32_t(pixel.x);
      for (int s = 0; s < spp; ++s) {
        Sampler sampler(pixelIndex, uint32_t(s), request.scene.render.seed);  // as the renderer does
        Point2 p = pixelSamplePosition(pixel, sampler.next2D());
        bool in = p.x >= float(pixel.x) && p.x < float(pixel.x + 1) && p.y >= float(pixel.y) &&
                  p.y < float(pixel.y + 1);
        if (!in) ++outsideCount;
        Point2 drawn = (p - Point2(first)) * float(cell);
        drawDot(image, drawn, std::max(1.5f, float(cell) / 40.0f), in ? inside : outside);
      }
    }
  }
  const std::string report = "pixel " + std::to_string(centre.x) + "," + std::to_string(centre.y) + " and " +
                             std::to_string(kPixels * kPixels - 1) + " neighbours, " + std::to_string(spp) +
                             " samples each: " + std::to_string(outsideCount) + " outside their pixel\n";
  return {image, report};
}

}  // namespace

void addCameraRaysViews(std::vector<DebugView>& views) {
  views.push_back({1, "directions", "camera ray direction per pixel as colour 0.5 + 0.5 d", directionsView,
                   kCameraImage});
  views.push_back({1, "samples", "sample positions in the inspected pixel and its neighbours (red: outside)",
                   samplesView, kUsesPixel});
}

}  // namespace pathlab
