// The candidate's side of task 12's calls: the linked media.cpp.
#include "serve_images.h"
#include "serve_trace.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::SampleFreeFlight>([](const std::vector<calls::FlightQuery>& queries) {
    std::vector<FreeFlight> flights;
    for (const auto& [sigmaT, tMax, u] : queries) flights.push_back(sampleFreeFlight(sigmaT, tMax, u));
    return flights;
  });
  server.serve<calls::HenyeyGreenstein>([](const std::vector<calls::PhaseQuery>& queries) {
    std::vector<float> values;
    for (const auto& [cosTheta, g] : queries) values.push_back(henyeyGreenstein(cosTheta, g));
    return values;
  });
  server.serve<calls::SampleHenyeyGreenstein>([](const std::vector<calls::PhaseSampleQuery>& queries) {
    std::vector<Vec3> directions;
    for (const auto& [direction, g, u] : queries) directions.push_back(sampleHenyeyGreenstein(direction, g, u));
    return directions;
  });
  server.serve<calls::Transmittance>([](const Scene& scene, const std::vector<calls::TransmittanceQuery>& queries) {
    const test::Rig rig(scene);
    TraceContext context = rig.context();
    std::vector<float> values;
    for (const auto& [ray, distance, medium, pixel, seed] : queries) {
      Sampler sampler(pixel, 0, seed);
      values.push_back(transmittance(context, ray, distance, medium, sampler));
    }
    return values;
  });
  server.serve<calls::DirectLightingInMedia>([](const Scene& scene, const calls::TraceSettings& settings,
                                                const std::vector<calls::VertexQuery>& queries) {
    const test::Rig rig(scene);
    TraceContext context = contextFor(rig, settings);
    std::vector<Color> radiance;
    for (const calls::VertexQuery& q : queries) {
      Sampler sampler(q.pixel, 0, q.seed);
      if (!q.onSurface) {
        const ScatteringVertex vertex = ScatteringVertex::inMedium(q.ray.at(q.distance), -q.ray.direction, q.g);
        radiance.push_back(estimateDirectLightingInMedia(context, vertex, q.medium, sampler));
        continue;
      }
      const std::optional<Hit> hit = context.intersect(q.ray, Interval{0.0f, kInfinity});
      if (!hit) {
        radiance.push_back(Color(0.0f));
        continue;
      }
      const Bsdf bsdf = context.bsdf(*hit, -q.ray.direction);
      radiance.push_back(estimateDirectLightingInMedia(
          context, ScatteringVertex::onSurface(*hit, bsdf, -q.ray.direction), q.medium, sampler));
    }
    return radiance;
  });
  server.serve<calls::TracePathsInMedia>([](const Scene& scene, const calls::TraceSettings& settings,
                                            const std::vector<calls::PathQuery>& queries) {
    const test::Rig rig(scene);
    TraceContext context = contextFor(rig, settings);
    std::vector<Color> radiance;
    for (const auto& [ray, pixel, seed] : queries) {
      Sampler sampler(pixel, 0, seed);
      radiance.push_back(tracePathInMedia(context, ray, sampler));
    }
    return radiance;
  });
  serveTraceCalls(server);
}

}  // namespace pathlab::remote
