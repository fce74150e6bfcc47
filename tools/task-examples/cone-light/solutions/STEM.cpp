// Task @N@ — @TITLE@ (reference solution).
#include "tasks/@STEM@.h"

#include <algorithm>
#include <cmath>

#include "util/frame.h"

namespace pathlab::@STEM@ {

float coneCosThetaMax(Point3 x, Point3 center, float radius) {
  const Vec3 toCenter = center - x;
  const float sin2ThetaMax = radius * radius / glm::dot(toCenter, toCenter);
  if (!(sin2ThetaMax < 1.0f)) return -1.0f;  // on or inside the sphere (or at its centre: inf, NaN)
  return std::sqrt(1.0f - sin2ThetaMax);
}

ConeSample sampleCone(Vec3 axis, float cosThetaMax, Vec2 u) {
  // Uniform in solid angle: cos(theta) uniform on [cosThetaMax, 1], phi on [0, 2 pi).
  const float cosTheta = 1.0f - u.x * (1.0f - cosThetaMax);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * kPi * u.y;
  const Vec3 local(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
  return {glm::normalize(Frame::fromNormal(axis).toWorld(local)), 1.0f / (2.0f * kPi * (1.0f - cosThetaMax))};
}

float conePdf(Vec3 axis, float cosThetaMax, Vec3 w) {
  return glm::dot(w, axis) >= cosThetaMax ? 1.0f / (2.0f * kPi * (1.0f - cosThetaMax)) : 0.0f;
}

}  // namespace pathlab::@STEM@
