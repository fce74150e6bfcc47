// The OBJ path: a scene whose mesh is the input as an .obj file.
#include "fuzz_support.h"
#include "util/error.h"
#include "scene/scene_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pathlab::fuzz::writeInput(data, size, "mesh.obj");
  try {
    pathlab::loadSceneFromJson("{\"meshes\": [{\"obj\": \"" + path + "\"}]}", "fuzz.json", "/");
  } catch (const pathlab::Error&) {
  }
  return 0;
}
