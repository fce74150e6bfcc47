// Reading what a user names and writing what they asked for, safely: only
// regular files are read (a FIFO would hang, /dev/zero never ends, a folder
// is a mistake), sizes are capped before anything is allocated, and no
// filesystem call throws: every failure is a pathlab::Error naming the path.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace pathlab {

// Caps on what one file may hold (docs/reliability.md, "Limits").
// A JSON scene holds settings and small inline meshes (big ones are OBJ files);
// COLLADA holds the meshes themselves, like OBJ.
constexpr size_t kMaxJsonSceneBytes = size_t(64) << 20;
constexpr size_t kMaxColladaBytes = size_t(256) << 20;
constexpr size_t kMaxMeshFileBytes = size_t(512) << 20;

// The whole file at `path`. `what` names it in messages ("scene file",
// "OBJ file"). Refuses anything but a regular file, and files over maxBytes.
std::string readInputFile(const std::string& path, std::string_view what, size_t maxBytes);

// Throws unless `path` is a regular file (for files a library opens itself);
// returns its size in bytes.
size_t requireRegularFile(const std::string& path, std::string_view what);

// Writes `bytes` to `path` through a temporary file beside it (".NAME.partial.EXT"),
// checking every write, the flush to disk and the close, then renames it over
// `path`. On any failure the temporary file is removed and nothing is left.
void writeFileAtomically(const std::string& path, std::string_view bytes);

// Creates `folder` and its parents if missing; a pathlab::Error naming it otherwise.
void createFolders(const std::string& folder);

// The temporary name writeFileAtomically writes through.
std::string partialPathFor(const std::string& path);

}  // namespace pathlab
