// What an estimator needs while tracing one sample: the scene, ray queries
// against it, its lights, BSDFs, the render settings, and per-thread state
// (pixel, counters, log). Estimators trace rays through intersect() and
// occluded() so rays are counted (rays/s) and, in the debugger, recorded.
// Core: the ray queries are an interface the render layer's Accelerator
// answers (task 3's tree), and BSDFs get the lobes the render layer passes.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/bsdf.h"
#include "core/hit.h"
#include "core/lights.h"
#include "core/scene.h"
#include "core/task_functions.h"
#include "util/ray.h"

namespace pathlab {

// One ray as the debugger records it.
struct TracedRay {
  Ray ray;
  Interval range;
  bool shadow = false;  // an occlusion query
  bool hit = false;     // blocked (shadow) or hit something
  Hit record;           // the closest hit (not for occlusion queries); record.t is kInfinity on a miss
};

// Closest-hit and any-hit queries against a whole scene (Accelerator).
class RayQueries {
 public:
  virtual std::optional<Hit> closestHit(const Ray& ray, Interval range) const = 0;
  virtual bool anyHit(const Ray& ray, Interval range) const = 0;

 protected:
  ~RayQueries() = default;
};

struct TraceContext {
  const Scene& scene;
  const RayQueries& queries;
  const Lights& lights;
  const BsdfLobes& lobes;  // tasks 4-6 (kLinkedTasks.lobes, task_wiring.h)
  // The render settings: -l (settings.lightSamples, samples per area light)
  // and -m (settings.maxDepth, the most bounces a path may make). A copy of
  // scene.render that a test or a debugger view may change.
  RenderSettings settings;

  // Per-thread state.
  IVec2 pixel{0, 0};            // the pixel being rendered
  uint64_t rays = 0;            // rays traced by this thread
  std::vector<TracedRay>* log = nullptr;  // when set, every ray is recorded

  TraceContext(const Scene& s, const RayQueries& q, const Lights& l, const BsdfLobes& b)
      : scene(s), queries(q), lights(l), lobes(b), settings(s.render) {}

  // Closest hit within range. (Inline: called for every ray.)
  std::optional<Hit> intersect(const Ray& ray, Interval range) {
    ++rays;
    std::optional<Hit> hit = queries.closestHit(ray, range);
    if (log) [[unlikely]] log->push_back({ray, range, false, hit.has_value(), hit.value_or(Hit{})});
    return hit;
  }
  // Whether anything lies on the ray within range.
  bool occluded(const Ray& ray, Interval range) {
    ++rays;
    const bool blocked = queries.anyHit(ray, range);
    if (log) [[unlikely]] log->push_back({ray, range, true, blocked, Hit{}});
    return blocked;
  }
  // The closest hit of a shadow ray: through media (task 12) light passes
  // the interfaces, so a shadow ray needs to know what it met. Counted and
  // recorded as a shadow ray.
  std::optional<Hit> shadowHit(const Ray& ray, Interval range) {
    ++rays;
    std::optional<Hit> hit = queries.closestHit(ray, range);
    if (log) [[unlikely]] log->push_back({ray, range, true, hit.has_value(), hit.value_or(Hit{})});
    return hit;
  }
  // Radiance arriving along a ray that leaves the scene.
  Color background(const Vec3& direction) const;
  // The BSDF at `hit` seen from direction wo (unit, pointing away from the surface).
  Bsdf bsdf(const Hit& hit, const Vec3& wo) const { return Bsdf(scene.materials[hit.material], hit, wo, lobes); }
};

}  // namespace pathlab
