// The COLLADA importer on arbitrary XML (seed corpus: tests/inputs, and $PATHLAB_DATA_DIR/course-scenes when set).
#include "fuzz_support.h"
#include "util/error.h"
#include "scene/scene_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pathlab::fuzz::writeInput(data, size, "scene.dae");
  try {
    pathlab::loadColladaScene(path);
  } catch (const pathlab::Error&) {
  }
  return 0;
}
