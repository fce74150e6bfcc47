#include "core/trace.h"

namespace pathlab {

Color TraceContext::background(const Vec3& direction) const {
  return lights.environment ? lights.environment->radiance(direction) : Color(0.0f);
}

}  // namespace pathlab
