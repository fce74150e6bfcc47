// pathlab-bench: benchmarks that print numbers (never timed unit tests).
//   pathlab-bench bvh [MESH.obj] [--threads N] [--json]
//   pathlab-bench render [--quick] [--threads N] [--json]
#include <CLI/CLI.hpp>

#include <cstdio>

#include "bvh_bench.h"
#include "render_bench.h"
#include "pathlab/error.h"

int main(int argc, char** argv) {
  CLI::App app{"PathLab benchmarks"};
  app.require_subcommand(1);
  pathlab::bench::BvhBenchOptions bvh;
  CLI::App* bvhCommand = app.add_subcommand("bvh", "The reference BVH against Intel Embree on the same rays");
  bvhCommand->add_option("mesh", bvh.mesh, "OBJ mesh (default: the course's bunny, else a generated mesh)");
  bvhCommand->add_option("--threads", bvh.threads, "Threads for the multithreaded runs (default: all cores)");
  bvhCommand->add_flag("--json", bvh.json, "Print one JSON object as the last line");
  pathlab::bench::RenderBenchOptions render;
  CLI::App* renderCommand = app.add_subcommand("render", "The grading render of the Cornell box: paths/s and rays/s");
  renderCommand->add_flag("--quick", render.quick, "64 spp instead of 1024 (under 45 s on 2 cores)");
  renderCommand->add_option("--threads", render.threads, "Threads (default: all cores)");
  renderCommand->add_flag("--json", render.json, "Print one JSON object as the last line");
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
  } catch (const pathlab::Error& e) {
    std::fprintf(stderr, "pathlab-bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
