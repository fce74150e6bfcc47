// Task 12's remote calls: the judge's view of the student's media.cpp. The
// samplers run on batches of random numbers the judge sends; transmittance,
// direct lighting and the path tracer run in the candidate over a scene the
// judge sends, with its own BVH and lights (../support/trace_calls.h).
#pragma once

#include <tuple>
#include <vector>

#include "wire/call.h"
#include "trace_calls.h"
#include "tasks/media.h"

namespace pathlab::calls {
// A free flight's question: sigmaT, tMax, u.
using FlightQuery = std::tuple<float, float, float>;
// A phase function's value: cos theta, g.
using PhaseQuery = std::tuple<float, float>;
// A direction from the phase function: the direction travelled, g, u.
using PhaseSampleQuery = std::tuple<Vec3, float, Vec2>;
// A shadow ray: the ray, its length, the medium it starts in, its random stream.
using TransmittanceQuery = std::tuple<Ray, float, MediumIndex, uint32_t /*pixel*/, uint64_t /*seed*/>;
// Direct lighting at a vertex: on the surface the ray (origin, direction)
// hits first, or (in a medium) at the point `distance` along it; wo is
// -direction. Then the medium there, and the random stream.
struct VertexQuery {
  Ray ray;
  bool onSurface = true;
  float distance = 0.0f;  // in a medium: how far along the ray
  float g = 0.0f;         // in a medium: its phase function's g
  MediumIndex medium = kVacuum;
  uint32_t pixel = 0;
  uint64_t seed = 0;
};

PATHLAB_REMOTE_CALL(SampleFreeFlight, 1, shape::OnePer<0>, std::vector<FreeFlight>(std::vector<FlightQuery>));
PATHLAB_REMOTE_CALL(HenyeyGreenstein, 2, shape::OnePer<0>, std::vector<float>(std::vector<PhaseQuery>));
PATHLAB_REMOTE_CALL(SampleHenyeyGreenstein, 3, shape::OnePer<0>, std::vector<Vec3>(std::vector<PhaseSampleQuery>));
PATHLAB_REMOTE_CALL(Transmittance, 4, shape::OnePer<1>, std::vector<float>(Scene, std::vector<TransmittanceQuery>));
PATHLAB_REMOTE_CALL(DirectLightingInMedia, 5, shape::OnePer<2>, std::vector<Color>(Scene, TraceSettings, std::vector<VertexQuery>));
PATHLAB_REMOTE_CALL(TracePathsInMedia, 6, shape::OnePer<2>, std::vector<Color>(Scene, TraceSettings, std::vector<PathQuery>));
}  // namespace pathlab::calls

namespace pathlab::wire {
template <>
struct Fields<FreeFlight> {
  static auto tie(FreeFlight& s) { return std::tie(s.t, s.scattered, s.pdf); }
};
template <>
struct Fields<calls::VertexQuery> {
  static auto tie(calls::VertexQuery& s) {
    return std::tie(s.ray, s.onSurface, s.distance, s.g, s.medium, s.pixel, s.seed);
  }
};
}  // namespace pathlab::wire

namespace pathlab::candidate {
inline std::vector<FreeFlight> sampleFreeFlight(const std::vector<calls::FlightQuery>& queries) {
  return remote::call<calls::SampleFreeFlight>(queries);
}
inline std::vector<float> henyeyGreenstein(const std::vector<calls::PhaseQuery>& queries) {
  return remote::call<calls::HenyeyGreenstein>(queries);
}
inline std::vector<Vec3> sampleHenyeyGreenstein(const std::vector<calls::PhaseSampleQuery>& queries) {
  return remote::call<calls::SampleHenyeyGreenstein>(queries);
}
// transmittance(context, ray, distance, medium, Sampler(pixel, 0, seed)) per query, over `scene`.
inline std::vector<float> transmittance(const Scene& scene, const std::vector<calls::TransmittanceQuery>& queries) {
  return remote::call<calls::Transmittance>(scene, queries);
}
// estimateDirectLightingInMedia(context, vertex, medium, Sampler(pixel, 0, seed)) per query.
inline std::vector<Color> directLightingInMedia(const Scene& scene, const calls::TraceSettings& settings,
                                                const std::vector<calls::VertexQuery>& queries) {
  return remote::call<calls::DirectLightingInMedia>(scene, settings, queries);
}
// tracePathInMedia(context, ray, Sampler(pixel, 0, seed)) per query.
inline std::vector<Color> tracePathsInMedia(const Scene& scene, const calls::TraceSettings& settings,
                                            const std::vector<calls::PathQuery>& queries) {
  return remote::call<calls::TracePathsInMedia>(scene, settings, queries);
}
}  // namespace pathlab::candidate
