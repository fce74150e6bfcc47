// attack: opens the results path, the build's judge and the grader's folders for writing
// base: stub  expect: 0
#include <fstream>
namespace {
const bool written = [] {
  for (const char* path : {"@OUT@", "@BUILD@/tests/test-01-camera-rays", "@BUILD@/submission-objects/task-1.o"}) {
    std::ofstream out(path);
    if (out) out << "{\"score\": 1000000}";
  }
  return true;
}();
}  // namespace
