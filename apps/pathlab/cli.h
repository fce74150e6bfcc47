// The `pathlab` command line: parsing, validation and the two commands
// (render, debug). main.cpp only wires signals and exit codes.
#pragma once

#include <atomic>

namespace pathlab {

// Returns the process exit code: 0 success, 1 bad input, 130 interrupted.
// `rendering` is set once the render starts: from then on a signal sets
// `cancel` (the image so far is written); before, it ends the process.
int runCli(int argc, char** argv, const std::atomic<bool>& cancel, std::atomic<bool>& rendering);

}  // namespace pathlab
