#include "render/strategies.h"

#include "render/render.h"

#include <algorithm>
#include <cmath>

#include "core/bsdf.h"
#include "tasks/direct_lighting.h"
#include "util/sampling.h"

namespace pathlab {
namespace {

constexpr int kRouletteFromBounce = 3;  // T5.2 step 6

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

MisWeights misWeights(MisEstimator estimator) {
  constexpr auto one = [](float, float) { return 1.0f; };
  switch (estimator) {
    case MisEstimator::LightSampling: return {one, nullptr};
    case MisEstimator::BsdfSampling: return {nullptr, one};
    case MisEstimator::Balance: return {&balanceHeuristic, &balanceHeuristic};
    case MisEstimator::Power: return {&powerHeuristic, &powerHeuristic};
  }
  return {};
}

const char* misEstimatorName(MisEstimator estimator) {
  for (const IntegratorEntry& entry : kIntegrators) {  // the integrator that runs it gives the name
    if (misEstimatorOf(entry.integrator) == estimator) return entry.name;
  }
  return "?";
}

// T5.2's loop, with each step the strategy changes marked.
Color traceWithStrategy(TraceContext& context, Ray ray, Sampler& sampler, const SamplingStrategy& strategy) {
  const Scene& scene = context.scene;
  const bool nee = strategy.lightSampling;
  Color radiance(0.0f), throughput(1.0f);
  bool countEmission = true;  // the camera ray, or after a delta bounce
  for (int bounce = 0;; ++bounce) {
    const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
    if (!hit) {
      if (countEmission || !nee) radiance += throughput * context.background(ray.direction);
      break;
    }
    const Vec3 wo = -ray.direction;
    if (countEmission || !nee) radiance += throughput * emittedRadiance(scene, *hit, wo);
    if (bounce >= context.settings.maxDepth) break;

    const Bsdf bsdf = context.bsdf(*hit, wo);
    if (nee) radiance += throughput * estimateDirectLighting(context, *hit, bsdf, wo, sampler);

    const std::optional<BsdfSample> sample = strategy.cosineSampling || bsdf.isDelta()
                                                 ? bsdf.sample(wo, sampler.next2D())
                                                 : sampleUniformHemisphere(bsdf, wo, sampler.next2D());
    if (!sample || !(sample->pdf > 0.0f)) break;
    const float cosine = std::abs(glm::dot(sample->wi, bsdf.normal()));
    throughput *= sample->f * (cosine / sample->pdf);
    if (!(maxComponent(throughput) > 0.0f)) break;
    countEmission = sample->isDelta;

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
