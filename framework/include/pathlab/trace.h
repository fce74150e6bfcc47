// What an estimator needs while tracing one sample: the scene, its BVH and
// lights, the render settings, and per-thread counters. Estimators trace
// rays through intersect() and occluded() so rays are counted (rays/s) and,
// in the debugger, recorded.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "pathlab/accelerator.h"
#include "pathlab/lights.h"
#include "pathlab/scene.h"

namespace pathlab {

// One ray as the debugger records it.
struct TracedRay {
  Ray ray;
  Interval range;
  bool shadow = false;  // an occlusion query
  bool hit = false;     // blocked (shadow) or hit something
  Hit record;           // the closest hit (not for shadow rays); record.t is kInfinity on a miss
};

struct TraceContext {
  const Scene& scene;
  const Accelerator& accelerator;
  const Lights& lights;
  int lightSamples = 1;         // -l: samples per area light
  int maxDepth = 4;             // -m: the most bounces a path may make
  bool russianRoulette = true;  // end long paths at random (unbiased)
  // Sampling strategies the reference path tracer honours, for comparing
  // them (pathlab-bench converge; "going further" in the handouts):
  bool lightSampling = true;    // next-event estimation; off: BSDF sampling only
  bool cosineSampling = true;   // diffuse bounces cosine-weighted; off: uniform hemisphere
  MisHeuristic mis = MisHeuristic::None;  // combine light and BSDF samples (reference only)
  IVec2 pixel{0, 0};            // the pixel being rendered
  uint64_t rays = 0;            // rays traced by this thread
  std::vector<TracedRay>* log = nullptr;  // when set, every ray is recorded

  TraceContext(const Scene& s, const Accelerator& a, const Lights& l) : scene(s), accelerator(a), lights(l) {}

  // Closest hit within range.
  std::optional<Hit> intersect(const Ray& ray, Interval range);
  // Whether anything lies on the ray within range.
  bool occluded(const Ray& ray, Interval range);
  // Radiance arriving along a ray that leaves the scene.
  Color background(const Vec3& direction) const;
};

}  // namespace pathlab
