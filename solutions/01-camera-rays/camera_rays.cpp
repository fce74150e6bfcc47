// Task 1 — camera rays (reference solution).
#include "tasks/camera_rays.h"

#include <cmath>

namespace pathlab {

Point2 pixelSamplePosition(IVec2 pixel, Vec2 u) { return Point2(pixel) + u; }

CameraBasis cameraBasis(const Camera& camera) {
  CameraBasis basis;
  basis.forward = glm::normalize(camera.lookAt - camera.position);

  // right = forward x up vanishes when up is parallel to the view; then any
  // perpendicular will do: take the world axis least aligned with forward.
  Vec3 up = glm::normalize(camera.up);
  Vec3 right = glm::cross(basis.forward, up);
  if (glm::length(right) < 1e-4f) {
    Vec3 a = glm::abs(basis.forward);
    Vec3 axis = (a.x <= a.y && a.x <= a.z) ? Vec3(1, 0, 0) : (a.y <= a.z ? Vec3(0, 1, 0) : Vec3(0, 0, 1));
    right = glm::cross(basis.forward, axis);
  }
  basis.right = glm::normalize(right);
  basis.up = glm::cross(basis.right, basis.forward);
  return basis;
}

Ray generateCameraRay(const Camera& camera, const CameraBasis& basis, Point2 raster, IVec2 resolution) {
  // Raster -> normalised device coordinates in [-1, 1], y flipped so +1 is the top row.
  const float ndcX = 2.0f * raster.x / float(resolution.x) - 1.0f;
  const float ndcY = 1.0f - 2.0f * raster.y / float(resolution.y);
  // Image plane at distance 1: half-height tan(vfov/2), half-width aspect times that.
  const float halfHeight = std::tan(glm::radians(camera.vfovDegrees) * 0.5f);
  const float halfWidth = halfHeight * float(resolution.x) / float(resolution.y);
  const Vec3 direction = basis.forward + (ndcX * halfWidth) * basis.right + (ndcY * halfHeight) * basis.up;
  return Ray{camera.position, glm::normalize(direction)};
}

}  // namespace pathlab
