// Task 6 — mirror and glass (reference solution).
#include "tasks/mirror_glass.h"

#include <algorithm>
#include <cmath>

namespace pathlab {

Vec3 reflect(const Vec3& wo) { return {-wo.x, -wo.y, wo.z}; }

std::optional<Vec3> refract(const Vec3& wo, float ior) {
  // Entering (wo outside, z > 0): eta = n_outside / n_inside = 1 / ior.
  // Leaving: the roles swap.
  const bool entering = wo.z > 0.0f;
  const float eta = entering ? 1.0f / ior : ior;
  const float cosI = std::abs(wo.z);
  const float sin2T = eta * eta * std::max(0.0f, 1.0f - cosI * cosI);
  if (sin2T >= 1.0f) return std::nullopt;  // total internal reflection
  const float cosT = std::sqrt(1.0f - sin2T);
  return Vec3(-eta * wo.x, -eta * wo.y, entering ? -cosT : cosT);
}

float schlickFresnel(float cosTheta, float ior) {
  const float r0 = (1.0f - ior) / (1.0f + ior);
  const float f0 = r0 * r0;
  const float m = 1.0f - std::clamp(cosTheta, 0.0f, 1.0f);
  return f0 + (1.0f - f0) * (m * m) * (m * m) * m;
}

// A delta lobe's f carries 1 / |cos theta|, so that f |cos theta| / pdf is
// the fraction of light the lobe passes on, as for any other sample.
BsdfSample sampleMirror(const Vec3& wo, const Color& reflectance) {
  BsdfSample s;
  s.wi = reflect(wo);
  s.f = reflectance / std::abs(s.wi.z);
  s.pdf = 1.0f;
  s.isDelta = true;
  return s;
}

BsdfSample sampleGlass(const Vec3& wo, const Color& reflectance, const Color& transmittance, float ior, float u) {
  BsdfSample s;
  s.isDelta = true;
  const std::optional<Vec3> refracted = refract(wo, ior);
  if (!refracted) {  // total internal reflection: all light reflects
    s.wi = reflect(wo);
    s.f = reflectance / std::abs(s.wi.z);
    s.pdf = 1.0f;
    return s;
  }
  // Schlick needs the cosine on the outside (index 1) side of the boundary.
  // Equal indices make no interface at all, which Schlick's (1 - cos)^5
  // term does not know: glass of index 1 reflects nothing.
  const float cosOutside = wo.z > 0.0f ? wo.z : std::abs(refracted->z);
  const float fresnel = ior == 1.0f ? 0.0f : schlickFresnel(cosOutside, ior);
  if (u < fresnel) {
    s.wi = reflect(wo);
    s.f = reflectance * fresnel / std::abs(s.wi.z);  // weight f |cos| / pdf = reflectance
    s.pdf = fresnel;
    return s;
  }
  s.wi = *refracted;
  // Radiance L / n^2 is invariant across the boundary: carrying it from the
  // far side (index n_i) to wo's side (index n_o) scales by (n_o / n_i)^2.
  const float nFrom = wo.z > 0.0f ? 1.0f : ior, nTo = wo.z > 0.0f ? ior : 1.0f;
  s.f = transmittance * ((1.0f - fresnel) * (nFrom * nFrom) / (nTo * nTo)) / std::abs(s.wi.z);
  s.pdf = 1.0f - fresnel;
  return s;
}

}  // namespace pathlab
