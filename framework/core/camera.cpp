#include "core/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace pathlab {

Camera orbitCamera(const Camera& camera, float yawDegrees, float pitchDegrees) {
  const Vec3 up = glm::normalize(camera.up);
  Vec3 offset = camera.position - camera.lookAt;
  offset = glm::angleAxis(glm::radians(yawDegrees), up) * offset;
  // Pitch about the right axis, clamped away from the poles where the view
  // direction would become parallel to up.
  const float length = glm::length(offset);
  const float polar = std::acos(std::clamp(glm::dot(offset / length, up), -1.0f, 1.0f));
  const float limit = glm::radians(5.0f);
  const float target = std::clamp(polar - glm::radians(pitchDegrees), limit, kPi - limit);
  const Vec3 right = glm::cross(up, offset);
  if (glm::length(right) > 0.0f) offset = glm::angleAxis(target - polar, glm::normalize(right)) * offset;
  Camera moved = camera;
  moved.position = camera.lookAt + offset;
  return moved;
}

Camera panCamera(const Camera& camera, Vec2 pixels, int imageHeight) {
  const Vec3 forward = camera.lookAt - camera.position;
  const float distance = glm::length(forward);
  const Vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const Vec3 trueUp = glm::cross(right, forward / distance);
  const float worldPerPixel =
      2.0f * distance * std::tan(glm::radians(camera.vfovDegrees) / 2.0f) / float(std::max(1, imageHeight));
  const Vec3 shift = (-pixels.x * right + pixels.y * trueUp) * worldPerPixel;
  Camera moved = camera;
  moved.position += shift;
  moved.lookAt += shift;
  return moved;
}

Camera dollyCamera(const Camera& camera, float factor) {
  Camera moved = camera;
  moved.position = camera.lookAt + (camera.position - camera.lookAt) * std::max(factor, 1e-3f);
  return moved;
}

}  // namespace pathlab
