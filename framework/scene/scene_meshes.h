// The meshes of a JSON scene (scene_io.cpp reads the rest): each kind of
// "meshes" entry made into triangles, its transform, and the scene's budget
// of triangles. Used only inside scene/; each function reports a bad field
// through the Object it reads (pathlab::Error naming the file and field).
#pragma once

#include <cstddef>
#include <string>

#include "core/scene.h"
#include "scene/json_object.h"

namespace pathlab::scene_meshes {

// All meshes of a scene together (each procedural one is capped at 8 M):
// 16 M triangles, about 1 GB with their tree. One budget for the scene, or
// eight meshes at their own caps would take 3 GB before anything failed.
inline constexpr size_t kMaxSceneTriangles = size_t(1) << 24;

// "transform": translate, then rotate (axis, degrees), then scale.
glm::mat4 parseTransform(const json::Object& o);
// "obj": an OBJ file, relative to the scene's folder.
TriangleMesh loadObj(const json::Object& o, const std::string& file);
// "positions", "triangles" (and optional "normals") written out.
TriangleMesh inlineMesh(const json::Object& o);
// The procedural meshes of scene/procedural.h: "quad", "bumpy_sphere", "coil".
TriangleMesh quadMesh(const json::Object& o);
TriangleMesh bumpySphereMesh(const json::Object& o);
TriangleMesh coilMesh(const json::Object& o);

// The error of a scene whose meshes reach `total` triangles, over kMaxSceneTriangles.
std::string overSceneBudget(size_t total);
// The triangles a mesh description will make, known before it is made.
size_t plannedTriangles(const json::Json& mesh);
// Whether any triangle of the mesh has a non-zero area.
bool hasArea(const TriangleMesh& mesh);

}  // namespace pathlab::scene_meshes
