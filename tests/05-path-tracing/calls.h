// Task 5's remote calls: the judge's view of the student's path_tracing.cpp.
// tracePath runs in the candidate over a scene the judge sends
// (../support/trace_calls.h).
#pragma once

#include <vector>

#include "wire/call.h"
#include "trace_calls.h"
#include "tasks/path_tracing.h"

namespace pathlab::calls {
PATHLAB_REMOTE_CALL(SampleDiffuseDirection, 1, shape::Fixed, Vec3(Vec2));
PATHLAB_REMOTE_CALL(DiffuseDirectionPdf, 2, shape::Fixed, float(Vec3));
}  // namespace pathlab::calls

namespace pathlab::candidate {
inline Vec3 sampleDiffuseDirection(Vec2 u) { return remote::call<calls::SampleDiffuseDirection>(u); }
inline std::vector<Vec3> sampleDiffuseDirections(const std::vector<Vec2>& us) {
  return remote::callMany<calls::SampleDiffuseDirection>({us.begin(), us.end()});
}
inline float diffuseDirectionPdf(const Vec3& wi) { return remote::call<calls::DiffuseDirectionPdf>(wi); }
inline std::vector<double> diffuseDirectionPdfs(const std::vector<Vec3>& wis) {
  const std::vector<float> pdfs = remote::callMany<calls::DiffuseDirectionPdf>({wis.begin(), wis.end()});
  return {pdfs.begin(), pdfs.end()};
}
}  // namespace pathlab::candidate
