// Task 2's visual debugger (students don't edit this file: it shows what
// their intersection.cpp does). One camera ray per pixel centre, closest hit
// through the scene's BVH (brute force while task 3 is undone).
//   normals       shading normal as colour 0.5 + 0.5 n (black: no hit)
//   depth         hit distance, near = bright, far = dark (blue: no hit)
//   primitive-id  one colour per primitive (black: no hit)
// Each prints the hit record of the inspected pixel (yellow square).
#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "render/accelerator.h"
#include "tasks/camera_rays.h"
#include "util/parallel.h"

namespace pathlab {
namespace {

// Closest hit through every pixel centre.
std::vector<std::optional<Hit>> primaryHits(const DebugViewRequest& request) {
  const Camera& camera = request.scene.camera;
  const CameraBasis basis = cameraBasis(camera);
  const IVec2 resolution{request.width, request.height};
  const Accelerator accelerator(request.scene);
  std::vector<std::optional<Hit>> hits(size_t(request.width) * size_t(request.height));
  forEachPixel(request.width, request.height, request.threads, [&](int x, int y) {
    Ray ray = generateCameraRay(camera, basis, Point2(float(x) + 0.5f, float(y) + 0.5f), resolution);
    hits[size_t(y) * size_t(request.width) + size_t(x)] = accelerator.intersect(ray, Interval{0.0f, kInfinity});
  });
  return hits;
}

// The hit record of the inspected pixel's centre ray, as task 2 computed it.
std::string hitRecord(const DebugViewRequest& request, const std::vector<std::optional<Hit>>& hits) {
  const IVec2 p = request.inspectedPixel();
  char line[320];
  if (p.x >= request.width || p.y >= request.height) return "";
  const std::optional<Hit>& hit = hits[size_t(p.y) * size_t(request.width) + size_t(p.x)];
  if (!hit) {
    std::snprintf(line, sizeof line, "pixel %d,%d: no hit\n", p.x, p.y);
    return line;
  }
  const PrimitiveRef& ref = request.scene.primitives[hit->primitive];
  std::snprintf(line, sizeof line,
                "pixel %d,%d: t = %.5g, point (%.4f, %.4f, %.4f)\n"
                "  geometric normal (%.4f, %.4f, %.4f), shading normal (%.4f, %.4f, %.4f)\n"
                "  primitive %u (%s %u), material \"%s\"\n",
                p.x, p.y, double(hit->t), double(hit->point.x), double(hit->point.y), double(hit->point.z),
                double(hit->geometricNormal.x), double(hit->geometricNormal.y), double(hit->geometricNormal.z),
                double(hit->shadingNormal.x), double(hit->shadingNormal.y), double(hit->shadingNormal.z), hit->primitive,
                ref.isSphere() ? "sphere" : "triangle", ref.index, request.scene.materials[hit->material].name.c_str());
  return line;
}

Color display(Vec3 v) {
  v = glm::clamp(v, 0.0f, 1.0f);
  return {srgbToLinear(v.x), srgbToLinear(v.y), srgbToLinear(v.z)};
}

DebugOutput normalsView(const DebugViewRequest& request) {
  auto hits = primaryHits(request);
  Image image(request.width, request.height);
  for (size_t i = 0; i < hits.size(); ++i) {
    if (hits[i]) image.pixels[i] = display(0.5f * (hits[i]->shadingNormal + Vec3(1.0f)));
  }
  markInspectedPixel(image, request);
  return {image, hitRecord(request, hits)};
}

DebugOutput depthView(const DebugViewRequest& request) {
  auto hits = primaryHits(request);
  float nearest = kInfinity, farthest = 0.0f;
  for (const auto& hit : hits) {
    if (hit) nearest = std::min(nearest, hit->t), farthest = std::max(farthest, hit->t);
  }
  Image image(request.width, request.height, display({0.1f, 0.15f, 0.4f}));
  for (size_t i = 0; i < hits.size(); ++i) {
    if (!hits[i]) continue;
    float s = farthest > nearest ? (hits[i]->t - nearest) / (farthest - nearest) : 0.0f;
    image.pixels[i] = display(Vec3(1.0f - 0.85f * s));
  }
  markInspectedPixel(image, request);
  char range[80];
  std::snprintf(range, sizeof range, "hit distances from %.4g to %.4g\n", double(nearest), double(farthest));
  return {image, range + hitRecord(request, hits)};
}

DebugOutput primitiveIdView(const DebugViewRequest& request) {
  auto hits = primaryHits(request);
  Image image(request.width, request.height);
  for (size_t i = 0; i < hits.size(); ++i) {
    if (hits[i]) image.pixels[i] = display(idColor(hits[i]->primitive));
  }
  markInspectedPixel(image, request);
  return {image, hitRecord(request, hits)};
}

}  // namespace

void addIntersectionViews(std::vector<DebugView>& views) {
  const unsigned inputs = kCameraImage | kUsesPixel;
  views.push_back({2, "normals", "shading normal as colour 0.5 + 0.5 n; the pixel's hit record", normalsView, inputs});
  views.push_back({2, "depth", "hit distance: near bright, far dark, no hit blue", depthView, inputs});
  views.push_back({2, "primitive-id", "one colour per primitive", primitiveIdView, inputs});
}

}  // namespace pathlab
