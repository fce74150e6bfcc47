// Loading scenes: PathLab's JSON format (docs/scene-format.md), OBJ meshes
// referenced from it, and the embedded default scene. Every failure throws
// pathlab::Error with one line naming the file, the line or field, and what
// was expected.
#pragma once

#include <string>
#include <string_view>

#include "core/scene.h"

namespace pathlab {

// By extension: .json (PathLab's format) or .dae (COLLADA with the course's profile).
Scene loadScene(const std::string& path);

// COLLADA 1.4 with the course's CMU462 / CGL extensions.
Scene loadColladaScene(const std::string& path);

// `name` is used in messages; relative paths inside resolve against `baseDir`.
Scene loadSceneFromJson(std::string_view text, const std::string& name, const std::string& baseDir);

// The Cornell box with two spheres (media/scenes/cornell-spheres.json),
// compiled into the binary.
Scene defaultScene();
std::string_view defaultSceneJson();

}  // namespace pathlab
