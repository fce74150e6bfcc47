// Task 4's remote calls: the judge's view of the student's direct_lighting.cpp.
// estimateDirectLighting runs in the candidate over a scene the judge sends
// (../support/trace_calls.h).
#pragma once

#include "wire/call.h"
#include "trace_calls.h"
#include "tasks/direct_lighting.h"

// This task's own value types on the wire (grader/wire/wire.h).
namespace pathlab::wire {
PATHLAB_WIRE_FIELDS(LightDirection, s.wi, s.distance, s.pdfSolidAngle);
}  // namespace pathlab::wire

namespace pathlab::calls {
PATHLAB_REMOTE_CALL(LambertianBrdf, 1, shape::Fixed, Color(Color));
PATHLAB_REMOTE_CALL(OffsetRayOrigin, 2, shape::Fixed, Point3(Point3, Vec3, Vec3));
PATHLAB_REMOTE_CALL(LightDirectionTo, 3, shape::Fixed, std::optional<LightDirection>(Point3, AreaSample));
}  // namespace pathlab::calls

namespace pathlab::candidate {
inline Color lambertianBrdf(const Color& albedo) { return remote::call<calls::LambertianBrdf>(albedo); }
inline std::vector<Point3> offsetRayOrigins(const std::vector<calls::OffsetRayOrigin::Args>& queries) {
  return remote::callMany<calls::OffsetRayOrigin>(queries);
}
inline std::optional<LightDirection> lightDirection(const Point3& from, const AreaSample& sample) {
  return remote::call<calls::LightDirectionTo>(from, sample);
}
}  // namespace pathlab::candidate
