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
#include "scene/scene_meshes.h"
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
using namespace scene_meshes;
namespace fs = std::filesystem;

// Limits that keep a typo from asking for terabytes (image size: scene.h).
constexpr int kMaxSpp = 1 << 20;
constexpr int kMaxDepth = 1024;


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

// ---- the whole scene ------------------------------------------------------------

// The "media" object, name: medium; each one's index by its name.
MediumNames parseMedia(const Source& source, const Object& top, Scene& scene) {
  MediumNames mediumIndex;
  if (!top.has("media")) return mediumIndex;
  const Json& media = top.at("media");
  if (!media.is_object()) top.fail("media", "expected an object of name: medium, got " + describe(media));
  for (const auto& [name, value] : media.items()) {
    mediumIndex[name] = MediumIndex(scene.media.size());
    scene.media.push_back(parseMedium(source, value, "media." + name, name));
  }
  return mediumIndex;
}

// The "materials" object, name: material, and each shape's "material" by
// name (none: a "default" material, made the first time one is needed).
class MaterialNames {
 public:
  MaterialNames(const Source& source, const Object& top, const MediumNames& mediumIndex, Scene& scene) : scene_(scene) {
    if (!top.has("materials")) return;
    const Json& materials = top.at("materials");
    if (!materials.is_object()) top.fail("materials", "expected an object of name: material, got " + describe(materials));
    for (const auto& [name, value] : materials.items()) {
      index_[name] = uint32_t(scene.materials.size());
      scene.materials.push_back(parseMaterial(source, value, "materials." + name, name, mediumIndex));
    }
  }

  uint32_t of(const Object& o) {
    if (!o.has("material")) {
      if (!index_.count("default")) {
        index_["default"] = uint32_t(scene_.materials.size());
        scene_.materials.push_back(Material{.name = "default"});
      }
      return index_["default"];
    }
    std::string name = o.string("material", "");
    auto it = index_.find(name);
    if (it == index_.end()) {
      std::string known;
      for (const auto& entry : index_) known += (known.empty() ? "" : ", ") + inQuotes(entry.first);
      o.fail(o.field("material"), "unknown material " + inQuotes(name) +
                                      (known.empty() ? " (the scene defines no materials)" : " (defined: " + known + ")"));
    }
    return it->second;
  }

 private:
  Scene& scene_;
  std::map<std::string, uint32_t> index_;
};

void parseSpheres(const Source& source, const Object& top, MaterialNames& materials, Scene& scene) {
  if (!top.has("spheres")) return;
  const Json& spheres = top.array("spheres");
  for (size_t i = 0; i < spheres.size(); ++i) {
    Object o(source, spheres[i], indexed("spheres", i), {"center", "radius", "material"});
    Sphere s;
    s.center = o.vec3("center", s.center);
    s.radius = o.positive("radius", s.radius);
    s.material = materials.of(o);
    scene.spheres.push_back(s);
  }
}

// One entry of "meshes": exactly one shape (an OBJ file, inline positions and
// triangles, a quad, a bumpy sphere or a coil), transformed, checked.
TriangleMesh parseMesh(const Source& source, const Object& o, const std::string& field) {
  int shapes = int(o.has("obj")) + int(o.has("positions") || o.has("triangles")) + int(o.has("quad")) +
               int(o.has("bumpy_sphere")) + int(o.has("coil"));
  if (shapes != 1) {
    o.fail(field,
           "expected exactly one of \"obj\", \"positions\"+\"triangles\", \"quad\", \"bumpy_sphere\" or \"coil\"");
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
      o.fail(field, "an inline mesh needs both \"positions\" and \"triangles\"");
    }
    mesh = inlineMesh(o);
  }
  if (o.has("transform")) {
    transformMesh(mesh, parseTransform(
                            Object(source, o.at("transform"), o.field("transform"), {"translate", "rotate", "scale"})));
  }
  for (const Point3& p : mesh.positions) {
    if (!isFinite(p)) o.fail(field, "a vertex position is not finite after the transform");
  }
  if (!hasArea(mesh)) o.fail(field, "every triangle of the mesh has zero area");
  mesh.name = o.string("name", mesh.name.empty() ? field : mesh.name);
  return mesh;
}

// "meshes", within the scene's triangle budget: planned from the entries
// before any is made (so an over-budget scene fails before it fills memory),
// then counted as they are made.
void parseMeshes(const Source& source, const Object& top, MaterialNames& materials, Scene& scene) {
  if (!top.has("meshes")) return;
  const Json& meshes = top.array("meshes");
  size_t planned = 0;
  for (size_t i = 0; i < meshes.size(); ++i) {
    planned += plannedTriangles(meshes[i]);
    if (planned > kMaxSceneTriangles) top.fail(indexed("meshes", i), overSceneBudget(planned));
  }
  size_t sceneTriangles = 0;
  for (size_t i = 0; i < meshes.size(); ++i) {
    Object o(source, meshes[i], indexed("meshes", i),
             {"name", "obj", "positions", "triangles", "normals", "quad", "bumpy_sphere", "coil", "material",
              "transform"});
    TriangleMesh mesh = parseMesh(source, o, indexed("meshes", i));
    mesh.material = materials.of(o);
    sceneTriangles += mesh.triangles.size();
    if (sceneTriangles > kMaxSceneTriangles) o.fail(indexed("meshes", i), overSceneBudget(sceneTriangles));
    scene.meshes.push_back(std::move(mesh));
  }
}

void parsePointLights(const Source& source, const Object& top, Scene& scene) {
  if (!top.has("lights")) return;
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

// "environment": a constant colour, or an equirectangular image, times a scale.
Environment parseEnvironment(const Source& source, const Object& o) {
  Environment env;
  env.color = o.color("color", env.color);
  env.scale = o.number("scale", env.scale);
  // Radiance times the sampling tables' weights must stay finite in float.
  constexpr float kMaxRadiance = 1e12f;
  if (!(env.scale >= 0.0f && env.scale <= kMaxRadiance)) {
    o.fail(o.field("scale"), "expected a number from 0 to 1e12, got " + o.at("scale").dump());
  }
  if (!(maxComponent(env.color) <= kMaxRadiance)) o.fail(o.field("color"), "expected values from 0 to 1e12");
  if (!o.has("image")) return env;
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
  return env;
}

Scene parseScene(const Source& source, const Json& root) {
  Object top(source, root, "",
             {"description", "camera", "render", "media", "medium", "materials", "spheres", "meshes", "lights",
              "environment"});
  Scene scene;
  scene.source = source.name;
  if (top.has("camera")) {
    scene.camera = parseCamera(Object(source, top.at("camera"), "camera",
                                      {"position", "look_at", "up", "vfov", "aperture_radius", "focal_distance"}));
  }
  if (top.has("render")) {
    scene.render = parseRender(
        Object(source, top.at("render"), "render", {"width", "height", "spp", "light_samples", "max_depth", "seed"}));
  }
  const MediumNames mediumIndex = parseMedia(source, top, scene);
  if (top.has("medium")) scene.medium = mediumNamed(top, "medium", mediumIndex);
  MaterialNames materials(source, top, mediumIndex, scene);
  parseSpheres(source, top, materials, scene);
  parseMeshes(source, top, materials, scene);
  parsePointLights(source, top, scene);
  if (top.has("environment")) {
    scene.environment =
        parseEnvironment(source, Object(source, top.at("environment"), "environment", {"color", "image", "scale"}));
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
