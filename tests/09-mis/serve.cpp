// The candidate's side of task 9's calls: the linked mis.cpp.
#include "serve_images.h"
#include "serve_trace.h"
#include "calls.h"

namespace pathlab::remote {

void registerCalls(Server& server) {
  serveImageCalls(server);
  server.serve<calls::BalanceHeuristic>(&balanceHeuristic);
  server.serve<calls::PowerHeuristic>(&powerHeuristic);
  server.serve<calls::SampleOneLight>([](const Scene& scene, const Point3& from, const std::vector<Vec3>& us) {
    const test::Rig rig(scene);
    const TraceContext context = rig.context();
    std::vector<std::optional<LightSample>> samples;
    for (const Vec3& u : us) samples.push_back(sampleOneLight(context, from, u));
    return samples;
  });
  server.serve<calls::OneLightPdf>([](const Scene& scene, const std::vector<calls::PdfQuery>& queries) {
    const test::Rig rig(scene);
    TraceContext context = rig.context();
    std::vector<float> pdfs;
    for (const auto& [from, wi] : queries) {
      const std::optional<Hit> hit = context.intersect(Ray{from, wi}, Interval{0.0f, kInfinity});
      pdfs.push_back(oneLightPdf(context, from, wi, hit));
    }
    return pdfs;
  });
  server.serve<calls::TracePathsMis>([](const Scene& scene, const calls::TraceSettings& settings,
                                        MisEstimator estimator, const std::vector<calls::PathQuery>& queries) {
    const test::Rig rig(scene);
    TraceContext context = contextFor(rig, settings);
    const MisWeights weights = misWeights(estimator);
    std::vector<Color> radiance;
    for (const auto& [ray, pixel, seed] : queries) {
      Sampler sampler(pixel, 0, seed);
      radiance.push_back(tracePathMis(context, ray, sampler, weights));
    }
    return radiance;
  });
  serveTraceCalls(server);
}

}  // namespace pathlab::remote
