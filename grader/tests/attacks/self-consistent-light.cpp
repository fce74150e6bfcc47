// attack: a "light sampler" that draws uniform directions over the sphere and reports that density as its
// pdf, and a path tracer that returns 0.3 for every path: its samples follow its own pdf, its estimators
// agree with one another, and nothing is light sampling
// task: 09  base: none  expect: 0
#include "tasks/mis.h"

#include <cmath>

namespace pathlab {

float balanceHeuristic(float, float) { return 0.5f; }
float powerHeuristic(float, float) { return 0.5f; }

std::optional<LightSample> sampleOneLight(const TraceContext&, const Point3&, Vec3 u) {
  const float z = 1.0f - 2.0f * u.y, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 6.2831853f * u.z;
  LightSample s;
  s.wi = Vec3(r * std::cos(phi), r * std::sin(phi), z);
  s.distance = 1.0f;
  s.radiance = Color(0.3f);
  s.pdf = 1.0f / (4.0f * 3.14159265f);
  return s;
}

float oneLightPdf(const TraceContext&, const Point3&, const Vec3&, const std::optional<Hit>&) {
  return 1.0f / (4.0f * 3.14159265f);
}

Color tracePathMis(TraceContext&, Ray, Sampler&, const MisWeights&) { return Color(0.3f); }

}  // namespace pathlab
