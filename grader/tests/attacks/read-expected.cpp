// attack: reads the judge's binary and the suite's source for the expected values
// base: stub  expect: 0
#include <unistd.h>
#include <fstream>
#include <iostream>
#include <string>
namespace {
const bool peeked = [] {
  for (std::string path : {std::string("@BUILD@/tests/test-01-camera-rays"), "/proc/" + std::to_string(getppid()) + "/exe",
                           std::string("@ROOT@/tests/01-camera-rays/test_camera_rays.cpp")}) {
    std::ifstream in(path, std::ios::binary);
    if (in) std::cout << "LEAKED " << path << " is readable" << std::endl;
  }
  return true;
}();
}  // namespace
