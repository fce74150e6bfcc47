// Task 9 — multiple importance sampling: light sampling and BSDF sampling,
// each weighed where it is strong. Implemented in tasks/09-mis/mis.cpp (the
// student's file; where the task is not the student's, the programs link the
// course's reference in its place).
#pragma once

#include <optional>

#include "core/hit.h"
#include "core/trace.h"
#include "util/random.h"
#include "util/ray.h"

namespace pathlab {

// T9.1: the weight of a sample drawn by one strategy with density pdfThis,
// where the other strategy would have drawn it with density pdfOther (one
// sample of each): balance pdfThis / (pdfThis + pdfOther), power (beta = 2)
// pdfThis^2 / (pdfThis^2 + pdfOther^2). Both densities per unit solid angle.
// pdfOther = 0 (the other strategy cannot make this sample) gives 1.
float balanceHeuristic(float pdfThis, float pdfOther);
float powerHeuristic(float pdfThis, float pdfOther);

// A direction towards one light, chosen among the scene's area lights and
// its environment (point lights are not in the choice: no BSDF sample can
// find them).
struct LightSample {
  Vec3 wi{0.0f};             // unit, from the shading point towards the light
  float distance = 0.0f;     // to the point on the light; kInfinity for the environment
  Color radiance{0.0f};      // arriving along -wi from that point (Le, or the map's pixel)
  float pdf = 0.0f;          // per unit solid angle, the choice of the light included
};

// T9.2: choose one light (any rule that gives every light that can reach
// `from` a positive probability), then a point or direction on it with its
// own sampler (area: AreaLight::sample and task 4's lightDirection;
// environment: EnvironmentLight::sample); the pdf is the light's choice
// probability times its solid-angle pdf. Nothing if the scene has no such
// light or the sample faces away from `from`. u: three uniform numbers.
std::optional<LightSample> sampleOneLight(const TraceContext& context, const Point3& from, Vec3 u);

// T9.2: the density with which sampleOneLight, called at `from`, returns the
// direction wi, where the ray from `from` along wi first meets `hit` (an
// emitting surface) or nothing (the environment): the same measure and the
// same choice probability. 0 where sampleOneLight never goes.
float oneLightPdf(const TraceContext& context, const Point3& from, const Vec3& wi, const std::optional<Hit>& hit);

// How a path weighs each light it finds: the light sample's weight at a
// vertex, and the weight of an emitter a BSDF sample hits (or of the
// environment it escapes to), each from (pdf of its own strategy, pdf of the
// other). A null weight switches its strategy off, the renderers' four
// estimators (misWeights, render/strategies.h):
//   MIS (power or balance): a heuristic for both;
//   light sampling alone: light 1, bsdf null (no emission found by a BSDF
//     sample counts, but after the camera ray or a delta bounce);
//   BSDF sampling alone: light null, bsdf 1. No light sample is taken at
//     all, point lights included: a point light is then never seen (no BSDF
//     sample can find a point), so BSDF sampling alone renders a scene lit
//     only by point lights black. T9.3 tests this.
struct MisWeights {
  float (*light)(float pdfLight, float pdfBsdf) = nullptr;
  float (*bsdf)(float pdfBsdf, float pdfLight) = nullptr;
};

// T9.3: task 5's path tracer with one light sample per vertex (T9.2) and the
// BSDF sample's emission both kept, each weighted by `weights`; point lights
// and delta lobes (mirror, glass) as in tasks 4 to 6, with weight 1.
// Every random number comes from `sampler`, in any order: the same sampler
// gives the same path (as task 5's).
Color tracePathMis(TraceContext& context, Ray ray, Sampler& sampler, const MisWeights& weights);

}  // namespace pathlab
