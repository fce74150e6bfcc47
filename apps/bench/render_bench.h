// `pathlab-bench render`: the course's grading render of the Cornell box,
// timed: paths per second and rays per second.
#pragma once

namespace pathlab::bench {

struct RenderBenchOptions {
  bool quick = false;  // 64 spp instead of 1024 (under 45 s on 2 cores)
  bool json = false;
  int threads = 0;     // 0: all cores
};

int runRenderBench(const RenderBenchOptions& options);

}  // namespace pathlab::bench
