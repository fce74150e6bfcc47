// `pathlab-bench render`: the course's grading render (the Cornell box, or
// --scene FILE), timed: paths per second, rays per second, and the share of
// the time spent answering ray queries.
#pragma once

#include <string>

namespace pathlab::bench {

struct RenderBenchOptions {
  bool quick = false;  // 64 spp instead of 1024 (under 45 s on 2 cores)
  bool json = false;
  int threads = 0;     // 0: all cores
  std::string accel;   // "task3" or "fast"; empty: the CLI's default (defaultTraversal)
  std::string sampler = "sobol";  // or "independent"
  std::string scene;              // a scene file; empty: the built-in Cornell box
  int spp = 0;                    // 0: 1024, or 64 with quick
};

int runRenderBench(const RenderBenchOptions& options);

}  // namespace pathlab::bench
