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
#include "util/random.h"
#include "util/ray.h"

namespace pathlab {

// Multiple importance sampling of light samples and BSDF samples (Veach):
// a sample drawn with pdf p_a, where the other strategy would have drawn it
// with pdf p_b, is weighted p_a / (p_a + p_b) (balance) or
// p_a^2 / (p_a^2 + p_b^2) (power). None: light samples only, as in tasks 4-5
// (the weight is 1).
enum class MisHeuristic { None, Balance, Power };

float misWeight(MisHeuristic heuristic, float pdfThis, float pdfOther);

struct SamplingStrategy {
  bool lightSampling = true;   // next-event estimation; off: BSDF sampling only
  bool cosineSampling = true;  // diffuse bounces cosine-weighted; off: uniform hemisphere
  MisHeuristic mis = MisHeuristic::None;  // combine light and BSDF samples (needs lightSampling)
  bool russianRoulette = true;  // end long paths at random from the third bounce (unbiased)

  // The course's recipe: what tracePath (task 5) does.
  bool isRecipe() const { return lightSampling && cosineSampling && mis == MisHeuristic::None && russianRoulette; }
};

// The radiance arriving along a camera ray, by `strategy`; honours
// context.settings (maxDepth, lightSamples) as tracePath does.
Color traceWithStrategy(TraceContext& context, Ray ray, Sampler& sampler, const SamplingStrategy& strategy);

}  // namespace pathlab
