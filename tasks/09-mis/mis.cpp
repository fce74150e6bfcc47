// Task 9 — multiple importance sampling
//
// Goal: one path tracer that is good at everything tasks 4 and 5 were each
// bad at: a sharp highlight of a large light (where light sampling is
// noisy), a rough surface under a small light (where BSDF sampling is
// noisy). Handout: tasks/09-mis/README.md
//
// Functions to write (declared in framework/tasks/mis.h):
//   T9.1 balanceHeuristic, powerHeuristic   the weights
//   T9.2 sampleOneLight, oneLightPdf        one light sample, and its density for any direction
//   T9.3 tracePathMis                       the path tracer with both strategies
//
// Check your work:
//   ./build/pathlab media/scenes/veach-plates.json --integrator mis -o plates.png
//   ./build/pathlab debug --task 9 --view weights media/scenes/veach-plates.json -o weights.png
//   ctest --test-dir build -R 09-mis --output-on-failure
#include "tasks/mis.h"

#include <algorithm>
#include <cmath>

#include "core/bsdf.h"
#include "tasks/direct_lighting.h"
#include "util/todo.h"

namespace pathlab {

// T9.1 — The heuristics.
//
// Two strategies can make the same sample x: light sampling with density
// p_light(x), BSDF sampling with density p_bsdf(x). Each sample is kept with
// a weight, and the estimate is
//   F = w_light(x_l) f(x_l) / p_light(x_l) + w_bsdf(x_b) f(x_b) / p_bsdf(x_b).
// It is unbiased whenever w_light(x) + w_bsdf(x) = 1 wherever f(x) != 0
// (and a weight is 0 where its strategy cannot make x). Veach's choices:
//   balance   w(x) = p_this / (p_this + p_other)
//   power     w(x) = p_this^2 / (p_this^2 + p_other^2)      (beta = 2)
// Both densities must be in the same measure: per unit solid angle.
// p_other = 0 gives 1; p_this = 0 gives 0.
//
// PITFALL: a sharp lobe's pdf can pass 1e19, and squaring it overflows a
// float (inf / inf is NaN). Divide by the larger density first.
float balanceHeuristic(float pdfThis, float pdfOther) {
  // TODO(T9.1): the balance heuristic.
  PATHLAB_TODO("T9.1");
  (void)pdfThis, (void)pdfOther;
  return 1.0f;
}

float powerHeuristic(float pdfThis, float pdfOther) {
  // TODO(T9.1): the power heuristic, without overflow.
  PATHLAB_TODO("T9.1");
  (void)pdfThis, (void)pdfOther;
  return 1.0f;
}

// T9.2 — One light sample, and its density.
//
// Task 4 sampled every area light at every vertex. Here each vertex takes
// one light sample: choose light k among the area lights
// (context.lights.areas) and the environment (context.lights.environment,
// if any) with probability P(k), then sample it:
//   area light:   AreaSample s = light.sample(Vec2(u.y, u.z)); task 4's
//                 lightDirection(from, s) gives wi, the distance and the
//                 solid-angle pdf (nothing if the light faces away);
//                 the radiance is s.radiance.
//   environment:  context.lights.environment->sample(Vec2(u.y, u.z)) gives
//                 the direction, its radiance and its solid-angle pdf;
//                 distance kInfinity.
// The sample's density is P(k) times the light's own pdf: a direction that
// only light k can give has p(wi) = P(k) p_k(wi). P(k) may be uniform, or
// follow the lights' power: any rule where every light has P(k) > 0.
//
// oneLightPdf is the same density for a direction the BSDF chose: the ray
// from `from` along wi hits `hit` (then only the area light under it, if
// any: context.lights.areaLightAt(context.scene, *hit), with
// Lights::areaPdfSolidAngle(light, from, *hit)) or escapes (the environment:
// environment->pdf(wi)). Multiply by the same P(k).
//
// PITFALL: a light seen from behind emits nothing towards `from`, and light
// sampling never returns such a direction: its density there is 0.
std::optional<LightSample> sampleOneLight(const TraceContext& context, const Point3& from, Vec3 u) {
  // TODO(T9.2): choose a light, sample it, and multiply the pdfs.
  PATHLAB_TODO("T9.2");
  (void)context, (void)from, (void)u;
  return std::nullopt;
}

float oneLightPdf(const TraceContext& context, const Point3& from, const Vec3& wi, const std::optional<Hit>& hit) {
  // TODO(T9.2): the density of the sampler above for the direction wi.
  PATHLAB_TODO("T9.2");
  (void)context, (void)from, (void)wi, (void)hit;
  return 0.0f;
}

// T9.3 — The path tracer with MIS.
//
// Task 5's loop, with both strategies kept at every non-delta vertex (both
// samples, every time: not one of the two chosen by a coin):
//   1. No hit: after the camera ray or a delta bounce, add
//      throughput * context.background(dir) in full. Otherwise the BSDF
//      sample found the environment: add
//      throughput * environment->pixelRadiance(dir) * weights.bsdf(p_bsdf, p_light),
//      p_bsdf the pdf of the bounce that made this ray, p_light =
//      oneLightPdf(context, previous vertex, dir, nothing). Stop.
//   2. Emission at the hit: in full after the camera ray or a delta bounce;
//      else weighted the same way, p_light = oneLightPdf(..., hit).
//   3. If bounce >= context.settings.maxDepth, stop.
//   4. Light sampling, if the lobe is not a delta (bsdf.isDelta()): point
//      lights as in task 4, in full (no BSDF sample can find a point; the
//      shadow ray stops at the light; a light at distance 0 adds nothing); then
//      one sampleOneLight sample at hit->point: if it is above the surface
//      and visible (task 4's shadow ray), add
//      throughput * f * Le * cos / p_light * weights.light(p_light, bsdf.pdf(wo, wi)).
//   5. The BSDF sample, roulette and the next ray as in task 5; keep its
//      point and pdf for steps 1 and 2.
// A null weight switches its strategy off: weights.light null, no light
// sampling at all, point lights included (BSDF sampling alone); weights.bsdf
// null, no emission found by a BSDF sample (light sampling alone, as task
// 5). So one function gives the estimators the renderer compares
// (MisWeights in framework/tasks/mis.h defines each).
//
// PITFALL: both pdfs of one weight belong to the same direction and the
// same vertex: the previous vertex's BSDF pdf is for the ray that arrived
// here, not for the next one.
Color tracePathMis(TraceContext& context, Ray ray, Sampler& sampler, const MisWeights& weights) {
  // TODO(T9.3): the loop above.
  PATHLAB_TODO("T9.3");
  (void)context, (void)ray, (void)sampler, (void)weights;
  return Color(0.0f);
}

}  // namespace pathlab
