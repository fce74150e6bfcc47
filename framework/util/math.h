// Math vocabulary shared by the framework and every task: GLM float vectors
// with names that say what they hold, intervals, and small numeric helpers.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

namespace pathlab {

// GLM has one vec3 for points, directions and normals; the aliases document
// which one a variable holds (STYLE.md rule 4).
using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Point2 = glm::vec2;
using Point3 = glm::vec3;
using Color = glm::vec3;  // linear RGB radiance or reflectance
using IVec2 = glm::ivec2;

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

// An open range of ray parameters: t is accepted when min < t < max.
struct Interval {
  float min = 0.0f;
  float max = kInfinity;

  bool contains(float t) const { return min < t && t < max; }
};

inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The largest component, NaN components ignored (as std::fmax, which GCC
// calls out of line on x86-64: this runs several times per path vertex).
inline float maxComponent(const Vec3& v) {
  auto fmax = [](float a, float b) { return (a > b || b != b) ? a : b; };
  return fmax(v.x, fmax(v.y, v.z));
}

// Rec. 709 luminance of linear RGB.
inline float luminance(const Color& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

}  // namespace pathlab
