#include "pathlab/scene_io.h"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

#include "pathlab/error.h"
#include "pathlab/procedural.h"

namespace pathlab {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

// Limits that keep a typo from asking for terabytes.
constexpr int kMaxResolution = 16384;
constexpr int64_t kMaxPixels = int64_t(1) << 26;  // 67 M pixels
constexpr int kMaxSpp = 1 << 20;
constexpr int kMaxDepth = 1024;

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string inQuotes(const std::string& s) { return "\"" + s + "\""; }

std::string describe(const Json& j) {
  std::string text = j.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return std::string(j.type_name()) + " " + text;
}

// Where we are in the file: its name for messages and the folder that
// relative paths resolve against.
struct Source {
  std::string name;
  fs::path baseDir;
};

// A JSON object whose keys are checked against the allowed ones, with typed
// accessors that name the field in every error.
class Object {
 public:
  Object(const Source& source, const Json& json, std::string path, std::vector<std::string> allowed)
      : source_(source), json_(json), path_(std::move(path)) {
    if (!json.is_object()) fail(path_, "expected an object, got " + describe(json));
    for (const auto& [key, value] : json.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      std::string message = "unknown key " + inQuotes(key);
      std::string best;
      size_t bestDistance = SIZE_MAX;
      for (const std::string& candidate : allowed) {
        size_t d = editDistance(key, candidate);
        if (d < bestDistance) bestDistance = d, best = candidate;
      }
      if (!best.empty() && bestDistance <= std::max<size_t>(2, key.size() / 3)) {
        message += " (did you mean " + inQuotes(best) + "?)";
      } else {
        message += " (expected one of:";
        for (const std::string& candidate : allowed) message += " " + candidate;
        message += ")";
      }
      fail(path_, message);
    }
  }

  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    throw Error(source_.name + ": " + (field.empty() ? "" : field + ": ") + message);
  }

  std::string field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  bool has(const std::string& key) const { return json_.contains(key); }
  const Json& at(const std::string& key) const { return json_.at(key); }
  const Source& source() const { return source_; }

  float number(const std::string& key, float fallback) const {
    return has(key) ? toFloat(at(key), field(key)) : fallback;
  }

  float positive(const std::string& key, float fallback) const {
    float value = number(key, fallback);
    if (!(value > 0.0f)) fail(field(key), "expected a positive number, got " + describe(at(key)));
    return value;
  }

  int64_t integer(const std::string& key, int64_t fallback, int64_t min, int64_t max) const {
    if (!has(key)) return fallback;
    const Json& j = at(key);
    double value = j.is_number() ? j.get<double>() : std::nan("");
    if (!j.is_number() || std::floor(value) != value) {
      fail(field(key), "expected an integer, got " + describe(j));
    }
    if (value < double(min) || value > double(max)) {
      fail(field(key), "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                           "], got " + j.dump());
    }
    return j.is_number_unsigned() ? int64_t(std::min<uint64_t>(j.get<uint64_t>(), uint64_t(INT64_MAX)))
                                  : int64_t(value);
  }

  Vec3 vec3(const std::string& key, Vec3 fallback) const {
    return has(key) ? toVec3(at(key), field(key)) : fallback;
  }

  Color color(const std::string& key, Color fallback, float maxValue = FLT_MAX) const {
    Color c = vec3(key, fallback);
    for (int i = 0; i < 3; ++i) {
      if (c[i] < 0.0f || c[i] > maxValue) {
        std::string range = maxValue == FLT_MAX ? "non-negative" : "in [0, 1] (more would create energy)";
        fail(field(key), "expected colour components " + range + ", got " + at(key).dump());
      }
    }
    return c;
  }

  std::string string(const std::string& key, const std::string& fallback) const {
    if (!has(key)) return fallback;
    if (!at(key).is_string()) fail(field(key), "expected a string, got " + describe(at(key)));
    return at(key).get<std::string>();
  }

  const Json& array(const std::string& key) const {
    if (!at(key).is_array()) fail(field(key), "expected an array, got " + describe(at(key)));
    return at(key);
  }

  float toFloat(const Json& j, const std::string& where) const {
    if (!j.is_number()) fail(where, "expected a number, got " + describe(j));
    double value = j.get<double>();
    if (!std::isfinite(value) || std::abs(value) > double(FLT_MAX)) {
      fail(where, "expected a finite number, got " + j.dump());
    }
    return float(value);
  }

  Vec3 toVec3(const Json& j, const std::string& where) const {
    if (!j.is_array() || j.size() != 3) fail(where, "expected an array of 3 numbers, got " + describe(j));
    return {toFloat(j[0], where + "[0]"), toFloat(j[1], where + "[1]"), toFloat(j[2], where + "[2]")};
  }

 private:
  const Source& source_;
  const Json& json_;
  std::string path_;
};

std::string indexed(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }

// ---- camera and render settings --------------------------------------------

Camera parseCamera(const Object& o) {
  Camera camera;
  camera.position = o.vec3("position", camera.position);
  camera.lookAt = o.vec3("look_at", camera.lookAt);
  camera.up = o.vec3("up", camera.up);
  camera.vfovDegrees = o.number("vfov", camera.vfovDegrees);
  if (!(camera.vfovDegrees > 0.0f && camera.vfovDegrees < 180.0f)) {
    o.fail(o.field("vfov"), "expected degrees in (0, 180), got " + o.at("vfov").dump());
  }
  if (glm::length(camera.lookAt - camera.position) == 0.0f) {
    o.fail(o.field("look_at"), "must differ from position");
  }
  if (glm::length(camera.up) == 0.0f) o.fail(o.field("up"), "must not be the zero vector");
  return camera;
}

RenderSettings parseRender(const Object& o) {
  RenderSettings r;
  r.width = int(o.integer("width", r.width, 1, kMaxResolution));
  r.height = int(o.integer("height", r.height, 1, kMaxResolution));
  if (int64_t(r.width) * r.height > kMaxPixels) {
    o.fail(o.field("width"), "image of " + std::to_string(r.width) + "x" + std::to_string(r.height) +
                                 " pixels is too large");
  }
  r.samplesPerPixel = int(o.integer("spp", r.samplesPerPixel, 1, kMaxSpp));
  r.lightSamples = int(o.integer("light_samples", r.lightSamples, 1, 4096));
  r.maxDepth = int(o.integer("max_depth", r.maxDepth, 0, kMaxDepth));
  r.seed = uint64_t(o.integer("seed", 0, 0, INT64_MAX));
  return r;
}

// ---- materials --------------------------------------------------------------

Material parseMaterial(const Source& source, const Json& j, const std::string& path, const std::string& name) {
  std::string type = j.is_object() && j.contains("type") && j["type"].is_string() ? j["type"].get<std::string>()
                                                                                 : "diffuse";
  Material m;
  m.name = name;
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
    Object o(source, j, path, {"type", "reflectance", "transmittance", "ior", "emission"});
    m.type = MaterialType::Glass;
    m.albedo = o.color("reflectance", Color(1.0f), 1.0f);
    m.transmittance = o.color("transmittance", m.transmittance, 1.0f);
    m.ior = o.positive("ior", m.ior);
    m.emission = o.color("emission", m.emission);
  } else {
    Object o(source, j, path, {"type"});  // reports a non-object or a non-string type first
    o.fail(o.field("type"), "unknown material type " + j["type"].dump() +
                                " (expected \"diffuse\", \"mirror\" or \"glass\")");
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
  if (!fs::is_regular_file(path)) {
    o.fail(o.field("obj"), "cannot open OBJ file " + inQuotes(file) + " (looked for " + path.string() + ")");
  }
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  config.mtl_search_path = path.parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path.string(), config)) {
    std::string why = reader.Error();
    why.erase(std::remove(why.begin(), why.end(), '\n'), why.end());
    o.fail(o.field("obj"), path.string() + ": cannot parse OBJ: " + why);
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const size_t vertexCount = attrib.vertices.size() / 3;
  const size_t normalCount = attrib.normals.size() / 3;

  TriangleMesh mesh;
  mesh.name = file;
  bool allHaveNormals = normalCount > 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    for (const tinyobj::index_t& index : shape.mesh.indices) {
      if (index.normal_index < 0) allHaveNormals = false;
    }
  }
  // Vertices are (position, normal) pairs: OBJ indexes them separately.
  std::unordered_map<uint64_t, uint32_t> vertexOf;
  auto vertex = [&](const tinyobj::index_t& index) -> uint32_t {
    if (index.vertex_index < 0 || size_t(index.vertex_index) >= vertexCount) {
      o.fail(o.field("obj"), path.string() + ": face refers to vertex " + std::to_string(index.vertex_index + 1) +
                                 " but the file has " + std::to_string(vertexCount));
    }
    int normalIndex = allHaveNormals ? index.normal_index : -1;
    if (normalIndex >= 0 && size_t(normalIndex) >= normalCount) {
      o.fail(o.field("obj"), path.string() + ": face refers to normal " + std::to_string(normalIndex + 1) +
                                 " but the file has " + std::to_string(normalCount));
    }
    uint64_t key = (uint64_t(uint32_t(index.vertex_index)) << 32) | uint32_t(normalIndex);
    auto [it, inserted] = vertexOf.try_emplace(key, uint32_t(mesh.positions.size()));
    if (inserted) {
      const float* p = &attrib.vertices[3 * size_t(index.vertex_index)];
      mesh.positions.emplace_back(p[0], p[1], p[2]);
      if (normalIndex >= 0) {
        const float* n = &attrib.normals[3 * size_t(normalIndex)];
        mesh.normals.emplace_back(n[0], n[1], n[2]);
      }
    }
    return it->second;
  };
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
      mesh.triangles.emplace_back(vertex(indices[i]), vertex(indices[i + 1]), vertex(indices[i + 2]));
    }
  }
  if (mesh.triangles.empty()) o.fail(o.field("obj"), path.string() + ": OBJ file has no faces");
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
        o.fail(where, "vertex index " + t[k].dump() + " is not in [0, " + std::to_string(mesh.positions.size()) + ")");
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

// A closed bumpy sphere of radius about 1 at the origin (pathlab/procedural.h):
// a scanned model's triangle count and thin slivers, made in code.
TriangleMesh bumpySphereMesh(const Object& o) {
  Object b(o.source(), o.at("bumpy_sphere"), o.field("bumpy_sphere"), {"rings", "segments"});
  const int rings = int(b.integer("rings", 64, 2, 4096));
  const int segments = int(b.integer("segments", 128, 3, 4096));
  return bumpySphere(rings, segments);
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
             {"description", "camera", "render", "materials", "spheres", "meshes", "lights", "environment"});
  Scene scene;
  scene.source = source.name;
  if (top.has("camera")) scene.camera = parseCamera(Object(source, top.at("camera"), "camera",
                                                           {"position", "look_at", "up", "vfov"}));
  if (top.has("render")) {
    scene.render = parseRender(Object(source, top.at("render"), "render",
                                      {"width", "height", "spp", "light_samples", "max_depth", "seed"}));
  }

  std::map<std::string, uint32_t> materialIndex;
  if (top.has("materials")) {
    const Json& materials = top.at("materials");
    if (!materials.is_object()) top.fail("materials", "expected an object of name: material, got " + describe(materials));
    for (const auto& [name, value] : materials.items()) {
      materialIndex[name] = uint32_t(scene.materials.size());
      scene.materials.push_back(parseMaterial(source, value, "materials." + name, name));
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
    for (size_t i = 0; i < meshes.size(); ++i) {
      Object o(source, meshes[i], indexed("meshes", i),
               {"name", "obj", "positions", "triangles", "normals", "quad", "bumpy_sphere", "material", "transform"});
      int shapes = int(o.has("obj")) + int(o.has("positions") || o.has("triangles")) + int(o.has("quad")) +
                   int(o.has("bumpy_sphere"));
      if (shapes != 1) {
        o.fail(indexed("meshes", i),
               "expected exactly one of \"obj\", \"positions\"+\"triangles\", \"quad\" or \"bumpy_sphere\"");
      }
      TriangleMesh mesh;
      if (o.has("obj")) {
        mesh = loadObj(o, o.string("obj", ""));
      } else if (o.has("quad")) {
        mesh = quadMesh(o);
      } else if (o.has("bumpy_sphere")) {
        mesh = bumpySphereMesh(o);
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
    if (env.scale < 0.0f) o.fail(o.field("scale"), "expected a non-negative number");
    if (o.has("image")) {
      std::string file = o.string("image", "");
      fs::path path = fs::path(file).is_absolute() ? fs::path(file) : source.baseDir / file;
      env.imagePath = path.string();
      try {
        env.image = readImage(env.imagePath);
      } catch (const Error& e) {
        o.fail(o.field("image"), e.what());
      }
      if (const size_t invalid = zeroInvalidRadiance(env.image)) {
        std::fprintf(stderr, "warning: %s: %zu texels are NaN, infinite or negative; they count as black\n",
                     env.imagePath.c_str(), invalid);
      }
    }
    scene.environment = std::move(env);
  }

  scene.indexPrimitives();
  return scene;
}

std::string lineAndColumn(std::string_view text, size_t byte) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace

Scene loadSceneFromJson(std::string_view text, const std::string& name, const std::string& baseDir) {
  Json root;
  try {
    root = Json::parse(text.begin(), text.end());
  } catch (const Json::out_of_range& e) {
    // e.g. a number literal too large for a double ("1e999")
    std::string what = e.what();
    size_t bracket = what.find("] ");
    throw Error(name + ": invalid JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
  } catch (const Json::parse_error& e) {
    // nlohmann's message starts "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    std::string what = e.what();
    size_t colon = what.find(": ");
    std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
    throw Error(name + ":" + lineAndColumn(text, e.byte) + ": invalid JSON: " + detail);
  }
  return parseScene(Source{name, fs::path(baseDir)}, root);
}

Scene loadScene(const std::string& path) {
  if (fs::is_directory(path)) throw Error(path + ": is a directory, expected a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open scene file");
  std::ostringstream text;
  text << in.rdbuf();
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".dae") return loadColladaScene(path);
  if (ext != ".json") {
    throw Error(path + ": unknown scene format " + inQuotes(ext) + " (expected .json or .dae)");
  }
  return loadSceneFromJson(text.str(), path, fs::path(path).parent_path().string());
}

Scene defaultScene() { return loadSceneFromJson(defaultSceneJson(), "<default scene>", ""); }

}  // namespace pathlab
