// Task 9 — multiple importance sampling (reference solution).
#include "tasks/mis.h"

#include <algorithm>
#include <cmath>

#include "core/bsdf.h"
#include "tasks/direct_lighting.h"

namespace pathlab {
namespace {

constexpr float kShadowShortening = 1e-4f;  // as task 4: shadow rays end short of the light

// Task 4's shadow ray, from the offset origin aimed at the light point itself.
bool visible(TraceContext& context, const Hit& hit, const Vec3& wi, float distance) {
  const Point3 origin = offsetRayOrigin(hit.point, hit.geometricNormal, wi);
  if (distance == kInfinity) return !context.occluded(Ray{origin, wi}, Interval{0.0f, kInfinity});
  const Vec3 toLight = hit.point + wi * distance - origin;
  const float remaining = glm::length(toLight);
  return !context.occluded(Ray{origin, toLight / remaining}, Interval{0.0f, remaining * (1.0f - kShadowShortening)});
}

// The lights sampleOneLight chooses among: every area light, then the environment.
int lightCount(const Lights& lights) { return int(lights.areas.size()) + (lights.environment ? 1 : 0); }

}  // namespace

float balanceHeuristic(float pdfThis, float pdfOther) {
  if (!(pdfThis > 0.0f)) return 0.0f;
  return pdfThis / (pdfThis + pdfOther);
}

// Written with the ratio of the smaller density to the larger, so that
// squaring neither overflows (a sharp lobe's pdf can pass 1e19) nor
// underflows.
float powerHeuristic(float pdfThis, float pdfOther) {
  if (!(pdfThis > 0.0f)) return 0.0f;
  if (pdfOther <= pdfThis) {
    const float r = pdfOther / pdfThis;
    return 1.0f / (1.0f + r * r);
  }
  const float r = pdfThis / pdfOther;
  return r * r / (1.0f + r * r);
}

// Every light equally likely: 1 / (area lights + environment).
std::optional<LightSample> sampleOneLight(const TraceContext& context, const Point3& from, Vec3 u) {
  const Lights& lights = context.lights;
  const int count = lightCount(lights);
  if (count == 0) return std::nullopt;
  const int chosen = std::min(int(u.x * float(count)), count - 1);
  const float choice = 1.0f / float(count);
  const Vec2 uv(u.y, u.z);
  if (chosen < int(lights.areas.size())) {
    const AreaSample sample = lights.areas[size_t(chosen)].sample(uv);
    const std::optional<LightDirection> direction = lightDirection(from, sample);
    if (!direction) return std::nullopt;
    return LightSample{direction->wi, direction->distance, sample.radiance, choice * direction->pdfSolidAngle};
  }
  const std::optional<EnvironmentLightSample> sample = lights.environment->sample(uv);
  if (!sample || !(sample->pdfSolidAngle > 0.0f)) return std::nullopt;
  return LightSample{sample->direction, kInfinity, sample->radiance, choice * sample->pdfSolidAngle};
}

float oneLightPdf(const TraceContext& context, const Point3& from, const Vec3& wi, const std::optional<Hit>& hit) {
  const Lights& lights = context.lights;
  const int count = lightCount(lights);
  if (count == 0) return 0.0f;
  const float choice = 1.0f / float(count);
  if (hit) {
    const AreaLight* light = lights.areaLightAt(context.scene, *hit);
    return light ? choice * Lights::areaPdfSolidAngle(*light, from, *hit) : 0.0f;
  }
  return lights.environment ? choice * lights.environment->pdf(wi) : 0.0f;
}

Color tracePathMis(TraceContext& context, Ray ray, Sampler& sampler, const MisWeights& weights) {
  constexpr int kRouletteFromBounce = 3;
  const Scene& scene = context.scene;
  Color radiance(0.0f), throughput(1.0f);
  bool afterDelta = true;  // the camera ray, or a mirror or glass bounce: emission counts in full
  Point3 previousPoint(0.0f);  // the last non-delta vertex, and the pdf its BSDF sample had
  float previousPdf = 0.0f;
  for (int bounce = 0;; ++bounce) {
    const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
    // 1. The environment, found by the BSDF sample: weighted against light sampling.
    if (!hit) {
      if (afterDelta) {
        radiance += throughput * context.background(ray.direction);
      } else if (weights.bsdf && context.lights.environment) {
        const float pdfLight = oneLightPdf(context, previousPoint, ray.direction, std::nullopt);
        radiance += throughput * context.lights.environment->pixelRadiance(ray.direction) *
                    weights.bsdf(previousPdf, pdfLight);
      }
      break;
    }
    // 2. Emission, likewise.
    const Vec3 wo = -ray.direction;
    const Color emitted = emittedRadiance(scene, *hit, wo);
    if (afterDelta) {
      radiance += throughput * emitted;
    } else if (weights.bsdf && maxComponent(emitted) > 0.0f) {
      const float pdfLight = oneLightPdf(context, previousPoint, ray.direction, hit);
      radiance += throughput * emitted * weights.bsdf(previousPdf, pdfLight);
    }
    if (bounce >= context.settings.maxDepth) break;

    // 3. Light sampling, where the lobe is not a delta: point lights in full
    // (no BSDF sample finds them), one of the other lights weighted.
    const Bsdf bsdf = context.bsdf(*hit, wo);
    if (weights.light && !bsdf.isDelta()) {
      for (const PointLight& light : context.lights.points) {
        const Vec3 toLight = light.position - hit->point;
        const float distanceSquared = glm::dot(toLight, toLight);
        if (!(distanceSquared > 0.0f)) continue;
        const float distance = std::sqrt(distanceSquared);
        const Vec3 wi = toLight / distance;
        const float cosSurface = glm::dot(wi, bsdf.normal());
        if (cosSurface <= 0.0f) continue;
        const Color f = bsdf.f(wo, wi);
        if (maxComponent(f) <= 0.0f || !visible(context, *hit, wi, distance)) continue;
        radiance += throughput * f * light.intensity * (cosSurface / distanceSquared);
      }
      const Vec2 u2 = sampler.next2D();
      const std::optional<LightSample> light = sampleOneLight(context, hit->point, Vec3(sampler.next1D(), u2));
      if (light && light->pdf > 0.0f) {
        const float cosSurface = glm::dot(light->wi, bsdf.normal());
        const Color f = cosSurface > 0.0f ? bsdf.f(wo, light->wi) : Color(0.0f);
        if (maxComponent(f) > 0.0f && maxComponent(light->radiance) > 0.0f &&
            visible(context, *hit, light->wi, light->distance)) {
          radiance += throughput * f * light->radiance * (cosSurface / light->pdf) *
                      weights.light(light->pdf, bsdf.pdf(wo, light->wi));
        }
      }
    }

    // 4. The BSDF sample, as task 5.
    const std::optional<BsdfSample> sample = bsdf.sample(wo, sampler.next2D());
    if (!sample || !(sample->pdf > 0.0f)) break;
    const float cosine = std::abs(glm::dot(sample->wi, bsdf.normal()));
    throughput *= sample->f * (cosine / sample->pdf);
    if (!(maxComponent(throughput) > 0.0f)) break;
    afterDelta = sample->isDelta;
    previousPoint = hit->point;
    previousPdf = sample->pdf;

    // 5. Russian roulette from the third bounce, as task 5.
    if (bounce + 1 >= kRouletteFromBounce) {
      const float q = std::min(0.95f, maxComponent(throughput));
      if (sampler.next1D() >= q) break;
      throughput /= q;
    }
    ray = Ray{offsetRayOrigin(hit->point, hit->geometricNormal, sample->wi), sample->wi};
  }
  return radiance;
}

}  // namespace pathlab
