#include "scene/scene_io.h"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <unordered_map>

#include "scene/json_object.h"
#include "scene/obj_file.h"
#include "scene/procedural.h"
#include "util/error.h"
#include "util/input_file.h"

namespace pathlab {
namespace {

using json::describe;
using json::indexed;
using json::Json;
using json::Object;
using json::Range;
using json::Source;
namespace fs = std::filesystem;

// Limits that keep a typo from asking for terabytes (image size: scene.h).
constexpr int kMaxSpp = 1 << 20;
constexpr int kMaxDepth = 1024;
// All meshes of a scene together (each procedural one is capped at 8 M):
// 16 M triangles, about 1 GB with their tree. One budget for the scene, or
// eight meshes at their own caps would take 3 GB before anything failed.
constexpr size_t kMaxSceneTriangles = size_t(1) << 24;


// ---- camera and render settings --------------------------------------------

Camera parseCamera(const Object& o) {
  Camera camera;
  camera.position = o.vec3("position", camera.position);
  camera.lookAt = o.vec3("look_at", camera.lookAt);
  camera.up = o.vec3("up", camera.up);
  camera.vfovDegrees = o.number("vfov", camera.vfovDegrees);
  camera.apertureRadius = o.number("aperture_radius", camera.apertureRadius);
  if (!(camera.apertureRadius >= 0.0f) || !std::isfinite(camera.apertureRadius)) {
    o.fail(o.field("aperture_radius"), "expected a radius >= 0 (0: a pinhole), got " + o.at("aperture_radius").dump());
  }
  // Absent: focused at look_at (a position out of range is reported by the scene's checks).
  camera.focalDistance = o.has("focal_distance") ? o.positive("focal_distance", 1.0f)
                                                 : float(glm::length(glm::dvec3(camera.lookAt) - glm::dvec3(camera.position)));
  if (!(camera.vfovDegrees > 0.0f && camera.vfovDegrees < 180.0f)) {
    o.fail(o.field("vfov"), "expected degrees in (0, 180), got " + o.at("vfov").dump());  // a number
  }
  if (glm::length(camera.lookAt - camera.position) == 0.0f) {
    o.fail(o.field("look_at"), "must differ from position");
  }
  // Only up's direction matters: normalised in double, so (1e30, 1e30, 0) and
  // (1e-30, 1e-30, 0) mean what (1, 1, 0) means instead of overflowing later.
  const glm::dvec3 up(camera.up);
  if (!(glm::length(up) > 0.0)) o.fail(o.field("up"), "must not be the zero vector");
  camera.up = Vec3(glm::normalize(up));
  return camera;
}

RenderSettings parseRender(const Object& o) {
  RenderSettings r;
  r.width = int(o.integer("width", r.width, 1, kMaxImageSide));
  r.height = int(o.integer("height", r.height, 1, kMaxImageSide));
  checkResolution(r.width, r.height, o.source().name + ": " + o.field("width"));
  r.samplesPerPixel = int(o.integer("spp", r.samplesPerPixel, 1, kMaxSpp));
  r.lightSamples = int(o.integer("light_samples", r.lightSamples, 1, 4096));
  r.maxDepth = int(o.integer("max_depth", r.maxDepth, 0, kMaxDepth));
  r.seed = uint64_t(o.integer("seed", 0, 0, INT64_MAX));
  return r;
}

// ---- materials --------------------------------------------------------------

// The ranges of the materials' and the media's numbers (tasks 8 and 12).
// A conductor's eta is at least 1e-3 (real metals: 0.03 and up): below
// about 1e-19 with k = 0, n^2 underflows in float and Fresnel is NaN.
constexpr Range kRoughness{0.0, 1.0}, kEta{1e-3, 1e3}, kExtinctionIndex{0.0, 1e3};
constexpr Range kPhaseG{-1.0, 1.0, true, true};

// A rough material's perceptual roughness (alpha = roughness^2, task 8).
float roughnessOf(const Object& o) { return o.number("roughness", 0.5f, kRoughness); }

// ---- media (task 12) -----------------------------------------------------------

// A homogeneous medium: density (sigma_t) and albedo, or sigma_a and sigma_s
// whose sum is the same in every colour; g for its phase function.
Medium parseMedium(const Source& source, const Json& j, const std::string& path, const std::string& name) {
  Object o(source, j, path, {"density", "albedo", "sigma_a", "sigma_s", "g"});
  Medium m;
  m.name = name;
  const bool coefficients = o.has("sigma_a") || o.has("sigma_s");
  if (coefficients == o.has("density")) {
    o.fail(path, "give either density (and albedo) or sigma_a and sigma_s");
  }
  if (coefficients) {
    if (o.has("albedo")) o.fail(o.field("albedo"), "give either density and albedo or sigma_a and sigma_s, not both");
    const Color sigmaA = o.color("sigma_a", Color(0.0f)), sigmaS = o.color("sigma_s", Color(0.0f));
    const Color sigmaT = sigmaA + sigmaS;
    m.sigmaT = maxComponent(sigmaT);
    if (!(m.sigmaT > 0.0f)) o.fail(path, "sigma_a + sigma_s is 0: a medium that does nothing");
    if (!(sigmaT.x >= 0.9999f * m.sigmaT && sigmaT.y >= 0.9999f * m.sigmaT && sigmaT.z >= 0.9999f * m.sigmaT)) {
      o.fail(path, "sigma_a + sigma_s must be the same in every colour (one extinction for all: task 12), got [" +
                       std::to_string(sigmaT.x) + ", " + std::to_string(sigmaT.y) + ", " + std::to_string(sigmaT.z) +
                       "]; give density and a coloured albedo instead");
    }
    m.albedo = glm::clamp(sigmaS / m.sigmaT, 0.0f, 1.0f);
  } else {
    m.sigmaT = o.positive("density", 1.0f);
    m.albedo = o.color("albedo", m.albedo, 1.0f);
  }
  if (!(m.sigmaT <= kMaxSceneCoordinate)) o.fail(path, "an extinction above 1e12 per unit length");
  m.g = o.number("g", 0.0f, kPhaseG);
  return m;
}

using MediumNames = std::map<std::string, MediumIndex>;

MediumIndex mediumNamed(const Object& o, const std::string& key, const MediumNames& media) {
  const std::string name = o.string(key, "");
  const auto it = media.find(name);
  if (it != media.end()) return it->second;
  std::string known;
  for (const auto& entry : media) known += (known.empty() ? "" : ", ") + inQuotes(entry.first);
  o.fail(o.field(key), "unknown medium " + inQuotes(name) +
                           (known.empty() ? " (the scene defines no media)" : " (defined: " + known + ")"));
}

constexpr const char* kMaterialTypes[] = {"diffuse", "mirror", "glass", "conductor", "plastic", "interface"};

// A material's "type", checked before its other keys (which depend on it).
std::string materialType(const Source& source, const Json& j, const std::string& path) {
  if (!j.is_object() || !j.contains("type")) return "diffuse";
  std::string expected;
  for (const char* type : kMaterialTypes) expected += std::string(expected.empty() ? "" : ", ") + inQuotes(type);
  const Json& type = j["type"];
  if (!type.is_string()) {
    throw Error(source.name + ": " + path + ".type: expected a string (" + expected + "), got " + describe(type));
  }
  const std::string name = type.get<std::string>();
  if (std::find(std::begin(kMaterialTypes), std::end(kMaterialTypes), name) == std::end(kMaterialTypes)) {
    throw Error(source.name + ": " + path + ".type: unknown material type " + inQuotes(name) + " (expected " +
                expected + ")");
  }
  return name;
}

Material parseMaterial(const Source& source, const Json& j, const std::string& path, const std::string& name,
                       const MediumNames& media) {
  const std::string type = materialType(source, j, path);
  Material m;
  m.name = name;
  if (type == "interface") {
    Object o(source, j, path, {"type", "interior"});
    m.type = MaterialType::Interface;
    if (!o.has("interior")) o.fail(path, "an interface bounds a medium: give its interior");
    m.interior = mediumNamed(o, "interior", media);
    return m;
  }
  if (type == "diffuse") {
    Object o(source, j, path, {"type", "albedo", "emission"});
    m.type = MaterialType::Diffuse;
    m.albedo = o.color("albedo", m.albedo, 1.0f);
    m.emission = o.color("emission", m.emission);
  } else if (type == "mirror") {
    Object o(source, j, path, {"type", "reflectance", "emission"});
    m.type = MaterialType::Mirror;
    m.albedo = o.color("reflectance", Color(1.0f), 1.0f);
    m.emission = o.color("emission", m.emission);
  } else if (type == "glass") {
    Object o(source, j, path, {"type", "reflectance", "transmittance", "ior", "emission", "interior"});
    m.type = MaterialType::Glass;
    m.albedo = o.color("reflectance", Color(1.0f), 1.0f);
    m.transmittance = o.color("transmittance", m.transmittance, 1.0f);
    m.ior = o.positive("ior", m.ior);
    m.emission = o.color("emission", m.emission);
    if (o.has("interior")) m.interior = mediumNamed(o, "interior", media);
  } else if (type == "conductor") {
    Object o(source, j, path, {"type", "roughness", "f0", "eta", "k", "emission"});
    m.type = MaterialType::RoughConductor;
    m.roughness = roughnessOf(o);
    m.albedo = o.color("f0", Color(0.9f), 1.0f);
    if (o.has("eta") != o.has("k")) o.fail(o.field(o.has("eta") ? "k" : "eta"), "missing: eta and k come together");
    if (o.has("eta") && o.has("f0")) o.fail(o.field("f0"), "give either f0 (Schlick) or eta and k (exact), not both");
    if (o.has("eta")) {
      m.exactFresnel = true;
      m.eta = o.color("eta", Color(1.0f), kEta);
      m.k = o.color("k", Color(0.0f), kExtinctionIndex);
    }
    m.emission = o.color("emission", m.emission);
  } else if (type == "plastic") {
    Object o(source, j, path, {"type", "roughness", "albedo", "ior", "emission"});
    m.type = MaterialType::RoughPlastic;
    m.roughness = roughnessOf(o);
    m.albedo = o.color("albedo", Color(0.5f), 1.0f);
    m.ior = o.positive("ior", 1.5f);
    m.emission = o.color("emission", m.emission);
  }
  return m;
}

// ---- geometry -----------------------------------------------------------------

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

// ---- the whole scene ------------------------------------------------------------

Scene parseScene(const Source& source, const Json& root) {
  Object top(source, root, "",
             {"description", "camera", "render", "media", "medium", "materials", "spheres", "meshes", "lights",
              "environment"});
  Scene scene;
  scene.source = source.name;
  if (top.has("camera")) scene.camera = parseCamera(Object(source, top.at("camera"), "camera",
                                                           {"position", "look_at", "up", "vfov", "aperture_radius",
                                                            "focal_distance"}));
  if (top.has("render")) {
    scene.render = parseRender(Object(source, top.at("render"), "render",
                                      {"width", "height", "spp", "light_samples", "max_depth", "seed"}));
  }

  MediumNames mediumIndex;
  if (top.has("media")) {
    const Json& media = top.at("media");
    if (!media.is_object()) top.fail("media", "expected an object of name: medium, got " + describe(media));
    for (const auto& [name, value] : media.items()) {
      mediumIndex[name] = MediumIndex(scene.media.size());
      scene.media.push_back(parseMedium(source, value, "media." + name, name));
    }
  }
  if (top.has("medium")) scene.medium = mediumNamed(top, "medium", mediumIndex);

  std::map<std::string, uint32_t> materialIndex;
  if (top.has("materials")) {
    const Json& materials = top.at("materials");
    if (!materials.is_object()) top.fail("materials", "expected an object of name: material, got " + describe(materials));
    for (const auto& [name, value] : materials.items()) {
      materialIndex[name] = uint32_t(scene.materials.size());
      scene.materials.push_back(parseMaterial(source, value, "materials." + name, name, mediumIndex));
    }
  }
  auto materialFor = [&](const Object& o) -> uint32_t {
    if (!o.has("material")) {
      if (!materialIndex.count("default")) {
        materialIndex["default"] = uint32_t(scene.materials.size());
        scene.materials.push_back(Material{.name = "default"});
      }
      return materialIndex["default"];
    }
    std::string name = o.string("material", "");
    auto it = materialIndex.find(name);
    if (it == materialIndex.end()) {
      std::string known;
      for (const auto& entry : materialIndex) known += (known.empty() ? "" : ", ") + inQuotes(entry.first);
      o.fail(o.field("material"), "unknown material " + inQuotes(name) +
                                      (known.empty() ? " (the scene defines no materials)" : " (defined: " + known + ")"));
    }
    return it->second;
  };

  if (top.has("spheres")) {
    const Json& spheres = top.array("spheres");
    for (size_t i = 0; i < spheres.size(); ++i) {
      Object o(source, spheres[i], indexed("spheres", i), {"center", "radius", "material"});
      Sphere s;
      s.center = o.vec3("center", s.center);
      s.radius = o.positive("radius", s.radius);
      s.material = materialFor(o);
      scene.spheres.push_back(s);
    }
  }

  if (top.has("meshes")) {
    const Json& meshes = top.array("meshes");
    size_t planned = 0;
    for (size_t i = 0; i < meshes.size(); ++i) {
      planned += plannedTriangles(meshes[i]);
      if (planned > kMaxSceneTriangles) {
        top.fail(indexed("meshes", i), overSceneBudget(planned));
      }
    }
    size_t sceneTriangles = 0;
    for (size_t i = 0; i < meshes.size(); ++i) {
      Object o(source, meshes[i], indexed("meshes", i),
               {"name", "obj", "positions", "triangles", "normals", "quad", "bumpy_sphere", "coil", "material",
                "transform"});
      int shapes = int(o.has("obj")) + int(o.has("positions") || o.has("triangles")) + int(o.has("quad")) +
                   int(o.has("bumpy_sphere")) + int(o.has("coil"));
      if (shapes != 1) {
        o.fail(indexed("meshes", i), "expected exactly one of \"obj\", \"positions\"+\"triangles\", \"quad\", "
                                     "\"bumpy_sphere\" or \"coil\"");
      }
      TriangleMesh mesh;
      if (o.has("obj")) {
        mesh = loadObj(o, o.string("obj", ""));
      } else if (o.has("quad")) {
        mesh = quadMesh(o);
      } else if (o.has("bumpy_sphere")) {
        mesh = bumpySphereMesh(o);
      } else if (o.has("coil")) {
        mesh = coilMesh(o);
      } else {
        if (!o.has("positions") || !o.has("triangles")) {
          o.fail(indexed("meshes", i), "an inline mesh needs both \"positions\" and \"triangles\"");
        }
        mesh = inlineMesh(o);
      }
      if (o.has("transform")) {
        transformMesh(mesh, parseTransform(Object(source, o.at("transform"), o.field("transform"),
                                                   {"translate", "rotate", "scale"})));
      }
      for (const Point3& p : mesh.positions) {
        if (!isFinite(p)) o.fail(indexed("meshes", i), "a vertex position is not finite after the transform");
      }
      if (!hasArea(mesh)) o.fail(indexed("meshes", i), "every triangle of the mesh has zero area");
      mesh.name = o.string("name", mesh.name.empty() ? indexed("meshes", i) : mesh.name);
      mesh.material = materialFor(o);
      sceneTriangles += mesh.triangles.size();
      if (sceneTriangles > kMaxSceneTriangles) {
        o.fail(indexed("meshes", i), overSceneBudget(sceneTriangles));
      }
      scene.meshes.push_back(std::move(mesh));
    }
  }

  if (top.has("lights")) {
    const Json& lights = top.array("lights");
    for (size_t i = 0; i < lights.size(); ++i) {
      Object o(source, lights[i], indexed("lights", i), {"type", "position", "intensity"});
      std::string type = o.string("type", "point");
      if (type != "point") {
        o.fail(o.field("type"), "unknown light type " + inQuotes(type) +
                                    " (expected \"point\"; area lights are meshes or spheres with an emissive material)");
      }
      PointLight light;
      light.position = o.vec3("position", light.position);
      light.intensity = o.color("intensity", light.intensity);
      scene.pointLights.push_back(light);
    }
  }

  if (top.has("environment")) {
    Object o(source, top.at("environment"), "environment", {"color", "image", "scale"});
    Environment env;
    env.color = o.color("color", env.color);
    env.scale = o.number("scale", env.scale);
    // Radiance times the sampling tables' weights must stay finite in float.
    constexpr float kMaxRadiance = 1e12f;
    if (!(env.scale >= 0.0f && env.scale <= kMaxRadiance)) {
      o.fail(o.field("scale"), "expected a number from 0 to 1e12, got " + o.at("scale").dump());
    }
    if (!(maxComponent(env.color) <= kMaxRadiance)) o.fail(o.field("color"), "expected values from 0 to 1e12");
    if (o.has("image")) {
      std::string file = o.string("image", "");
      fs::path path = fs::path(file).is_absolute() ? fs::path(file) : source.baseDir / file;
      env.imagePath = path.string();
      bool hasAlpha = false;
      try {
        env.image = readImage(env.imagePath, &hasAlpha);
      } catch (const Error& e) {
        o.fail(o.field("image"), e.what());
      }
      if (hasAlpha) {  // a sky has no transparency: said, so alpha 0 cannot look like a bug in the renderer
        printWarning(env.imagePath + ": the alpha channel is ignored; the colours are used as stored");
      }
      if (const size_t invalid = zeroInvalidRadiance(env.image)) {
        printWarning(env.imagePath + ": " + std::to_string(invalid) +
                     " texels are NaN, infinite or negative; they count as black");
      }
    }
    scene.environment = std::move(env);
  }

  scene.indexPrimitives();
  checkSceneLimits(scene);
  return scene;
}


}  // namespace

Scene loadSceneFromJson(std::string_view text, const std::string& name, const std::string& baseDir) {
  return parseScene(Source{name, fs::path(baseDir)}, json::parse(text, name));
}

Scene loadScene(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".dae") return loadColladaScene(path);
  const std::string text = readInputFile(path, "scene file", kMaxJsonSceneBytes);
  if (ext != ".json") {
    throw Error(shown(path, 200) + ": unknown scene format " + inQuotes(ext) + " (expected .json or .dae)");
  }
  return loadSceneFromJson(text, path, fs::path(path).parent_path().string());
}

Scene defaultScene() { return loadSceneFromJson(defaultSceneJson(), "<default scene>", ""); }

}  // namespace pathlab
