// Task 9's remote calls: the judge's view of the student's mis.cpp. The
// light sampler and the MIS path tracer run in the candidate over a scene
// the judge sends, with its own BVH and lights (../support/trace_calls.h).
#pragma once

#include <optional>
#include <tuple>
#include <vector>

#include "wire/call.h"
#include "trace_calls.h"
#include "render/strategies.h"
#include "tasks/mis.h"

namespace pathlab::calls {
// A direction from a point: oneLightPdf's question (the candidate finds what the ray hits).
using PdfQuery = std::tuple<Point3 /*from*/, Vec3 /*wi*/>;

PATHLAB_REMOTE_CALL(BalanceHeuristic, 1, shape::Fixed, float(float, float));
PATHLAB_REMOTE_CALL(PowerHeuristic, 2, shape::Fixed, float(float, float));
PATHLAB_REMOTE_CALL(SampleOneLight, 3, shape::OnePer<2>, std::vector<std::optional<LightSample>>(Scene, Point3, std::vector<Vec3>));
PATHLAB_REMOTE_CALL(OneLightPdf, 4, shape::OnePer<1>, std::vector<float>(Scene, std::vector<PdfQuery>));
PATHLAB_REMOTE_CALL(TracePathsMis, 5, shape::OnePer<3>, std::vector<Color>(Scene, TraceSettings, MisEstimator, std::vector<PathQuery>));
}  // namespace pathlab::calls

namespace pathlab::wire {
template <>
struct Fields<LightSample> {
  static auto tie(LightSample& s) { return std::tie(s.wi, s.distance, s.radiance, s.pdf); }
};
}  // namespace pathlab::wire

namespace pathlab::candidate {
template <class C>
std::vector<typename C::Result> many(const std::vector<typename C::Args>& queries) {
  return remote::callMany<C>(queries);
}
inline float balanceHeuristic(float a, float b) { return remote::call<calls::BalanceHeuristic>(a, b); }
inline float powerHeuristic(float a, float b) { return remote::call<calls::PowerHeuristic>(a, b); }
// sampleOneLight(context, from, u) for each u, over `scene`'s lights.
inline std::vector<std::optional<LightSample>> sampleOneLight(const Scene& scene, const Point3& from,
                                                             const std::vector<Vec3>& us) {
  return remote::call<calls::SampleOneLight>(scene, from, us);
}
// oneLightPdf(context, from, wi, what the ray from `from` along wi hits) per query.
inline std::vector<float> oneLightPdf(const Scene& scene, const std::vector<calls::PdfQuery>& queries) {
  return remote::call<calls::OneLightPdf>(scene, queries);
}
// tracePathMis(context, ray, Sampler(pixel, 0, seed), misWeights(estimator)) per query.
inline std::vector<Color> tracePathsMis(const TraceContext& context, MisEstimator estimator,
                                        const std::vector<calls::PathQuery>& queries) {
  return remote::call<calls::TracePathsMis>(context.scene, calls::settingsOf(context), estimator, queries);
}
}  // namespace pathlab::candidate
