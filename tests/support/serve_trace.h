// The candidate's side of trace_calls.h, for the suites that use them.
#pragma once

#include "render_support.h"
#include "util/random.h"
#include "render/task_wiring.h"
#include "tasks/direct_lighting.h"
#include "tasks/path_tracing.h"
#include "wire/server.h"
#include "trace_calls.h"

namespace pathlab::remote {

inline TraceContext contextFor(const test::Rig& rig, const calls::TraceSettings& settings) {
  return rig.context(settings.maxDepth, settings.lightSamples);
}

// ShadowRays' ray queries: closest hits from the candidate's own tree, every
// occlusion query asked of the judge (trace_calls.h), which traces it
// itself and records it for the estimate being computed.
class JudgedOcclusion final : public RayQueries {
 public:
  explicit JudgedOcclusion(const RayQueries& own) : own_(own) {}
  uint32_t query = 0;  // the estimate being computed: its index in the request

  std::optional<Hit> closestHit(const Ray& ray, Interval range) const override { return own_.closestHit(ray, range); }
  bool anyHit(const Ray& ray, Interval range) const override {
    wire::Writer question;
    question.put(query);
    question.put(ray);
    question.put(range);
    return wire::Reader(ask(question.bytes())).get<bool>();
  }

 private:
  const RayQueries& own_;
};

inline void serveTraceCalls(Server& server) {
  server.serve<calls::DirectLighting>(
      [](const Scene& scene, const calls::TraceSettings& settings, const std::vector<calls::DirectQuery>& queries) {
        const test::Rig rig(scene);
        TraceContext context = contextFor(rig, settings);
        std::vector<Color> estimates;
        for (const auto& [hit, wo, pixel, seed] : queries) {
          const Bsdf bsdf(rig.scene().materials.at(hit.material), hit, wo, kLinkedTasks.lobes);
          Sampler sampler(pixel, 0, seed);
          estimates.push_back(estimateDirectLighting(context, hit, bsdf, wo, sampler));
        }
        return estimates;
      });
  server.serve<calls::ShadowRays>(
      [](const Scene& scene, const calls::TraceSettings& settings, const std::vector<calls::DirectQuery>& queries) {
        const test::Rig rig(scene);
        const TraceContext own = contextFor(rig, settings);
        JudgedOcclusion judged(own.queries);
        TraceContext context(rig.scene(), judged, rig.lights(), own.lobes);
        context.settings = own.settings;
        std::vector<Color> estimates;
        for (size_t q = 0; q < queries.size(); ++q) {
          const auto& [hit, wo, pixel, seed] = queries[q];
          judged.query = uint32_t(q);
          const Bsdf bsdf(rig.scene().materials.at(hit.material), hit, wo, kLinkedTasks.lobes);
          Sampler sampler(pixel, 0, seed);
          estimates.push_back(estimateDirectLighting(context, hit, bsdf, wo, sampler));
        }
        return estimates;
      });
  server.serve<calls::TracePaths>(
      [](const Scene& scene, const calls::TraceSettings& settings, const std::vector<calls::PathQuery>& queries) {
        const test::Rig rig(scene);
        TraceContext context = contextFor(rig, settings);
        std::vector<Color> radiance;
        for (const auto& [ray, pixel, seed] : queries) {
          Sampler sampler(pixel, 0, seed);
          radiance.push_back(tracePath(context, ray, sampler));
        }
        return radiance;
      });
  server.serve<calls::BsdfSamples>(
      [](const Material& material, const Hit& hit, const Vec3& wo, const std::vector<Vec2>& us) {
        const Bsdf bsdf(material, hit, wo, kLinkedTasks.lobes);
        std::vector<std::optional<BsdfSample>> samples;
        for (const Vec2& u : us) samples.push_back(bsdf.sample(wo, u));
        return samples;
      });
}

}  // namespace pathlab::remote
