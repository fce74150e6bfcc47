// pathlab-bench: benchmarks that print numbers (never timed unit tests).
//   pathlab-bench bvh [MESH.obj | --triangles N] [--threads N] [--json]
//   pathlab-bench render [--scene FILE] [--quick | --spp N] [--threads N] [--accel task3|fast]
//                        [--sampler sobol|stratified|independent] [--json]
//   pathlab-bench converge SCENE [--strategies a,b] [--budget SECONDS] [--at SECONDS...] [-r W H] [-m DEPTH]
//                          [--out DIR] [--json]
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "bvh_bench.h"
#include "converge_bench.h"
#include "render_bench.h"
#include "util/error.h"

namespace {

// A finite number above 0 (CLI::PositiveNumber lets NaN through: NaN <= 0 is false).
const CLI::Validator kFinitePositive(
    [](std::string& text) -> std::string {
      try {
        size_t used = 0;
        const double value = std::stod(text, &used);
        if (used == text.size() && std::isfinite(value) && value > 0.0) return "";
      } catch (const std::exception&) {
      }
      return "must be a finite number above 0, got '" + text + "'";
    },
    "> 0");

// A whole number of at least `least` (CLI11's range checks print DBL_MAX as the upper end).
CLI::Validator wholeNumber(long long least) {
  return CLI::Validator(
      [least](std::string& text) -> std::string {
        try {
          size_t used = 0;
          const long long value = std::stoll(text, &used);
          if (used == text.size() && value >= least) return "";
        } catch (const std::exception&) {
        }
        return "must be a whole number of at least " + std::to_string(least) + ", got '" + text + "'";
      },
      ">= " + std::to_string(least));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"PathLab benchmarks"};
  app.require_subcommand(1);
  pathlab::bench::BvhBenchOptions bvh;
  CLI::App* bvhCommand = app.add_subcommand("bvh", "Task 3's BVH as built (yours or the reference: the output says) against Intel Embree on the same rays");
  bvhCommand->add_option("mesh", bvh.mesh, "OBJ mesh (default: $PATHLAB_DATA_DIR/models/stanford-bunny.obj, else a generated scan-like mesh)");
  bvhCommand->add_option("--threads", bvh.threads, "Threads for the multithreaded runs (default: all cores)")
      ->check(wholeNumber(0));
  bvhCommand->add_flag("--json", bvh.json, "Print one JSON object as the last line");
  bvhCommand->add_option("--triangles", bvh.triangles, "Use a generated mesh of about N triangles (scaling)")
      ->check(wholeNumber(1));
  // Hidden: how a student build runs the reference build beside it (bvh_bench.cpp).
  bvhCommand->add_option("--task3-speed-only", bvh.task3SpeedOut, "Write task 3's Mrays/s alone to FILE")->group("");
  pathlab::bench::RenderBenchOptions render;
  CLI::App* renderCommand = app.add_subcommand("render", "The grading render (the Cornell box, or --scene): paths/s, rays/s, ray-query share");
  renderCommand->add_flag("--quick", render.quick, "64 spp instead of 1024 (under 45 s on 2 cores)");
  renderCommand->add_option("--threads", render.threads, "Threads (default: all cores)")->check(wholeNumber(0));
  renderCommand->add_option("--accel", render.accel, "task3 or fast (default: fast where tasks 2 and 3 are the reference)");
  renderCommand->add_option("--sampler", render.sampler, "sobol (default), stratified or independent");
  renderCommand->add_option("--scene", render.scene, "Scene file (default: the built-in Cornell box)");
  renderCommand->add_option("--spp", render.spp, "Samples per pixel (default: 1024, or 64 with --quick)")
      ->check(wholeNumber(1));
  renderCommand->add_flag("--json", render.json, "Print one JSON object as the last line");
  pathlab::bench::ConvergeOptions converge;
  CLI::App* convergeCommand = app.add_subcommand(
      "converge", "Error against time for sampling strategies (those the linked task code ignores: unavailable)");
  convergeCommand->add_option("scene", converge.scene, "Scene file")->required();
  convergeCommand->add_option("--strategies", converge.strategies, "Comma-separated: reference, cosine, uniform-hemisphere, nee, no-nee, rr, no-rr, light, bsdf, mis-balance, mis (or mis-power), env-importance, env-uniform, independent, stratified, adaptive (task 11, tolerance 0.2), adaptive-TOL");
  convergeCommand->add_option("--budget", converge.budgetSeconds, "Render seconds per strategy (default 60)")
      ->check(kFinitePositive);
  convergeCommand->add_option("--out", converge.outDir, "Output folder for the CSV and the cached reference");
  convergeCommand->add_option("--reference-spp", converge.referenceSpp, "Samples per pixel of the reference")
      ->check(wholeNumber(1));
  convergeCommand->add_option("--reference-strategy", converge.referenceStrategy,
                              "The strategy that renders the reference (default: reference, the course's recipe)");
  convergeCommand->add_option("-r", converge.resolution, "Resolution instead of the scene's: -r WIDTH HEIGHT")
      ->expected(2);
  convergeCommand->add_option("-m,--max-depth", converge.maxDepth, "Maximum ray depth instead of the scene's")
      ->check(wholeNumber(0));
  convergeCommand->add_option("--at", converge.equalTimes,
                              "Compare at these render times (seconds, e.g. --at 30 120): each strategy's relMSE "
                              "there, and the first's efficiency over each other's")
      ->check(kFinitePositive);
  convergeCommand->add_option("--threads", converge.threads, "Threads (default: all cores)")->check(wholeNumber(0));
  convergeCommand->add_flag("--json", converge.json, "Print one JSON object as the last line");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "pathlab-bench: %s (see pathlab-bench --help)\n", e.what());
    return 1;
  }
  try {
    if (bvhCommand->parsed()) return pathlab::bench::runBvhBench(bvh);
    if (renderCommand->parsed()) return pathlab::bench::runRenderBench(render);
    if (convergeCommand->parsed()) return pathlab::bench::runConvergeBench(converge);
  } catch (const pathlab::Error& e) {
    pathlab::printError("pathlab-bench", e.what());
    return 1;
  }
  return 0;
}
