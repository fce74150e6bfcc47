// Task 8's remote calls: the judge's view of the student's microfacet.cpp.
// Paths over rough materials run in the candidate over a scene the judge
// sends (../support/trace_calls.h).
#pragma once

#include <optional>
#include <vector>

#include "wire/call.h"
#include "trace_calls.h"
#include "tasks/microfacet.h"

namespace pathlab::calls {
PATHLAB_REMOTE_CALL(AlphaFromRoughness, 1, shape::Fixed, float(float));
PATHLAB_REMOTE_CALL(GgxD, 2, shape::Fixed, float(Vec3, float));
PATHLAB_REMOTE_CALL(SmithLambda, 3, shape::Fixed, float(Vec3, float));
PATHLAB_REMOTE_CALL(SmithG1, 4, shape::Fixed, float(Vec3, Vec3, float));
PATHLAB_REMOTE_CALL(SmithG2, 5, shape::Fixed, float(Vec3, Vec3, Vec3, float));
PATHLAB_REMOTE_CALL(SchlickFresnelF0, 6, shape::Fixed, Color(float, Color));
PATHLAB_REMOTE_CALL(ConductorFresnel, 7, shape::Fixed, Color(float, Color, Color));
PATHLAB_REMOTE_CALL(ConductorBrdf, 8, shape::Fixed, Color(Vec3, Vec3, RoughConductor));
PATHLAB_REMOTE_CALL(SampleGgxNormal, 9, shape::Fixed, Vec3(Vec2, float));
PATHLAB_REMOTE_CALL(SampleVisibleNormal, 10, shape::Fixed, Vec3(Vec3, Vec2, float));
PATHLAB_REMOTE_CALL(VisibleNormalPdf, 11, shape::Fixed, float(Vec3, Vec3, float));
PATHLAB_REMOTE_CALL(SampleConductor, 12, shape::Fixed, std::optional<BsdfSample>(Vec3, Vec2, RoughConductor));
PATHLAB_REMOTE_CALL(ConductorPdf, 13, shape::Fixed, float(Vec3, Vec3, RoughConductor));
PATHLAB_REMOTE_CALL(PlasticBrdf, 14, shape::Fixed, Color(Vec3, Vec3, RoughPlastic));
PATHLAB_REMOTE_CALL(SamplePlastic, 15, shape::Fixed, std::optional<BsdfSample>(Vec3, Vec2, RoughPlastic));
PATHLAB_REMOTE_CALL(PlasticPdf, 16, shape::Fixed, float(Vec3, Vec3, RoughPlastic));
}  // namespace pathlab::calls

namespace pathlab::candidate {
// One call per function, each a batch: a suite asks for thousands of values at once.
template <class C>
std::vector<typename C::Result> many(const std::vector<typename C::Args>& queries) {
  return remote::callMany<C>(queries);
}
inline float alphaFromRoughness(float roughness) { return remote::call<calls::AlphaFromRoughness>(roughness); }
inline float ggxD(const Vec3& m, float alpha) { return remote::call<calls::GgxD>(m, alpha); }
inline Color conductorBrdf(const Vec3& wo, const Vec3& wi, const RoughConductor& c) {
  return remote::call<calls::ConductorBrdf>(wo, wi, c);
}
inline Color plasticBrdf(const Vec3& wo, const Vec3& wi, const RoughPlastic& p) {
  return remote::call<calls::PlasticBrdf>(wo, wi, p);
}
}  // namespace pathlab::candidate
