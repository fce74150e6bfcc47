// attack: forks until fork fails; every child sleeps forever
// base: stub  expect: 0
#include <unistd.h>
namespace {
const bool bomb = [] {
  for (int i = 0; i < 100000; ++i) {
    pid_t pid = fork();
    if (pid < 0) break;
    if (pid == 0) {
      for (;;) pause();
    }
  }
  return true;
}();
}  // namespace
