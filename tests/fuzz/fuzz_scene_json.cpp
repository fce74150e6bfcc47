// The JSON scene loader on arbitrary text (seed corpus: media/scenes, tests/inputs).
#include "fuzz_support.h"
#include "util/error.h"
#include "scene/scene_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    // Files the scene names resolve inside a folder that does not exist.
    pathlab::loadSceneFromJson(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json",
                               "/nonexistent-fuzz-folder");
  } catch (const pathlab::Error&) {
  }
  return 0;
}
