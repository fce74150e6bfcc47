// Task 4 — direct lighting with shadows (reference solution).
#include "tasks/direct_lighting.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace pathlab {
namespace {

// Shadow rays end this fraction short of the light, so they cannot hit the
// light's own surface.
constexpr float kShadowShortening = 1e-4f;

// The shadow ray from the surface towards a point at `distance` along wi
// (kInfinity: towards the environment). It is aimed from the offset origin
// at the light point itself, so it ends just short of the light whatever
// the size of the offset.
bool visible(TraceContext& context, const Hit& hit, const Vec3& wi, float distance) {
  const Point3 origin = offsetRayOrigin(hit.point, hit.geometricNormal, wi);
  if (distance == kInfinity) return !context.occluded(Ray{origin, wi}, Interval{0.0f, kInfinity});
  const Vec3 toLight = hit.point + wi * distance - origin;
  const float remaining = glm::length(toLight);
  return !context.occluded(Ray{origin, toLight / remaining}, Interval{0.0f, remaining * (1.0f - kShadowShortening)});
}

}  // namespace

Color lambertianBrdf(const Color& albedo) { return albedo * kInvPi; }

// Wächter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection",
// Ray Tracing Gems (2019), chapter 6: move the point a fixed number of float
// ulps along the normal (scale-independent), with a small absolute step near
// the origin where ulps are tiny.
Point3 offsetRayOrigin(const Point3& p, const Vec3& geometricNormal, const Vec3& direction) {
  constexpr float kOrigin = 1.0f / 32.0f;
  constexpr float kFloatScale = 1.0f / 65536.0f;
  constexpr float kIntScale = 256.0f;
  const Vec3 n = glm::dot(geometricNormal, direction) < 0.0f ? -geometricNormal : geometricNormal;
  Point3 result;
  for (int a = 0; a < 3; ++a) {
    const int32_t ulps = int32_t(kIntScale * n[a]);
    const int32_t bits = std::bit_cast<int32_t>(p[a]);
    const float moved = std::bit_cast<float>(bits + (p[a] < 0.0f ? -ulps : ulps));
    result[a] = std::abs(p[a]) < kOrigin ? p[a] + kFloatScale * n[a] : moved;
  }
  return result;
}

std::optional<LightDirection> lightDirection(const Point3& from, const AreaSample& sample) {
  const Vec3 toLight = sample.point - from;
  const float distanceSquared = glm::dot(toLight, toLight);
  if (!(distanceSquared > 0.0f)) return std::nullopt;
  const float distance = std::sqrt(distanceSquared);
  const Vec3 wi = toLight / distance;
  // The light's cosine: its normal against the direction back to us.
  const float cosLight = -glm::dot(sample.normal, wi);
  if (cosLight <= 0.0f) return std::nullopt;  // seen from behind: it emits nothing this way
  // dA = r^2 / cos(theta') dw, so p(w) = p(A) r^2 / cos(theta').
  return LightDirection{wi, distance, sample.pdfArea * distanceSquared / cosLight};
}

Color estimateDirectLighting(TraceContext& context, const Hit& hit, const Bsdf& bsdf, const Vec3& wo,
                             Sampler& sampler) {
  if (bsdf.isDelta()) return Color(0.0f);  // a perfect mirror or glass reflects no light source directly
  Color radiance(0.0f);

  // Point lights: a delta distribution, one exact sample each.
  for (const PointLight& light : context.lights.points) {
    const Vec3 toLight = light.position - hit.point;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) continue;
    const float distance = std::sqrt(distanceSquared);
    const Vec3 wi = toLight / distance;
    const float cosSurface = glm::dot(wi, bsdf.normal());
    if (cosSurface <= 0.0f) continue;
    const Color f = bsdf.f(wo, wi);
    if (maxComponent(f) <= 0.0f || !visible(context, hit, wi, distance)) continue;
    radiance += f * light.intensity * (cosSurface / distanceSquared);
  }

  // Area lights: the mean of settings.lightSamples estimates f Le cos / p(w).
  for (const AreaLight& light : context.lights.areas) {
    Color sum(0.0f);
    for (int i = 0; i < context.settings.lightSamples; ++i) {
      const AreaSample sample = light.sample(sampler.next2D());
      const std::optional<LightDirection> direction = lightDirection(hit.point, sample);
      if (!direction) continue;
      const float cosSurface = glm::dot(direction->wi, bsdf.normal());
      if (cosSurface <= 0.0f) continue;
      const Color f = bsdf.f(wo, direction->wi);
      if (maxComponent(f) <= 0.0f || !visible(context, hit, direction->wi, direction->distance)) continue;
      sum += f * sample.radiance * (cosSurface / direction->pdfSolidAngle);
    }
    radiance += sum / float(context.settings.lightSamples);
  }

  // The environment: a light at infinity, sampled like an area light but
  // directly in solid angle.
  if (const std::optional<EnvironmentLight>& environment = context.lights.environment) {
    Color sum(0.0f);
    for (int i = 0; i < context.settings.lightSamples; ++i) {
      const std::optional<EnvironmentLightSample> sample = environment->sample(sampler.next2D());
      if (!sample) continue;
      const float cosSurface = glm::dot(sample->direction, bsdf.normal());
      if (cosSurface <= 0.0f) continue;
      const Color f = bsdf.f(wo, sample->direction);
      if (maxComponent(f) <= 0.0f || maxComponent(sample->radiance) <= 0.0f ||
          !visible(context, hit, sample->direction, kInfinity)) {
        continue;
      }
      sum += f * sample->radiance * (cosSurface / sample->pdfSolidAngle);
    }
    radiance += sum / float(context.settings.lightSamples);
  }
  return radiance;
}

}  // namespace pathlab
