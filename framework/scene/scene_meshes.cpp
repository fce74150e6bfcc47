#include "scene/scene_meshes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

#include "scene/obj_file.h"
#include "scene/procedural.h"
#include "util/error.h"

namespace pathlab::scene_meshes {

using json::Json;
using json::describe;
using json::indexed;
using json::Object;
namespace fs = std::filesystem;

glm::mat4 parseTransform(const Object& o) {
  glm::mat4 m(1.0f);
  Vec3 translate = o.vec3("translate", Vec3(0.0f));
  m = glm::translate(m, translate);
  if (o.has("rotate")) {
    Object r(o.source(), o.at("rotate"), o.field("rotate"), {"axis", "degrees"});
    Vec3 axis = r.vec3("axis", Vec3(0.0f, 1.0f, 0.0f));
    if (glm::length(axis) == 0.0f) r.fail(r.field("axis"), "must not be the zero vector");
    m = glm::rotate(m, glm::radians(r.number("degrees", 0.0f)), glm::normalize(axis));
  }
  if (o.has("scale")) {
    Vec3 scale = o.at("scale").is_array() ? o.vec3("scale", Vec3(1.0f)) : Vec3(o.number("scale", 1.0f));
    if (!(scale.x != 0.0f && scale.y != 0.0f && scale.z != 0.0f)) {
      o.fail(o.field("scale"), "must be non-zero on every axis");
    }
    m = glm::scale(m, scale);
  }
  return m;
}

TriangleMesh loadObj(const Object& o, const std::string& file) {
  fs::path path = fs::path(file).is_absolute() ? fs::path(file) : o.source().baseDir / file;
  TriangleMesh mesh;
  try {
    mesh = readObjFile(path.string());
  } catch (const Error& e) {
    o.fail(o.field("obj"), e.what());
  }
  mesh.name = file;
  return mesh;
}

TriangleMesh inlineMesh(const Object& o) {
  TriangleMesh mesh;
  const Json& positions = o.array("positions");
  for (size_t i = 0; i < positions.size(); ++i) {
    mesh.positions.push_back(o.toVec3(positions[i], indexed(o.field("positions"), i)));
  }
  const Json& triangles = o.array("triangles");
  for (size_t i = 0; i < triangles.size(); ++i) {
    const Json& t = triangles[i];
    const std::string where = indexed(o.field("triangles"), i);
    if (!t.is_array() || t.size() != 3) o.fail(where, "expected an array of 3 vertex indices, got " + describe(t));
    glm::uvec3 tri;
    for (int k = 0; k < 3; ++k) {
      if (!t[k].is_number_unsigned() || t[k].get<uint64_t>() >= mesh.positions.size()) {
        o.fail(where, "vertex index " + describe(t[k]) + " is not in [0, " + std::to_string(mesh.positions.size()) + ")");
      }
      tri[k] = uint32_t(t[k].get<uint64_t>());
    }
    mesh.triangles.push_back(tri);
  }
  if (o.has("normals")) {
    const Json& normals = o.array("normals");
    if (normals.size() != mesh.positions.size()) {
      o.fail(o.field("normals"), "expected one normal per position (" + std::to_string(mesh.positions.size()) +
                                     "), got " + std::to_string(normals.size()));
    }
    for (size_t i = 0; i < normals.size(); ++i) {
      Vec3 n = o.toVec3(normals[i], indexed(o.field("normals"), i));
      if (glm::length(n) == 0.0f) o.fail(indexed(o.field("normals"), i), "normal must not be zero");
      mesh.normals.push_back(glm::normalize(n));
    }
  }
  if (mesh.triangles.empty()) o.fail(o.field("triangles"), "mesh has no triangles");
  return mesh;
}

TriangleMesh quadMesh(const Object& o) {
  Object q(o.source(), o.at("quad"), o.field("quad"), {"corner", "edge_u", "edge_v"});
  for (const char* key : {"corner", "edge_u", "edge_v"}) {
    if (!q.has(key)) q.fail(q.field(key), "is required");
  }
  Point3 corner = q.vec3("corner", Vec3(0.0f));
  Vec3 u = q.vec3("edge_u", Vec3(0.0f)), v = q.vec3("edge_v", Vec3(0.0f));
  if (glm::length(glm::cross(u, v)) == 0.0f) q.fail(q.field("edge_v"), "edges are parallel: the quad has no area");
  TriangleMesh mesh;
  mesh.positions = {corner, corner + u, corner + u + v, corner + v};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};  // front face: u x v
  return mesh;
}

// A closed bumpy sphere of radius about 1 at the origin (scene/procedural.h):
// a scanned model's triangle count and thin slivers, made in code.
TriangleMesh bumpySphereMesh(const Object& o) {
  Object b(o.source(), o.at("bumpy_sphere"), o.field("bumpy_sphere"), {"rings", "segments"});
  const int rings = int(b.integer("rings", 64, 2, 4096));
  const int segments = int(b.integer("segments", 128, 3, 4096));
  if (int64_t(rings) * segments > (int64_t(1) << 22)) {  // 8 M triangles, about 400 MB
    b.fail(b.field("rings"), std::to_string(rings) + " rings of " + std::to_string(segments) +
                                 " segments is more than 4,194,304 quads");
  }
  return bumpySphere(rings, segments);
}

// A coiled wire of radius about 1 around the y axis (scene/procedural.h):
// many long, thin triangles, made in code.
TriangleMesh coilMesh(const Object& o) {
  Object c(o.source(), o.at("coil"), o.field("coil"), {"turns", "segments", "sides", "wire"});
  const int turns = int(c.integer("turns", 40, 1, 4096));
  const int segments = int(c.integer("segments", 32, 3, 4096));
  const int sides = int(c.integer("sides", 8, 3, 256));
  const float wire = c.positive("wire", 0.01f);
  if (wire > 0.5f) c.fail(c.field("wire"), "expected a wire radius in (0, 0.5] (the coil's radius is 1), got " +
                                               c.at("wire").dump());
  if (int64_t(turns) * segments * sides > (int64_t(1) << 22)) {  // 8 M triangles, as for bumpy_sphere
    c.fail(c.field("turns"), std::to_string(turns) + " turns of " + std::to_string(segments) + " segments of " +
                                 std::to_string(sides) + " sides is more than 4,194,304 quads");
  }
  return coil(turns, segments, sides, wire);
}

// The error of a scene whose meshes reach `total` triangles, over kMaxSceneTriangles.
std::string overSceneBudget(size_t total) {
  return "the scene's meshes have more than " + std::to_string(kMaxSceneTriangles) + " triangles together (" +
         std::to_string(total) + " with this one): the most one scene may have";
}

// The triangles a mesh will have, known from its description alone
// (procedural and inline meshes; an OBJ file counts once loaded), so a scene
// over its budget fails before anything is built. Values out of range, and
// a mesh over its own cap, count as their limit: the mesh's own parse
// reports them.
size_t plannedTriangles(const Json& mesh) {
  constexpr int64_t kMostPerProceduralMesh = int64_t(2) << 22;  // 4,194,304 quads

  auto count = [](const Json& o, const char* key, int64_t fallback, int64_t most) -> int64_t {
    if (!o.is_object() || !o.contains(key) || !o.at(key).is_number_integer()) return fallback;
    return std::clamp<int64_t>(o.at(key).get<int64_t>(), 0, most);
  };
  if (!mesh.is_object()) return 0;
  if (mesh.contains("bumpy_sphere")) {
    const Json& b = mesh.at("bumpy_sphere");
    return size_t(std::min(kMostPerProceduralMesh, 2 * count(b, "rings", 64, 4096) * count(b, "segments", 128, 4096)));
  }
  if (mesh.contains("coil")) {
    const Json& c = mesh.at("coil");
    return size_t(std::min(kMostPerProceduralMesh,
                           2 * count(c, "turns", 40, 4096) * count(c, "segments", 32, 4096) * count(c, "sides", 8, 256)));
  }
  if (mesh.contains("triangles") && mesh.at("triangles").is_array()) return mesh.at("triangles").size();
  return 0;
}

bool hasArea(const TriangleMesh& mesh) {
  for (const glm::uvec3& t : mesh.triangles) {
    Vec3 e1 = mesh.positions[t.y] - mesh.positions[t.x], e2 = mesh.positions[t.z] - mesh.positions[t.x];
    if (glm::length(glm::cross(e1, e2)) > 0.0f) return true;
  }
  return false;
}

}  // namespace pathlab::scene_meshes
