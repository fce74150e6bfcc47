// Remote calls that run the framework's estimators in the candidate, over a
// scene the judge sends: direct lighting at given hits (task 4), paths along
// given rays (tasks 5 and 6) and BSDF samples (tasks 4-6). The candidate
// builds the scene's BVH and lights with its own linked code, and every
// sample draws its random numbers from Sampler(pixel, 0, seed), as the
// tests would in one process.
#pragma once

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "wire/call.h"
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

PATHLAB_REMOTE_CALL(DirectLighting, 101, shape::OnePer<2>,
                    std::vector<Color>(Scene, TraceSettings, std::vector<DirectQuery>));
PATHLAB_REMOTE_CALL(TracePaths, 102, shape::OnePer<2>,
                    std::vector<Color>(Scene, TraceSettings, std::vector<PathQuery>));
// Bsdf(material, hit, wo).sample(wo, u) for each u.
PATHLAB_REMOTE_CALL(BsdfSamples, 103, shape::OnePer<3>,
                    std::vector<std::optional<BsdfSample>>(Material, Hit, Vec3, std::vector<Vec2>));
// Each DirectLighting query's estimate, its occlusion queries served by the
// judge: the candidate's trace context asks the judge for every one
// (context.occluded, or anything else that reaches its RayQueries' anyHit:
// the query's index, the ray and its range, a uint32_t, a Ray and an
// Interval; the reply whether it is blocked, the judge's own trace), so that
// the judge itself knows the shadow rays each estimate traced. Closest-hit
// queries stay the candidate's own. (A log kept in the candidate's process,
// context.log, is the candidate's to write: the judge does not read it.)
using ShadowQuery = std::tuple<Ray, Interval>;
PATHLAB_REMOTE_CALL(ShadowRays, 104, shape::OnePer<2>,
                    std::vector<Color>(Scene, TraceSettings, std::vector<DirectQuery>));
// The most occlusion queries the judge serves one estimate: -l per emitting
// surface and one per point light and for the sky, twice over (room for an
// estimator that tests a sample twice).
inline size_t mostShadowRays(const Scene& scene, const TraceSettings& settings) {
  size_t surfaces = scene.spheres.size();
  for (const TriangleMesh& mesh : scene.meshes) surfaces += mesh.triangles.size();
  const size_t perLight = size_t(std::max(1, settings.lightSamples));
  return 2 * (perLight * (surfaces + 1) + scene.pointLights.size());
}

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
inline std::vector<Color> estimateDirectLighting(const TraceContext& context,
                                                 const std::vector<calls::DirectQuery>& queries) {
  return remote::call<calls::DirectLighting>(context.scene, calls::settingsOf(context), queries);
}
// What the judge saw of one estimate whose occlusion queries it served.
struct ServedShadows {
  Color estimate;                        // what estimateDirectLighting returned (its claim)
  std::vector<calls::ShadowQuery> rays;  // the occlusion queries the judge served it, in order (the judge's record)
};
// estimateDirectLighting per query (as estimateDirectLighting above), each
// occlusion query asked of the judge, which answers with its own trace of
// `context`'s scene and records it.
inline std::vector<ServedShadows> shadowRays(const TraceContext& context,
                                             const std::vector<calls::DirectQuery>& queries) {
  const calls::TraceSettings settings = calls::settingsOf(context);
  const size_t most = calls::mostShadowRays(context.scene, settings);
  std::vector<ServedShadows> served(queries.size());
  const remote::AskHandler serve = [&](const std::string& question) {
    const auto [query, ray, range] = remote::readAsk<uint32_t, Ray, Interval>(question, "an occlusion query");
    if (query >= queries.size()) {
      throw remote::CandidateError("the candidate asked for an occlusion query of estimate " + std::to_string(query) +
                                   " (the request has " + std::to_string(queries.size()) + ")");
    }
    std::vector<calls::ShadowQuery>& rays = served[query].rays;
    if (rays.size() >= most) {  // the judge's own record stays bounded
      throw remote::CandidateError("estimate " + std::to_string(query) + " traced over " + std::to_string(most) +
                                   " shadow rays, twice what its lights need");
    }
    rays.emplace_back(ray, range);
    wire::Writer reply;
    reply.put(context.queries.anyHit(ray, range));
    return reply.bytes();
  };
  const std::vector<Color> estimates =
      remote::callMany<calls::ShadowRays>({{context.scene, settings, queries}}, &serve).front();
  for (size_t q = 0; q < queries.size(); ++q) served[q].estimate = estimates[q];
  return served;
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
