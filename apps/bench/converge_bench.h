// `pathlab-bench converge`: error against time for sampling strategies.
#pragma once

#include <string>

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
  int threads = 0;
  bool json = false;  // one JSON object as the last line
};

int runConvergeBench(const ConvergeOptions& options);

}  // namespace pathlab::bench
