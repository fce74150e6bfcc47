// Environment maps: the input as an .hdr, .exr or .png file (the first byte
// picks which), loaded as a scene's environment, then its importance
// sampling built and used as the renderer would.
#include "fuzz_support.h"
#include "util/error.h"
#include "core/lights.h"
#include "util/random.h"
#include "scene/scene_io.h"
#include "render/task_wiring.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* extensions[] = {".hdr", ".exr", ".png"};
  const std::string path = pathlab::fuzz::writeInput(data + 1, size - 1, std::string("map") + extensions[data[0] % 3]);
  try {
    const pathlab::Scene scene =
        pathlab::loadSceneFromJson("{\"environment\": {\"image\": \"" + path + "\"}}", "fuzz.json", "/");
    const pathlab::Lights lights = pathlab::Lights::fromScene(scene, pathlab::kLinkedTasks.environment);
    if (lights.environment) {
      for (uint32_t i = 0; i < 16; ++i) {
        pathlab::Sampler sampler(i, 0, 1);
        if (auto sample = lights.environment->sample(sampler.next2D())) {
          (void)lights.environment->radiance(sample->direction);
          (void)lights.environment->pdf(sample->direction);
        }
      }
    }
  } catch (const pathlab::Error&) {
  }
  return 0;
}
