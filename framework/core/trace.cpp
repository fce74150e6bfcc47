#include "core/trace.h"

namespace pathlab {

std::optional<Hit> TraceContext::intersect(const Ray& ray, Interval range) {
  ++rays;
  std::optional<Hit> hit = queries.closestHit(ray, range);
  if (log) log->push_back({ray, range, false, hit.has_value(), hit.value_or(Hit{})});
  return hit;
}

bool TraceContext::occluded(const Ray& ray, Interval range) {
  ++rays;
  const bool blocked = queries.anyHit(ray, range);
  if (log) log->push_back({ray, range, true, blocked, Hit{}});
  return blocked;
}

Color TraceContext::background(const Vec3& direction) const {
  return lights.environment ? lights.environment->radiance(direction) : Color(0.0f);
}

}  // namespace pathlab
