// Task 5 — path tracing (reference solution).
#include "tasks/path_tracing.h"

#include <algorithm>
#include <cmath>

#include "core/bsdf.h"
#include "tasks/direct_lighting.h"

namespace pathlab {

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
  for (int bounce = 0;; ++bounce) {
    // 1. The next hit; a ray that leaves the scene sees the environment,
    // which next-event estimation already counted after a diffuse bounce.
    const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
    if (!hit) {
      if (countEmission) radiance += throughput * context.background(ray.direction);
      break;
    }
    // 2. Emission, likewise only where no light sample covered it.
    const Vec3 wo = -ray.direction;
    if (countEmission) radiance += throughput * emittedRadiance(scene, *hit, wo);
    // 3. -m: at most maxDepth bounces.
    if (bounce >= context.settings.maxDepth) break;

    // 4. Next-event estimation.
    const Bsdf bsdf = context.bsdf(*hit, wo);
    radiance += throughput * estimateDirectLighting(context, *hit, bsdf, wo, sampler);

    // 5. The next direction.
    const std::optional<BsdfSample> sample = bsdf.sample(wo, sampler.next2D());
    if (!sample || !(sample->pdf > 0.0f)) break;
    const float cosine = std::abs(glm::dot(sample->wi, bsdf.normal()));
    throughput *= sample->f * (cosine / sample->pdf);
    if (!(maxComponent(throughput) > 0.0f)) break;
    countEmission = sample->isDelta;

    // 6. Russian roulette: continue with probability q and divide by q, so
    // the expected value is unchanged.
    if (bounce + 1 >= kRouletteFromBounce) {
      const float q = std::min(0.95f, maxComponent(throughput));
      if (sampler.next1D() >= q) break;
      throughput /= q;
    }
    // 7. The next ray, off the surface.
    ray = Ray{offsetRayOrigin(hit->point, hit->geometricNormal, sample->wi), sample->wi};
  }
  return radiance;
}

}  // namespace pathlab
