// Which implementation of each task this program links, as CMake chose it:
// "1:reference 2:student ..." (cmake/PathLabTasks.cmake, pathlab_task_summary),
// the string `--version` prints. Each program gets a one-line definition of
// its own (pathlab_add_task_summary), so that the sources several programs
// share (the CLI, the window, the benchmarks) are compiled once.
#pragma once

namespace pathlab {

const char* linkedTaskSummary();

}  // namespace pathlab
