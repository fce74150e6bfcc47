// Sampling strategies beyond the course's recipe, for comparing them
// (pathlab-bench converge, "going further" in the handouts): the framework's
// own path tracer, assembled from the tasks' pieces (task 4's BRDF, ray
// offset and light directions, task 5's diffuse sampling through the BSDF,
// task 6's lobes, task 7's environment sampling). The student's tracePath and
// estimateDirectLighting follow the recipe only and honour no strategy flag;
// with the default strategy this tracer takes the same random numbers in the
// same order as the model answers, so its images are bit-identical to theirs
// (a framework test checks it).
#pragma once

#include "core/trace.h"
#include "tasks/mis.h"
#include "util/random.h"
#include "util/ray.h"

namespace pathlab {

struct SamplingStrategy {
  bool lightSampling = true;   // next-event estimation; off: BSDF sampling only
  bool cosineSampling = true;  // diffuse bounces cosine-weighted; off: uniform hemisphere
  bool russianRoulette = true;  // end long paths at random from the third bounce (unbiased)

  // The course's recipe: what tracePath (task 5) does.
  bool isRecipe() const { return lightSampling && cosineSampling && russianRoulette; }
};

// The estimators task 9's tracePathMis gives, by the weights it is handed:
// one light sample per vertex alone, the BSDF sample alone, or both combined
// by multiple importance sampling (Veach) with the balance or the power
// heuristic (task 9's balanceHeuristic, powerHeuristic). The project's only MIS.
enum class MisEstimator { LightSampling, BsdfSampling, Balance, Power };

MisWeights misWeights(MisEstimator estimator);
const char* misEstimatorName(MisEstimator estimator);

// The radiance arriving along a camera ray, by `strategy`; honours
// context.settings (maxDepth, lightSamples) as tracePath does.
Color traceWithStrategy(TraceContext& context, Ray ray, Sampler& sampler, const SamplingStrategy& strategy);

}  // namespace pathlab
