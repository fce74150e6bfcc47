// Task 12 — homogeneous participating media (reference solution).
#include "tasks/media.h"

#include <algorithm>
#include <cmath>

#include "tasks/direct_lighting.h"
#include "util/frame.h"

namespace pathlab {
namespace {

// Shadow rays end this fraction short of the light, as task 4's do.
constexpr float kShadowShortening = 1e-4f;
// A ray crosses at most this many interfaces in a row (a path or a shadow
// ray): a guard against surfaces the offset cannot leave, never reached in
// a well-made scene.
constexpr int kMaxCrossings = 256;

}  // namespace

FreeFlight sampleFreeFlight(float sigmaT, float tMax, float u) {
  // Invert the CDF 1 - exp(-sigmaT t): t = -ln(1 - u) / sigmaT; log1p keeps
  // the digits of small u, and 1 - u > 0 never takes the log of 0.
  const float t = -std::log1p(-u) / sigmaT;
  if (t < tMax) return {t, true, sigmaT * std::exp(-sigmaT * t)};
  return {tMax, false, std::exp(-sigmaT * tMax)};
}

float henyeyGreenstein(float cosTheta, float g) {
  const float denominator = 1.0f + g * g - 2.0f * g * cosTheta;
  return (1.0f - g * g) / (4.0f * kPi * denominator * std::sqrt(denominator));
}

Vec3 sampleHenyeyGreenstein(const Vec3& direction, float g, Vec2 u) {
  // The CDF of cos theta inverted: 1 + g^2 - 2 g cos = ((1 - g^2) / (1 - g + 2 g u))^2.
  // Near g = 0 that loses every digit; the phase function is then uniform.
  float cosTheta = 1.0f - 2.0f * u.x;
  if (std::abs(g) >= 1e-3f) {
    const float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u.x);
    cosTheta = (1.0f + g * g - s * s) / (2.0f * g);
  }
  cosTheta = std::clamp(cosTheta, -1.0f, 1.0f);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * kPi * u.y;
  const Frame frame = Frame::fromNormal(direction);
  return glm::normalize(frame.toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta}));
}

float transmittance(TraceContext& context, Ray ray, float distance, MediumIndex medium, Sampler& /*sampler*/) {
  // Homogeneous media: exactly exp(-sigmaT d) per stretch, no random numbers.
  const Scene& scene = context.scene;
  const Point3 end = ray.origin + ray.direction * distance;  // unused when distance is infinite
  float fraction = 1.0f;
  for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
    const std::optional<Hit> hit = context.shadowHit(ray, Interval{0.0f, distance});
    const float travelled = hit ? hit->t : distance;
    if (medium != kVacuum) fraction *= std::exp(-scene.media[medium].sigmaT * travelled);
    if (!hit) return fraction;
    if (scene.materials[hit->material].type != MaterialType::Interface) return 0.0f;
    medium = scene.mediumAcross(*hit, ray.direction, medium);
    const Point3 origin = offsetRayOrigin(hit->point, hit->geometricNormal, ray.direction);
    if (distance != kInfinity) distance = glm::dot(end - origin, ray.direction);  // the rest of the way
    if (!(distance > 0.0f)) return fraction;
    ray.origin = origin;
  }
  return 0.0f;
}

Color estimateDirectLightingInMedia(TraceContext& context, const ScatteringVertex& vertex, MediumIndex medium,
                                    Sampler& sampler) {
  const Bsdf* bsdf = vertex.bsdf;
  if (bsdf && bsdf->isDelta()) return Color(0.0f);
  // What the vertex makes of light arriving along -wi: f |cos| on a
  // surface (light from below it: none), the phase function in a medium.
  auto scattering = [&](const Vec3& wi) {
    if (!bsdf) return Color(henyeyGreenstein(glm::dot(-vertex.wo, wi), vertex.g));
    const float cosine = glm::dot(wi, bsdf->normal());
    return cosine > 0.0f ? bsdf->f(vertex.wo, wi) * cosine : Color(0.0f);
  };
  // The transmittance towards a light point `distance` along wi (kInfinity:
  // the environment): from just off the surface, ending just short of the light.
  auto shadow = [&](const Vec3& wi, float distance) {
    const Point3 origin = bsdf ? offsetRayOrigin(vertex.point, vertex.hit->geometricNormal, wi) : vertex.point;
    if (distance == kInfinity) return transmittance(context, Ray{origin, wi}, kInfinity, medium, sampler);
    const Vec3 toLight = vertex.point + wi * distance - origin;
    const float remaining = glm::length(toLight);
    return transmittance(context, Ray{origin, toLight / remaining}, remaining * (1.0f - kShadowShortening), medium,
                         sampler);
  };

  Color radiance(0.0f);
  for (const PointLight& light : context.lights.points) {
    const Vec3 toLight = light.position - vertex.point;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) continue;
    const float distance = std::sqrt(distanceSquared);
    const Vec3 wi = toLight / distance;
    const Color f = scattering(wi);
    if (maxComponent(f) <= 0.0f) continue;
    radiance += f * light.intensity * (shadow(wi, distance) / distanceSquared);
  }
  for (const AreaLight& light : context.lights.areas) {
    Color sum(0.0f);
    for (int i = 0; i < context.settings.lightSamples; ++i) {
      const AreaSample sample = light.sample(sampler.next2D());
      const std::optional<LightDirection> direction = lightDirection(vertex.point, sample);
      if (!direction) continue;
      const Color f = scattering(direction->wi);
      if (maxComponent(f) <= 0.0f) continue;
      sum += f * sample.radiance * (shadow(direction->wi, direction->distance) / direction->pdfSolidAngle);
    }
    radiance += sum / float(context.settings.lightSamples);
  }
  if (const std::optional<EnvironmentLight>& environment = context.lights.environment) {
    Color sum(0.0f);
    for (int i = 0; i < context.settings.lightSamples; ++i) {
      const std::optional<EnvironmentLightSample> sample = environment->sample(sampler.next2D());
      if (!sample || maxComponent(sample->radiance) <= 0.0f) continue;
      const Color f = scattering(sample->direction);
      if (maxComponent(f) <= 0.0f) continue;
      sum += f * sample->radiance * (shadow(sample->direction, kInfinity) / sample->pdfSolidAngle);
    }
    radiance += sum / float(context.settings.lightSamples);
  }
  return radiance;
}

Color tracePathInMedia(TraceContext& context, Ray ray, Sampler& sampler) {
  constexpr int kRouletteFromBounce = 3;
  const Scene& scene = context.scene;
  Color radiance(0.0f), throughput(1.0f);
  bool countEmission = true;  // light seen directly, or through a mirror or glass
  MediumIndex medium = scene.medium;
  int bounce = 0, crossings = 0;
  // Russian roulette after each bounce, from the third: unbiased.
  auto survives = [&] {
    if (bounce < kRouletteFromBounce) return true;
    const float q = std::min(0.95f, maxComponent(throughput));
    if (sampler.next1D() >= q) return false;
    throughput /= q;
    return true;
  };
  for (;;) {
    const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
    // 1. In a medium: a free flight, which ends in the medium or passes the surface.
    if (medium != kVacuum) {
      const Medium& m = scene.media[medium];
      const FreeFlight flight = sampleFreeFlight(m.sigmaT, hit ? hit->t : kInfinity, sampler.next1D());
      if (flight.scattered) {
        // sigmaS exp(-sigmaT t) / pdf(t) = sigmaS / sigmaT: the exponentials cancel.
        throughput *= m.albedo;
        if (bounce >= context.settings.maxDepth) break;
        const Point3 point = ray.origin + ray.direction * flight.t;
        const ScatteringVertex vertex = ScatteringVertex::inMedium(point, -ray.direction, m.g);
        radiance += throughput * estimateDirectLightingInMedia(context, vertex, medium, sampler);
        // Sampled in proportion to the phase function: weight p / pdf = 1.
        const Vec3 wi = sampleHenyeyGreenstein(ray.direction, m.g, sampler.next2D());
        countEmission = false;
        ++bounce;
        if (!(maxComponent(throughput) > 0.0f) || !survives()) break;
        ray = Ray{point, wi};
        continue;
      }
      // Passed: transmittance over its probability, exp(-sigmaT t) / exp(-sigmaT t) = 1.
    }
    // 2. The surface, or the environment, as task 5.
    if (!hit) {
      if (countEmission) radiance += throughput * context.background(ray.direction);
      break;
    }
    // An interface only changes the medium: straight on, not a bounce.
    if (scene.materials[hit->material].type == MaterialType::Interface) {
      if (++crossings > kMaxCrossings) break;
      medium = scene.mediumAcross(*hit, ray.direction, medium);
      ray.origin = offsetRayOrigin(hit->point, hit->geometricNormal, ray.direction);
      continue;
    }
    const Vec3 wo = -ray.direction;
    if (countEmission) radiance += throughput * emittedRadiance(scene, *hit, wo);
    if (bounce >= context.settings.maxDepth) break;
    const Bsdf bsdf = context.bsdf(*hit, wo);
    radiance += throughput *
                estimateDirectLightingInMedia(context, ScatteringVertex::onSurface(*hit, bsdf, wo), medium, sampler);
    const std::optional<BsdfSample> sample = bsdf.sample(wo, sampler.next2D());
    if (!sample || !(sample->pdf > 0.0f)) break;
    const float cosine = std::abs(glm::dot(sample->wi, bsdf.normal()));
    throughput *= sample->f * (cosine / sample->pdf);
    countEmission = sample->isDelta;
    ++bounce;
    if (!(maxComponent(throughput) > 0.0f) || !survives()) break;
    // Through glass that bounds a medium, into it or out of it.
    medium = scene.mediumAcross(*hit, sample->wi, medium);
    ray = Ray{offsetRayOrigin(hit->point, hit->geometricNormal, sample->wi), sample->wi};
  }
  return radiance;
}

}  // namespace pathlab
