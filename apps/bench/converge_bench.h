// `pathlab-bench converge`: error against time for sampling strategies.
#pragma once

#include <string>
#include <vector>

namespace pathlab::bench {

struct ConvergeOptions {
  std::string scene;
  std::string strategies = "env-importance,env-uniform";
  double budgetSeconds = 60.0;  // per strategy
  std::string outDir = "converge";
  int referenceSpp = 2048;
  // The strategy that renders the reference: the default, or one that
  // converges where the default is noisy (mis-power on Veach's plates).
  std::string referenceStrategy = "reference";
  std::vector<int> resolution;  // -r WIDTH HEIGHT instead of the scene's (none: the scene's)
  int maxDepth = -1;            // -m instead of the scene's (-1: the scene's)
  // Render times (seconds) at which to compare the strategies at equal time:
  // each curve's relMSE there, interpolated; the curves run on past the
  // largest even beyond the budget.
  std::vector<double> equalTimes;
  int threads = 0;
  bool json = false;  // one JSON object as the last line
};

int runConvergeBench(const ConvergeOptions& options);

}  // namespace pathlab::bench
