// What an estimator needs while tracing one sample: the scene, its BVH and
// lights, the render settings, and per-thread state (pixel, counters, log).
// Estimators trace rays through intersect() and occluded() so rays are
// counted (rays/s) and, in the debugger, recorded.
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
  // The render settings: -l (settings.lightSamples, samples per area light)
  // and -m (settings.maxDepth, the most bounces a path may make). A copy of
  // scene.render that a test or a debugger view may change.
  RenderSettings settings;

  // Per-thread state.
  IVec2 pixel{0, 0};            // the pixel being rendered
  uint64_t rays = 0;            // rays traced by this thread
  std::vector<TracedRay>* log = nullptr;  // when set, every ray is recorded

  TraceContext(const Scene& s, const Accelerator& a, const Lights& l)
      : scene(s), accelerator(a), lights(l), settings(s.render) {}

  // Closest hit within range.
  std::optional<Hit> intersect(const Ray& ray, Interval range);
  // Whether anything lies on the ray within range.
  bool occluded(const Ray& ray, Interval range);
  // Radiance arriving along a ray that leaves the scene.
  Color background(const Vec3& direction) const;
};

}  // namespace pathlab
