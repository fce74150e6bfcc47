#include "render_bench.h"

#include <nlohmann/json.hpp>

#include <cstdio>

#include "linked_tasks.h"
#include "pathlab/error.h"
#include "pathlab/parallel.h"
#include "pathlab/render.h"
#include "pathlab/scene_io.h"

namespace pathlab::bench {

int runRenderBench(const RenderBenchOptions& options) {
  // The seed's grading render: the CBspheres-like box, 800x600, 1024 spp, -m 4.
  Scene scene = defaultScene();
  scene.render.width = 800;
  scene.render.height = 600;
  scene.render.samplesPerPixel = options.quick ? 64 : 1024;
  scene.render.maxDepth = 4;
  scene.render.lightSamples = 1;
  RenderOptions render;
  render.threads = options.threads > 0 ? options.threads : defaultThreadCount();
  render.progress = !options.json;
  render.traversal = defaultTraversal(PATHLAB_TASK_SUMMARY);
  if (!options.accel.empty()) {
    const std::optional<Traversal> traversal = traversalFromName(options.accel);
    if (!traversal) throw Error("--accel: unknown traversal " + inQuotes(options.accel) + " (task3, fast)");
    render.traversal = *traversal;
  }
  const std::optional<SampleSequence> sampler = sampleSequenceFromName(options.sampler);
  if (!sampler) throw Error("--sampler: unknown sampler " + inQuotes(options.sampler) + " (sobol, independent)");
  render.sampler = *sampler;
  const RenderResult result = pathlab::render(scene, render);
  const RenderStats& stats = result.stats;
  const double paths = double(stats.samples) / stats.seconds, rays = double(stats.rays) / stats.seconds;
  std::printf("grading render%s: %dx%d, %d spp, -m %d, %d threads, %s traversal, %s samples\n",
              options.quick ? " (quick)" : "", scene.render.width, scene.render.height, scene.render.samplesPerPixel,
              scene.render.maxDepth, render.threads, traversalName(render.traversal), sampleSequenceName(render.sampler));
  // A path runs every task: camera rays, intersection, BVH, direct lighting,
  // path tracing (and task 6's BSDFs, task 7's sky where the scene has them).
  const LinkedTasks linked = linkedTasks();
  std::printf("code: %s\n", describeAllTasks(linked).c_str());
  std::printf("%.1f s, %.3f M paths/s, %.3f M rays/s, %.2f rays per path\n", stats.seconds, paths / 1e6, rays / 1e6,
              double(stats.rays) / double(stats.samples));
  if (stats.nonFiniteSamples) std::printf("warning: %llu NaN/Inf samples\n", (unsigned long long)stats.nonFiniteSamples);
  if (options.json) {
    nlohmann::json json = {{"paths_per_second", paths}, {"rays_per_second", rays},   {"seconds", stats.seconds},
                           {"spp", scene.render.samplesPerPixel},                    {"width", scene.render.width},
                           {"height", scene.render.height},                          {"max_depth", scene.render.maxDepth},
                           {"threads", render.threads},                              {"quick", options.quick},
                           {"traversal", traversalName(render.traversal)},
                           {"sampler", sampleSequenceName(render.sampler)},
                           {"tasks", allTasksJson(linked)}};
    std::printf("%s\n", json.dump().c_str());
  }
  return 0;
}

}  // namespace pathlab::bench
