// attack: a daemon (double fork, new session) outlives the test and rewrites results.json afterwards
// base: stub  expect: 0
#include <unistd.h>
#include <fstream>
namespace {
const bool daemonized = [] {
  if (fork() == 0) {
    setsid();
    if (fork() == 0) {
      for (int i = 0; i < 40; ++i) {
        sleep(1);
        std::ofstream out("@OUT@");
        if (out) out << "{\"score\": 1000000, \"tests\": []}";
      }
      _exit(0);
    }
    _exit(0);
  }
  return true;
}();
}  // namespace
