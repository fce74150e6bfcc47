// attack: chains of processes, each forking the next and exiting at once (retrying while the process
// limit is reached), so no list of process ids is ever current: they must not outlive the test
// base: stub  expect: 0
#include <unistd.h>
namespace {
const bool chained = [] {
  for (int chain = 0; chain < 4; ++chain) {
    if (fork() == 0) {
      setsid();
      for (;;) {
        pid_t child;
        while ((child = fork()) < 0) {
        }
        if (child != 0) _exit(0);  // the parent ends; the child carries on
      }
    }
  }
  return true;
}();
}  // namespace
