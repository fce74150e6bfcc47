// Task 10 — a thin-lens camera (reference solution).
#include "tasks/thin_lens.h"

#include <cmath>

namespace pathlab {

Point2 sampleUnitDisk(Vec2 u) {
  // Shirley and Chiu's concentric map: squares of [-1, 1]^2 onto rings of
  // the disk, so strata of u stay compact on the lens.
  const Vec2 offset = 2.0f * u - Vec2(1.0f);
  if (offset.x == 0.0f && offset.y == 0.0f) return Point2(0.0f);
  float r, phi;
  if (std::abs(offset.x) > std::abs(offset.y)) {
    r = offset.x;
    phi = 0.25f * kPi * (offset.y / offset.x);
  } else {
    r = offset.y;
    phi = 0.5f * kPi - 0.25f * kPi * (offset.x / offset.y);
  }
  return r * Point2(std::cos(phi), std::sin(phi));
}

Ray generateThinLensRay(const Camera& camera, const CameraBasis& basis, const Ray& pinholeRay, Vec2 uLens) {
  // The point in focus: where the pinhole ray reaches depth focalDistance
  // along the view axis (a plane, so t grows off the axis).
  const float t = camera.focalDistance / glm::dot(pinholeRay.direction, basis.forward);
  const Point3 focus = pinholeRay.origin + t * pinholeRay.direction;
  // The lens point, from the unit disk to the lens's plane in world space.
  const Point2 disk = camera.apertureRadius * sampleUnitDisk(uLens);
  const Point3 origin = camera.position + disk.x * basis.right + disk.y * basis.up;
  return Ray{origin, glm::normalize(focus - origin)};
}

}  // namespace pathlab
