// Task 5 — path tracing
//
// Goal: light that bounces — colour bleeding, soft indirect light, the
// ceiling lit by the floor. Handout: tasks/05-path-tracing/README.md
//
// Functions to write (declared in framework/tasks/path_tracing.h):
//   T5.1 sampleDiffuseDirection, diffuseDirectionPdf   cosine-weighted hemisphere sampling
//   T5.2 tracePath                                     the path tracer
//
// Check your work:
//   ./build/pathlab -o path.png                     (the default integrator is path)
//   ./build/pathlab debug --task 5 --view bounces -o bounces.png
//   ctest --test-dir build -R 05-path-tracing --output-on-failure
#include "tasks/path_tracing.h"

#include <algorithm>
#include <cmath>

#include "core/bsdf.h"
#include "tasks/direct_lighting.h"
#include "util/todo.h"

namespace pathlab {

// T5.1 — Sampling a diffuse bounce.
//
// In the local frame the normal is +z and cos(theta) = wi.z. Reflected
// radiance integrates f Li cos(theta); sampling wi with pdf proportional to
// cos(theta) cancels that cosine:
//   p(wi) = cos(theta) / pi                       (integrates to 1 over the hemisphere)
// Inversion method: pick a point uniformly on the unit disk,
//   r = sqrt(u.x), phi = 2 pi u.y,  x = r cos(phi), y = r sin(phi)
// and lift it onto the hemisphere: z = sqrt(1 - x^2 - y^2) = sqrt(1 - u.x).
//
// The pdf must describe exactly the sampler you wrote (uniform hemisphere
// sampling with p = 1 / (2 pi) is correct too, only noisier).
// PITFALL: directions below the surface (z <= 0) have pdf 0.
Vec3 sampleDiffuseDirection(Vec2 u) {
  // TODO(T5.1): a cosine-weighted direction.
  PATHLAB_TODO("T5.1");
  (void)u;
  return Vec3(0.0f, 0.0f, 1.0f);
}

float diffuseDirectionPdf(const Vec3& wi) {
  // TODO(T5.1): the pdf of the sampler above.
  PATHLAB_TODO("T5.1");
  (void)wi;
  return 0.0f;
}

// T5.2 — The path tracer.
//
//   L = Le + integral f L cos dw, estimated one path at a time:
//   radiance += throughput * (what this vertex adds),
//   throughput *= f cos(theta) / pdf at every bounce.
//
// Recipe, for bounce = 0, 1, 2, ...:
//   1. hit = context.intersect(ray, Interval{0, kInfinity}); if nothing is hit,
//      the ray sees the environment: add throughput * context.background(ray.direction)
//      under the same rule as emission (step 2), and stop.
//   2. wo = -ray.direction. Emission: add throughput * emittedRadiance(scene, hit, wo)
//      only for the camera ray (bounce 0) or after a delta bounce — after a
//      diffuse bounce that light was already counted by step 4 (next-event
//      estimation, which samples area lights and the environment) at the
//      previous vertex.
//   3. If bounce >= context.settings.maxDepth, stop: -m counts bounces, so
//      -m 0 shows only emitters and -m 1 is direct lighting.
//   4. bsdf = context.bsdf(hit, wo); add throughput * estimateDirectLighting(...).
//   5. Sample the next direction: s = bsdf.sample(wo, sampler.next2D()); stop if
//      there is none or s->pdf is 0. throughput *= s->f * |cos| / s->pdf,
//      cos = dot(s->wi, bsdf.normal()) (for every lobe: a mirror's f holds
//      1 / |cos| so this gives its reflectance, task 6).
//   6. Russian roulette from the third bounce on: continue with probability
//      q = min(0.95, max component of throughput); if sampler.next1D() >= q
//      stop, else throughput /= q. (Without the division the image is too
//      dark; the estimator stays unbiased with it.)
//   7. The next ray starts at offsetRayOrigin(hit->point, hit->geometricNormal, s->wi).
//
// PITFALL: use the trace context's intersect() so rays are counted and the
// debugger can show them.
Color tracePath(TraceContext& context, Ray ray, Sampler& sampler) {
  // TODO(T5.2): the loop above.
  PATHLAB_TODO("T5.2");
  (void)context, (void)ray, (void)sampler;
  return Color(0.0f);
}

}  // namespace pathlab
