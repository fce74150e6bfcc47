// COLLADA in the web build: the desktop's reader (collada.cpp) parses XML
// with pugixml, which Debian ships compiled for the host alone, without its
// sources (cmake/PathLabWeb.cmake). A .dae scene says so instead of loading.
#include "scene/scene_io.h"
#include "util/error.h"

namespace pathlab {

Scene loadColladaScene(const std::string& path) {
  throw Error(shown(path, 200) + ": COLLADA (.dae) scenes are not read by the web build (docs/web.md): open it in "
                                 "the desktop program, or give the scene as JSON with OBJ meshes");
}

}  // namespace pathlab
