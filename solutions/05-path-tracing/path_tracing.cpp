// Task 5 — path tracing (reference solution).
#include "pathlab/tasks/path_tracing.h"

#include <algorithm>
#include <cmath>

#include "pathlab/bsdf.h"
#include "pathlab/tasks/direct_lighting.h"

namespace pathlab {
namespace {

// The uniform-hemisphere strategy (pathlab-bench converge): p = 1 / (2 pi).
std::optional<BsdfSample> sampleUniformHemisphere(const Bsdf& bsdf, const Vec3& wo, Vec2 u) {
  const float z = u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
  if (!(z > 0.0f)) return std::nullopt;
  BsdfSample s;
  s.wi = glm::normalize(bsdf.frame().toWorld(Vec3(r * std::cos(phi), r * std::sin(phi), z)));
  s.f = bsdf.f(wo, s.wi);
  s.pdf = 0.5f * kInvPi;
  return s;
}

}  // namespace

// Cosine-weighted: a uniform point on the unit disk (concentric-free polar
// form r = sqrt(u1)), lifted onto the hemisphere (Malley's method).
Vec3 sampleDiffuseDirection(Vec2 u) {
  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x))};
}

float diffuseDirectionPdf(const Vec3& wi) { return wi.z > 0.0f ? wi.z * kInvPi : 0.0f; }

Color tracePath(TraceContext& context, Ray ray, Sampler& sampler) {
  constexpr int kRouletteFromBounce = 3;
  const Scene& scene = context.scene;
  Color radiance(0.0f), throughput(1.0f);
  bool countEmission = true;  // light seen directly, or through a mirror (task 6)
  // For multiple importance sampling (a reference strategy): where the last
  // diffuse bounce was, and the pdf with which it chose this ray.
  Point3 previousPoint(0.0f);
  float previousBsdfPdf = 0.0f;
  const bool mis = context.mis != MisHeuristic::None && context.lightSampling;
  for (int bounce = 0;; ++bounce) {
    const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
    if (!hit) {
      // The environment is a light too: after a diffuse bounce next-event
      // estimation already counted it.
      if (countEmission || !context.lightSampling) {
        radiance += throughput * context.background(ray.direction);
      } else if (mis && context.lights.environment) {
        const float pdfLight = float(context.lightSamples) * context.lights.environment->pdf(ray.direction);
        radiance += throughput * context.lights.environment->pixelRadiance(ray.direction) *
                    misWeight(context.mis, previousBsdfPdf, pdfLight);
      }
      break;
    }
    const Vec3 wo = -ray.direction;
    // Emission found by a BSDF sample after a diffuse bounce was already
    // counted by next-event estimation at the previous vertex.
    if (countEmission || !context.lightSampling) {
      radiance += throughput * emittedRadiance(scene, *hit, wo);
    } else if (mis) {
      if (const AreaLight* light = context.lights.areaLightAt(scene, *hit)) {
        const float pdfLight = float(context.lightSamples) * Lights::areaPdfSolidAngle(*light, previousPoint, *hit);
        radiance += throughput * emittedRadiance(scene, *hit, wo) * misWeight(context.mis, previousBsdfPdf, pdfLight);
      }
    }
    if (bounce >= context.maxDepth) break;  // -m: at most maxDepth bounces

    const Bsdf bsdf(scene.materials[hit->material], *hit, wo);
    if (context.lightSampling) radiance += throughput * estimateDirectLighting(context, *hit, bsdf, wo, sampler);

    const std::optional<BsdfSample> sample = context.cosineSampling || bsdf.isDelta()
                                                 ? bsdf.sample(wo, sampler.next2D())
                                                 : sampleUniformHemisphere(bsdf, wo, sampler.next2D());
    if (!sample || !(sample->pdf > 0.0f)) break;
    const float cosine = std::abs(glm::dot(sample->wi, bsdf.normal()));
    throughput *= sample->f * (sample->isDelta ? 1.0f : cosine / sample->pdf);
    if (!(maxComponent(throughput) > 0.0f)) break;
    countEmission = sample->isDelta;
    previousPoint = hit->point;
    previousBsdfPdf = sample->pdf;

    // Russian roulette: continue with probability q and divide by q, so the
    // expected value is unchanged.
    if (context.russianRoulette && bounce + 1 >= kRouletteFromBounce) {
      const float q = std::min(0.95f, maxComponent(throughput));
      if (sampler.next1D() >= q) break;
      throughput /= q;
    }
    ray = Ray{offsetRayOrigin(hit->point, hit->geometricNormal, sample->wi), sample->wi};
  }
  return radiance;
}

}  // namespace pathlab
