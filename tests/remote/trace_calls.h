// Remote calls that run the framework's estimators in the candidate, over a
// scene the judge sends: direct lighting at given hits (task 4), paths along
// given rays (tasks 5 and 6) and BSDF samples (tasks 4-6). The candidate
// builds the scene's BVH and lights with its own linked code, and every
// sample draws its random numbers from Sampler(pixel, 0, seed), as the
// tests would in one process.
#pragma once

#include <algorithm>
#include <tuple>
#include <vector>

#include "call.h"
#include "core/bsdf.h"
#include "core/scene.h"
#include "core/trace.h"

namespace pathlab::calls {

// What an estimator reads from its TraceContext besides the scene.
struct TraceSettings {
  int lightSamples = 1;
  int maxDepth = 4;
};
// One estimate: where, towards where, and its random stream.
using DirectQuery = std::tuple<Hit, Vec3 /*wo*/, uint32_t /*pixel*/, uint64_t /*seed*/>;
using PathQuery = std::tuple<Ray, uint32_t /*pixel*/, uint64_t /*seed*/>;

PATHLAB_REMOTE_CALL(DirectLighting, 101, shape::OnePer<2>, std::vector<Color>(Scene, TraceSettings, std::vector<DirectQuery>));
PATHLAB_REMOTE_CALL(TracePaths, 102, shape::OnePer<2>, std::vector<Color>(Scene, TraceSettings, std::vector<PathQuery>));
// Bsdf(material, hit, wo).sample(wo, u) for each u.
PATHLAB_REMOTE_CALL(BsdfSamples, 103, shape::OnePer<3>, std::vector<std::optional<BsdfSample>>(Material, Hit, Vec3, std::vector<Vec2>));
// The occlusion queries each DirectLighting query made, as the trace
// context records them (the framework's log, not the candidate's report).
using ShadowQuery = std::tuple<Ray, Interval>;
// At most -l rays per emitting surface and one per point light and for the
// sky (twice that: room for an estimator that tests a sample twice).
struct ShadowRayCount {
  static size_t of(const std::tuple<Scene, TraceSettings, std::vector<DirectQuery>>& args) {
    const Scene& scene = std::get<0>(args);
    size_t surfaces = scene.spheres.size();
    for (const TriangleMesh& mesh : scene.meshes) surfaces += mesh.triangles.size();
    const size_t perLight = size_t(std::max(1, std::get<1>(args).lightSamples));
    return 2 * (perLight * (surfaces + 1) + scene.pointLights.size());
  }
};
using ShadowRaysPerQuery = shape::OnePer<2, shape::AtMost<ShadowRayCount>>;
PATHLAB_REMOTE_CALL(ShadowRays, 104, ShadowRaysPerQuery,
                    std::vector<std::vector<ShadowQuery>>(Scene, TraceSettings, std::vector<DirectQuery>));

inline TraceSettings settingsOf(const TraceContext& context) {
  return {context.settings.lightSamples, context.settings.maxDepth};
}

}  // namespace pathlab::calls

namespace pathlab::wire {
template <>
struct Fields<calls::TraceSettings> {
  static auto tie(calls::TraceSettings& s) { return std::tie(s.lightSamples, s.maxDepth); }
};
}  // namespace pathlab::wire

namespace pathlab::candidate {

// estimateDirectLighting(context, hit, Bsdf(material of hit, hit, wo), wo, Sampler(pixel, 0, seed)) per query.
inline std::vector<Color> estimateDirectLighting(const TraceContext& context, const std::vector<calls::DirectQuery>& queries) {
  return remote::call<calls::DirectLighting>(context.scene, calls::settingsOf(context), queries);
}
// The shadow rays estimateDirectLighting traces for each query.
inline std::vector<std::vector<calls::ShadowQuery>> shadowRays(const TraceContext& context,
                                                              const std::vector<calls::DirectQuery>& queries) {
  return remote::call<calls::ShadowRays>(context.scene, calls::settingsOf(context), queries);
}
// tracePath(context, ray, Sampler(pixel, 0, seed)) per query.
inline std::vector<Color> tracePaths(const TraceContext& context, const std::vector<calls::PathQuery>& queries) {
  return remote::call<calls::TracePaths>(context.scene, calls::settingsOf(context), queries);
}
inline std::vector<std::optional<BsdfSample>> bsdfSamples(const Material& material, const Hit& hit, const Vec3& wo,
                                                          const std::vector<Vec2>& us) {
  return remote::call<calls::BsdfSamples>(material, hit, wo, us);
}

}  // namespace pathlab::candidate
