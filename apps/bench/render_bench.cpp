#include "render_bench.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "linked_tasks.h"
#include "util/error.h"
#include "util/parallel.h"
#include "util/platform.h"
#include "render/render.h"
#include "scene/scene_io.h"
#include "render/task_wiring.h"

#ifdef PATHLAB_HAVE_EMBREE
#include "embree_scene.h"
#endif

namespace pathlab::bench {
namespace {

// The share of a path's time spent in ray queries (BVH traversal and the
// hit record), without timing each query: trace a sparse grid of pixels on
// one thread, record every ray, and replay the rays alone through the same
// accelerator. With Embree, the same rays also go through Intel Embree's
// traversal alone (no hit record: a bound that favours Embree): how much of
// a path's time a walk as fast as Embree's could save. Each is timed in the
// thread's CPU seconds, five rounds taken in turn, and the medians compared:
// a busy machine (CI runs tests side by side) slows a round, not the ratio.
struct QueryShare {
  double share = 0.0;
  size_t rays = 0;
  double embreeShare = -1.0;  // < 0: Embree not built in
  double embreeAgreement = 0.0;  // share of the rays Embree answers alike (hit or miss, and which primitive)
  std::string embreeProblem;     // why Embree could not answer them, if it could not
};

QueryShare measureQueryShare(const Scene& scene, const RenderOptions& options) {
  const Accelerator accelerator(scene, options.traversal);
  const Lights lights = Lights::fromScene(scene, kLinkedTasks.environment, options.environmentSampling);
  const CameraBasis basis = cameraBasis(scene.camera);
  constexpr int kStride = 8, kSamples = 4;  // every 8th pixel each way: 7,500 pixels of 800x600
  auto traceGrid = [&](std::vector<TracedRay>* log) {
    TraceContext context(scene, accelerator, lights, kLinkedTasks.lobes);
    context.log = log;
    Color sum(0.0f);
    for (int y = kStride / 2; y < scene.render.height; y += kStride) {
      for (int x = kStride / 2; x < scene.render.width; x += kStride) {
        context.pixel = {x, y};
        for (int s = 0; s < kSamples; ++s) sum += estimatePixelSample(context, options, basis, uint32_t(s));
      }
    }
    return sum;
  };
  std::vector<TracedRay> rays;
  traceGrid(&rays);
  volatile float sink = 0.0f;  // keeps the work from being optimised away
  // The recorded rays alone through `queries` (the accelerator, or Embree: the same two calls).
  auto replay = [&](const auto& queries) {
    size_t found = 0;
    for (const TracedRay& traced : rays) {
      found += traced.shadow ? queries.occluded(traced.ray, traced.range)
                             : queries.intersect(traced.ray, traced.range).has_value();
    }
    sink = sink + float(found);
  };
  // What is timed, in this order: the paths, their rays through our walk, and (if built in) through Embree's.
  std::vector<std::function<void()>> runs = {[&] { sink = sink + traceGrid(nullptr).r; },
                                             [&] { replay(accelerator); }};
  QueryShare share;
  share.rays = rays.size();
#ifdef PATHLAB_HAVE_EMBREE
  std::optional<EmbreeScene> embree;
  try {
    embree.emplace(scene, 1);
    size_t alike = 0;
    for (const TracedRay& traced : rays) {
      if (traced.shadow) {
        alike += embree->occluded(traced.ray, traced.range) == traced.hit;
      } else {
        const std::optional<PrimitiveHit> hit = embree->intersect(traced.ray, traced.range);
        alike += hit ? traced.hit && hit->primitive == traced.record.primitive : !traced.hit;
      }
    }
    share.embreeAgreement = rays.empty() ? 1.0 : double(alike) / double(rays.size());
    runs.push_back([&] { replay(*embree); });
  } catch (const Error& error) {  // the comparison is extra: the render's numbers stand without it
    share.embreeProblem = error.what();
  }
#endif
  constexpr int kRounds = 5;
  std::vector<std::vector<double>> seconds(runs.size());
  for (int round = 0; round < kRounds; ++round) {
    for (size_t i = 0; i < runs.size(); ++i) {
      const double start = currentThreadCpuSeconds();
      runs[i]();
      seconds[i].push_back(currentThreadCpuSeconds() - start);
    }
  }
  auto median = [](std::vector<double> times) {
    std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
    return times[times.size() / 2];
  };
  const double paths = median(seconds[0]);
  share.share = median(seconds[1]) / paths;
  if (runs.size() > 2) share.embreeShare = median(seconds[2]) / paths;
  return share;
}

}  // namespace

int runRenderBench(const RenderBenchOptions& options) {
  // The seed's grading render: the CBspheres-like box (or the course's own
  // scene file), 800x600, 1024 spp, -m 4, one sample per area light.
  Scene scene = options.scene.empty() ? defaultScene() : loadScene(options.scene);
  scene.render.width = 800;
  scene.render.height = 600;
  scene.render.samplesPerPixel = options.spp > 0 ? options.spp : options.quick ? 64 : 1024;
  scene.render.maxDepth = 4;
  scene.render.lightSamples = 1;
  RenderOptions render;
  render.threads = options.threads > 0 ? options.threads : defaultThreadCount();
  render.progress = !options.json;
  render.traversal = defaultTraversal(linkedTaskSummary());
  if (!options.accel.empty()) {
    const std::optional<Traversal> traversal = traversalFromName(options.accel);
    if (!traversal) throw Error("--accel: unknown traversal " + inQuotes(options.accel) + " (task3, fast)");
    render.traversal = *traversal;
  }
  const std::optional<SampleSequence> sampler = sampleSequenceFromName(options.sampler);
  if (!sampler) throw Error("--sampler: unknown sampler " + inQuotes(options.sampler) + " (sobol, stratified, independent)");
  render.sampler = *sampler;
  const RenderResult result = pathlab::render(scene, render);
  const RenderStats& stats = result.stats;
  const double paths = double(stats.samples) / stats.seconds, rays = double(stats.rays) / stats.seconds;
  const QueryShare share = measureQueryShare(scene, render);
  std::printf("grading render%s of %s: %dx%d, %d spp, -m %d, %d threads, %s traversal, %s samples\n",
              options.quick ? " (quick)" : "", options.scene.empty() ? "the Cornell box" : options.scene.c_str(),
              scene.render.width, scene.render.height, scene.render.samplesPerPixel,
              scene.render.maxDepth, render.threads, traversalName(render.traversal), sampleSequenceName(render.sampler));
  // A path runs every task: camera rays, intersection, BVH, direct lighting,
  // path tracing (and task 6's BSDFs, task 7's sky where the scene has them).
  const LinkedTasks linked = linkedTasks();
  std::printf("code: %s\n", describeAllTasks(linked).c_str());
  std::printf("%.1f s, %.3f M paths/s, %.3f M rays/s, %.2f rays per path\n", stats.seconds, paths / 1e6, rays / 1e6,
              double(stats.rays) / double(stats.samples));
  std::printf("ray queries (BVH traversal and hit records): %.0f %% of the time (%zu rays replayed alone, 1 thread)\n",
              100.0 * share.share, share.rays);
  if (!share.embreeProblem.empty()) std::printf("Intel Embree: not compared (%s)\n", share.embreeProblem.c_str());
  if (share.embreeShare >= 0.0) {
    std::printf("the same rays through Intel Embree 3 (its traversal alone, no hit record): %.0f %% of the time "
                "(%.2f %% answered alike);\n  a render path as fast as that at its ray queries: at most %.2fx the "
                "paths per second\n",
                100.0 * share.embreeShare, 100.0 * share.embreeAgreement,
                1.0 / (1.0 - share.share + share.embreeShare));
  }
  if (stats.nonFiniteSamples) std::printf("warning: %llu NaN/Inf samples\n", (unsigned long long)stats.nonFiniteSamples);
  if (options.json) {
    nlohmann::json json = {{"paths_per_second", paths}, {"rays_per_second", rays},   {"seconds", stats.seconds},
                           {"spp", scene.render.samplesPerPixel},                    {"width", scene.render.width},
                           {"height", scene.render.height},                          {"max_depth", scene.render.maxDepth},
                           {"threads", render.threads},                              {"quick", options.quick},
                           {"traversal", traversalName(render.traversal)},
                           {"sampler", sampleSequenceName(render.sampler)},
                           {"scene", options.scene.empty() ? "<default>" : options.scene},
                           {"ray_query_share", share.share},
                           {"embree_query_share", share.embreeShare >= 0.0 ? nlohmann::json(share.embreeShare)
                                                                           : nlohmann::json()},
                           {"embree_agreement", share.embreeShare >= 0.0 ? nlohmann::json(share.embreeAgreement)
                                                                         : nlohmann::json()},
                           {"tasks", allTasksJson(linked)}};
    std::printf("%s\n", json.dump().c_str());
  }
  return 0;
}

}  // namespace pathlab::bench
