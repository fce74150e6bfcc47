// attack: rewrites the suite's support code and the stubs on disk, so the next submission scores full marks
// base: stub  expect: 0
#include <fstream>
namespace {
const bool tampered = [] {
  for (const char* path : {"@ROOT@/grader/suite/listener.cpp", "@ROOT@/tasks/01-camera-rays/camera_rays.cpp",
                           "@ROOT@/tools/grade", "@BUILD@/tests/test-01-camera-rays"}) {
    std::ofstream out(path, std::ios::app);
    if (out) out << "\n// tampered\n";
  }
  return true;
}();
}  // namespace
