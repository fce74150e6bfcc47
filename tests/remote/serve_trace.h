// The candidate's side of trace_calls.h, for the suites that use them.
#pragma once

#include "../support/render_support.h"
#include "util/random.h"
#include "render/task_wiring.h"
#include "tasks/direct_lighting.h"
#include "tasks/path_tracing.h"
#include "server.h"
#include "trace_calls.h"

namespace pathlab::remote {

inline TraceContext contextFor(const test::Rig& rig, const calls::TraceSettings& settings) {
  return rig.context(settings.maxDepth, settings.lightSamples);
}

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
        TraceContext context = contextFor(rig, settings);
        std::vector<std::vector<calls::ShadowQuery>> rays;
        std::vector<TracedRay> log;
        context.log = &log;
        for (const auto& [hit, wo, pixel, seed] : queries) {
          log.clear();
          const Bsdf bsdf(rig.scene().materials.at(hit.material), hit, wo, kLinkedTasks.lobes);
          Sampler sampler(pixel, 0, seed);
          estimateDirectLighting(context, hit, bsdf, wo, sampler);
          rays.emplace_back();
          for (const TracedRay& traced : log)
            if (traced.shadow) rays.back().emplace_back(traced.ray, traced.range);
        }
        return rays;
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
