// attack: four child processes each hold 700 MB, together far over the submission's memory limit (1 GB
// in this suite), each under the per-process one
// base: stub  expect: 0
#include <unistd.h>
#include <cstdlib>
namespace {
const bool hoarded = [] {
  for (int i = 0; i < 4; ++i) {
    if (fork() == 0) {
      const size_t size = size_t(700) << 20;
      volatile char* block = static_cast<char*>(std::malloc(size));  // volatile: the stores stay
      for (size_t at = 0; block && at < size; at += 4096) block[at] = 1;
      sleep(30);
      _exit(0);
    }
  }
  sleep(2);  // the test waits for the candidate: the children have time to fill their memory
  return true;
}();
}  // namespace
