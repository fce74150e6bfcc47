// `pathlab-bench render`: the course's grading render of the Cornell box,
// timed: paths per second and rays per second.
#pragma once

#include <string>

namespace pathlab::bench {

struct RenderBenchOptions {
  bool quick = false;  // 64 spp instead of 1024 (under 45 s on 2 cores)
  bool json = false;
  int threads = 0;     // 0: all cores
  std::string accel;   // "task3" or "fast"; empty: the CLI's default (defaultTraversal)
  std::string sampler = "sobol";  // or "independent"
};

int runRenderBench(const RenderBenchOptions& options);

}  // namespace pathlab::bench
