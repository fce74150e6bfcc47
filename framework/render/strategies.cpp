#include "render/strategies.h"

#include <algorithm>
#include <cmath>

#include "core/bsdf.h"
#include "tasks/direct_lighting.h"
#include "util/sampling.h"

namespace pathlab {
namespace {

constexpr int kRouletteFromBounce = 3;      // T5.2 step 6
constexpr float kShadowShortening = 1e-4f;  // as T4.4's model answer: shadow rays end short of the light

// The shadow ray from the surface towards a point at `distance` along wi
// (kInfinity: towards the environment), aimed from the offset origin at the
// light point itself.
bool visible(TraceContext& context, const Hit& hit, const Vec3& wi, float distance) {
  const Point3 origin = offsetRayOrigin(hit.point, hit.geometricNormal, wi);
  if (distance == kInfinity) return !context.occluded(Ray{origin, wi}, Interval{0.0f, kInfinity});
  const Vec3 toLight = hit.point + wi * distance - origin;
  const float remaining = glm::length(toLight);
  return !context.occluded(Ray{origin, toLight / remaining}, Interval{0.0f, remaining * (1.0f - kShadowShortening)});
}

// Next-event estimation as in T4.4, each light sample weighted against the
// BSDF sample that could have found the same light (multi-sample MIS:
// lightSamples light samples against one BSDF sample). The random numbers
// are drawn in T4.4's order.
Color directLighting(TraceContext& context, const Hit& hit, const Bsdf& bsdf, const Vec3& wo, Sampler& sampler,
                     MisHeuristic mis) {
  if (bsdf.isDelta()) return Color(0.0f);
  const int samples = context.settings.lightSamples;
  auto weight = [&](float pdfLight, const Vec3& wi) {
    return mis == MisHeuristic::None ? 1.0f : misWeight(mis, float(samples) * pdfLight, bsdf.pdf(wo, wi));
  };
  Color radiance(0.0f);
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
    radiance += f * light.intensity * (cosSurface / distanceSquared);  // a delta light: no BSDF sample finds it
  }
  for (const AreaLight& light : context.lights.areas) {
    Color sum(0.0f);
    for (int i = 0; i < samples; ++i) {
      const AreaSample sample = light.sample(sampler.next2D());
      const std::optional<LightDirection> direction = lightDirection(hit.point, sample);
      if (!direction) continue;
      const float cosSurface = glm::dot(direction->wi, bsdf.normal());
      if (cosSurface <= 0.0f) continue;
      const Color f = bsdf.f(wo, direction->wi);
      if (maxComponent(f) <= 0.0f || !visible(context, hit, direction->wi, direction->distance)) continue;
      sum += f * sample.radiance * (cosSurface / direction->pdfSolidAngle) *
             weight(direction->pdfSolidAngle, direction->wi);
    }
    radiance += sum / float(samples);
  }
  if (const std::optional<EnvironmentLight>& environment = context.lights.environment) {
    Color sum(0.0f);
    for (int i = 0; i < samples; ++i) {
      const std::optional<EnvironmentLightSample> sample = environment->sample(sampler.next2D());
      if (!sample) continue;
      const float cosSurface = glm::dot(sample->direction, bsdf.normal());
      if (cosSurface <= 0.0f) continue;
      const Color f = bsdf.f(wo, sample->direction);
      if (maxComponent(f) <= 0.0f || maxComponent(sample->radiance) <= 0.0f ||
          !visible(context, hit, sample->direction, kInfinity)) {
        continue;
      }
      sum += f * sample->radiance * (cosSurface / sample->pdfSolidAngle) *
             weight(sample->pdfSolidAngle, sample->direction);
    }
    radiance += sum / float(samples);
  }
  return radiance;
}

// A diffuse bounce drawn uniformly over the hemisphere: p = 1 / (2 pi).
std::optional<BsdfSample> sampleUniformHemisphere(const Bsdf& bsdf, const Vec3& wo, Vec2 u) {
  const Vec3 local = uniformHemisphereDirection(u);
  if (!(local.z > 0.0f)) return std::nullopt;
  BsdfSample s;
  s.wi = glm::normalize(bsdf.frame().toWorld(local));
  s.f = bsdf.f(wo, s.wi);
  s.pdf = 0.5f * kInvPi;
  return s;
}

}  // namespace

float misWeight(MisHeuristic heuristic, float pdfThis, float pdfOther) {
  if (heuristic == MisHeuristic::None) return 1.0f;
  if (heuristic == MisHeuristic::Balance) return pdfThis / (pdfThis + pdfOther);
  const float a = pdfThis * pdfThis, b = pdfOther * pdfOther;
  return a / (a + b);
}

// T5.2's loop, with each step the strategy changes marked.
Color traceWithStrategy(TraceContext& context, Ray ray, Sampler& sampler, const SamplingStrategy& strategy) {
  const Scene& scene = context.scene;
  const bool nee = strategy.lightSampling;
  const MisHeuristic mis = nee ? strategy.mis : MisHeuristic::None;
  Color radiance(0.0f), throughput(1.0f);
  bool countEmission = true;  // the camera ray, or after a delta bounce
  // For MIS: where the last diffuse bounce was, and the pdf with which it chose this ray.
  Point3 previousPoint(0.0f);
  float previousBsdfPdf = 0.0f;
  for (int bounce = 0;; ++bounce) {
    const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
    if (!hit) {
      if (countEmission || !nee) {
        radiance += throughput * context.background(ray.direction);
      } else if (mis != MisHeuristic::None && context.lights.environment) {
        // Strategy: light found by a BSDF sample, weighted against NEE's chance of finding it.
        const float pdfLight = float(context.settings.lightSamples) * context.lights.environment->pdf(ray.direction);
        radiance += throughput * context.lights.environment->pixelRadiance(ray.direction) *
                    misWeight(mis, previousBsdfPdf, pdfLight);
      }
      break;
    }
    const Vec3 wo = -ray.direction;
    if (countEmission || !nee) {
      radiance += throughput * emittedRadiance(scene, *hit, wo);
    } else if (mis != MisHeuristic::None) {
      if (const AreaLight* light = context.lights.areaLightAt(scene, *hit)) {
        const float pdfLight =
            float(context.settings.lightSamples) * Lights::areaPdfSolidAngle(*light, previousPoint, *hit);
        radiance += throughput * emittedRadiance(scene, *hit, wo) * misWeight(mis, previousBsdfPdf, pdfLight);
      }
    }
    if (bounce >= context.settings.maxDepth) break;

    const Bsdf bsdf = context.bsdf(*hit, wo);
    if (nee) radiance += throughput * directLighting(context, *hit, bsdf, wo, sampler, mis);

    const std::optional<BsdfSample> sample = strategy.cosineSampling || bsdf.isDelta()
                                                 ? bsdf.sample(wo, sampler.next2D())
                                                 : sampleUniformHemisphere(bsdf, wo, sampler.next2D());
    if (!sample || !(sample->pdf > 0.0f)) break;
    const float cosine = std::abs(glm::dot(sample->wi, bsdf.normal()));
    throughput *= sample->f * (cosine / sample->pdf);
    if (!(maxComponent(throughput) > 0.0f)) break;
    countEmission = sample->isDelta;
    previousPoint = hit->point;
    previousBsdfPdf = sample->pdf;

    if (strategy.russianRoulette && bounce + 1 >= kRouletteFromBounce) {
      const float q = std::min(0.95f, maxComponent(throughput));
      if (sampler.next1D() >= q) break;
      throughput /= q;
    }
    ray = Ray{offsetRayOrigin(hit->point, hit->geometricNormal, sample->wi), sample->wi};
  }
  return radiance;
}

}  // namespace pathlab
