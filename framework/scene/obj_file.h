// Wavefront OBJ meshes: positions, normals and polygonal faces (everything
// else, materials included, is ignored: materials come from the scene file).
#pragma once

#include <string>
#include <string_view>

#include "core/scene.h"

namespace pathlab {

// Largest non-convex polygon triangulated (ear clipping costs n^2); a convex
// polygon of any size is split as a fan.
constexpr size_t kMaxConcavePolygonVertices = 4096;

// Parses OBJ text; `name` prefixes every error ("NAME:LINE: problem").
// Refuses numbers that are not finite, indices out of range, faces of fewer
// than 3 vertices, and a file without faces.
TriangleMesh parseObj(std::string_view text, const std::string& name);

// readInputFile (a regular file of at most kMaxMeshFileBytes), then parseObj.
TriangleMesh readObjFile(const std::string& path);

}  // namespace pathlab
