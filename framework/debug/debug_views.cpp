#include "debug/debug_views.h"

#include "debug/draw.h"
#include "render/accelerator.h"
#include "tasks/camera_rays.h"
#include "util/parallel.h"

namespace pathlab {

Image scenePreview(const DebugViewRequest& request, const Accelerator& accelerator, float brightness) {
  const Camera& camera = request.drawingCamera();
  const CameraBasis basis = cameraBasis(camera);
  const IVec2 size{request.width, request.height};
  Image image(request.width, request.height);
  forEachPixel(request.width, request.height, request.threads, [&](int x, int y) {
    const Ray ray = generateCameraRay(camera, basis, Point2(float(x) + 0.5f, float(y) + 0.5f), size);
    if (auto hit = accelerator.intersect(ray, Interval{0.0f, kInfinity})) {
      const float cosine = std::abs(glm::dot(hit->shadingNormal, ray.direction));
      const Material& material = request.scene.materials[hit->material];
      image.at(x, y) = brightness * (material.albedo * cosine + material.emission);
    }
  });
  return image;
}

void markInspectedPixel(Image& image, const DebugViewRequest& request) {
  if (request.viewCamera) return;  // another viewpoint: the pixel is not where it was
  const Point2 p(request.inspectedPixel());
  drawRectOutline(image, p - Point2(3.0f), p + Point2(4.0f), Color(1.0f, 1.0f, 0.2f));
}

std::vector<DebugView> allDebugViews() {
  std::vector<DebugView> views;
  addTaskDebugViews(views);
  return views;
}

}  // namespace pathlab
