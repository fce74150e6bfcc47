// Task 6's remote calls: the judge's view of the student's mirror_glass.cpp.
// Paths through mirrors and glass run in the candidate over a scene the
// judge sends (../support/trace_calls.h).
#pragma once

#include <vector>

#include "wire/call.h"
#include "trace_calls.h"
#include "tasks/mirror_glass.h"

namespace pathlab::calls {
PATHLAB_REMOTE_CALL(Reflect, 1, shape::Fixed, Vec3(Vec3));
PATHLAB_REMOTE_CALL(Refract, 2, shape::Fixed, std::optional<Vec3>(Vec3, float));
PATHLAB_REMOTE_CALL(SchlickFresnel, 3, shape::Fixed, float(float, float));
PATHLAB_REMOTE_CALL(SampleMirror, 4, shape::Fixed, BsdfSample(Vec3, Color));
PATHLAB_REMOTE_CALL(SampleGlass, 5, shape::Fixed, BsdfSample(Vec3, Color, Color, float, float));
}  // namespace pathlab::calls

namespace pathlab::candidate {
inline Vec3 reflect(const Vec3& wo) { return remote::call<calls::Reflect>(wo); }
inline std::optional<Vec3> refract(const Vec3& wo, float ior) { return remote::call<calls::Refract>(wo, ior); }
inline float schlickFresnel(float cosTheta, float ior) { return remote::call<calls::SchlickFresnel>(cosTheta, ior); }
inline BsdfSample sampleMirror(const Vec3& wo, const Color& reflectance) {
  return remote::call<calls::SampleMirror>(wo, reflectance);
}
inline BsdfSample sampleGlass(const Vec3& wo, const Color& reflectance, const Color& transmittance, float ior, float u) {
  return remote::call<calls::SampleGlass>(wo, reflectance, transmittance, ior, u);
}
inline std::vector<BsdfSample> sampleGlass(const std::vector<calls::SampleGlass::Args>& queries) {
  return remote::callMany<calls::SampleGlass>(queries);
}
}  // namespace pathlab::candidate
