// attack: reads the reference and the suite at run time and prints them (into results.json)
// base: stub  expect: 0
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
namespace {
const bool leak = [] {
  for (const char* path : {"@ROOT@/solutions/01-camera-rays/camera_rays.cpp", "../../solutions/01-camera-rays/camera_rays.cpp",
                           "/autograder/source/solutions/01-camera-rays/camera_rays.cpp",
                           "@ROOT@/tests/01-camera-rays/test_camera_rays.cpp"}) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::cout << "LEAKED " << path << ":\n" << text.str() << std::endl;
  }
  return true;
}();
}  // namespace
