// COLLADA 1.4 scenes with the course's extensions (technique profile
// "CMU462", identical in the CS184 "CGL" copies): meshes (polylist and
// triangles), node transforms, analytic spheres, point and area lights,
// emission, diffuse / mirror / glass materials, the camera.
#include <pugixml.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "pathlab/aabb.h"
#include "pathlab/error.h"
#include "pathlab/scene_io.h"

namespace pathlab {
namespace {

class ColladaReader {
 public:
  explicit ColladaReader(const std::string& path) : file_(path) {
    pugi::xml_parse_result parsed = document_.load_file(path.c_str());
    if (!parsed) {
      throw Error(path + ": invalid XML at byte " + std::to_string(parsed.offset) + ": " + parsed.description());
    }
    root_ = document_.child("COLLADA");
    if (!root_) throw Error(path + ": not a COLLADA file (no <COLLADA> element)");
    indexIds(root_);
  }

  Scene read() {
    scene_.source = file_;
    pugi::xml_node visualScene = resolve(root_.child("scene").child("instance_visual_scene").attribute("url").value(),
                                         "scene/instance_visual_scene");
    for (pugi::xml_node node : visualScene.children("node")) readNode(node, glm::mat4(1.0f));
    placeLights();
    if (scene_.meshes.empty() && scene_.spheres.empty()) fail("library_visual_scenes", "the scene has no geometry");
    scene_.indexPrimitives();
    placeCamera();
    return std::move(scene_);
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw Error(file_ + ": " + where + ": " + what);
  }

  void indexIds(pugi::xml_node node) {
    for (pugi::xml_node child : node.children()) {
      if (const char* id = child.attribute("id").value(); *id) ids_[id] = child;
      indexIds(child);
    }
  }

  pugi::xml_node resolve(const std::string& url, const std::string& where) const {
    if (url.size() < 2 || url[0] != '#') fail(where, "expected a reference like \"#id\", got \"" + url + "\"");
    auto it = ids_.find(url.substr(1));
    if (it == ids_.end()) fail(where, "refers to \"" + url + "\", which the file does not define");
    return it->second;
  }

  std::vector<float> numbers(pugi::xml_node node, const std::string& where, size_t expected = 0) const {
    std::vector<float> values;
    std::istringstream in(node.child_value());
    std::string token;
    while (in >> token) {
      char* end = nullptr;
      float v = std::strtof(token.c_str(), &end);
      if (*end != '\0' || !std::isfinite(v)) fail(where, "expected numbers, got \"" + token + "\"");
      values.push_back(v);
    }
    if (expected && values.size() != expected) {
      fail(where, "expected " + std::to_string(expected) + " numbers, got " + std::to_string(values.size()));
    }
    return values;
  }

  std::vector<long> indices(pugi::xml_node node, const std::string& where) const {
    std::vector<long> values;
    std::istringstream in(node.child_value());
    std::string token;
    while (in >> token) {
      char* end = nullptr;
      long v = std::strtol(token.c_str(), &end, 10);
      if (*end != '\0' || v < 0) fail(where, "expected non-negative indices, got \"" + token + "\"");
      values.push_back(v);
    }
    return values;
  }

  // The course's <extra><technique profile="CMU462"> (or "CGL") block.
  static pugi::xml_node courseTechnique(pugi::xml_node parent) {
    for (pugi::xml_node technique : parent.child("extra").children("technique")) {
      std::string profile = technique.attribute("profile").value();
      if (profile == "CMU462" || profile == "CGL") return technique;
    }
    return {};
  }

  Color color(pugi::xml_node node, const std::string& where) const {
    std::vector<float> v = numbers(node, where);
    if (v.size() < 3) fail(where, "expected a colour of 3 or 4 numbers");
    Color c(v[0], v[1], v[2]);
    if (glm::any(glm::lessThan(c, Color(0.0f)))) fail(where, "colour components must not be negative");
    return c;
  }

  // ---- materials ----------------------------------------------------------

  uint32_t material(const std::string& url, const std::string& where) {
    auto cached = materials_.find(url);
    if (cached != materials_.end()) return cached->second;
    pugi::xml_node material = resolve(url, where);
    const std::string name = material.attribute("id").value();
    pugi::xml_node effect = resolve(material.child("instance_effect").attribute("url").value(),
                                    "material \"" + name + "\"/instance_effect");
    const std::string effectWhere = std::string("effect \"") + effect.attribute("id").value() + "\"";
    Material m;
    m.name = name;
    // The common profile's diffuse colour (phong, blinn or lambert).
    pugi::xml_node common = effect.child("profile_COMMON").child("technique");
    for (const char* model : {"phong", "blinn", "lambert"}) {
      if (pugi::xml_node c = common.child(model).child("diffuse").child("color")) {
        m.albedo = glm::clamp(color(c, effectWhere + "/diffuse"), 0.0f, 1.0f);
      }
    }
    if (pugi::xml_node technique = courseTechnique(effect)) {
      if (pugi::xml_node emission = technique.child("emission")) {
        m.emission = color(emission.child("radiance"), effectWhere + "/emission/radiance");
        m.albedo = Color(0.0f);  // the course's emitters reflect nothing
      } else if (pugi::xml_node mirror = technique.child("mirror")) {
        m.type = MaterialType::Mirror;
        m.albedo = glm::clamp(color(mirror.child("reflectance"), effectWhere + "/mirror/reflectance"), 0.0f, 1.0f);
      } else if (pugi::xml_node glass = technique.child("glass")) {
        m.type = MaterialType::Glass;
        m.albedo = glm::clamp(color(glass.child("reflectance"), effectWhere + "/glass/reflectance"), 0.0f, 1.0f);
        m.transmittance = glm::clamp(color(glass.child("transmittance"), effectWhere + "/glass/transmittance"), 0.0f, 1.0f);
        m.ior = numbers(glass.child("ior"), effectWhere + "/glass/ior", 1)[0];
        if (!(m.ior > 0.0f)) fail(effectWhere + "/glass/ior", "must be positive");
      } else if (pugi::xml_node other = technique.first_child()) {
        fail(effectWhere, std::string("material type <") + other.name() + "> is not supported (diffuse, emission, mirror, glass)");
      }
    }
    scene_.materials.push_back(m);
    return materials_[url] = uint32_t(scene_.materials.size() - 1);
  }

  // ---- geometry -------------------------------------------------------------

  struct Source {
    std::vector<float> values;
    size_t stride = 3;
    size_t count = 0;
  };

  Source source(const std::string& url, const std::string& where) const {
    pugi::xml_node node = resolve(url, where);
    if (std::string(node.name()) == "vertices") {  // <vertices> forwards to its POSITION source
      for (pugi::xml_node input : node.children("input")) {
        if (std::string(input.attribute("semantic").value()) == "POSITION") {
          return source(input.attribute("source").value(), where + "/vertices");
        }
      }
      fail(where, "<vertices> without a POSITION input");
    }
    pugi::xml_node array = node.child("float_array");
    if (!array) fail(where, "source \"" + std::string(node.attribute("id").value()) + "\" has no float_array");
    Source s;
    s.values = numbers(array, where + "/float_array");
    pugi::xml_node accessor = node.child("technique_common").child("accessor");
    s.stride = accessor ? accessor.attribute("stride").as_uint(1) : 3;
    if (s.stride < 3) fail(where, "accessor stride must be at least 3");
    s.count = s.values.size() / s.stride;
    return s;
  }

  void readMesh(pugi::xml_node mesh, const glm::mat4& worldFromObject, const std::map<std::string, std::string>& bindings,
                const std::string& where) {
    for (pugi::xml_node primitives : mesh.children()) {
      const std::string kind = primitives.name();
      if (kind != "polylist" && kind != "triangles") continue;
      const std::string here = where + "/" + kind;
      // Inputs: VERTEX (positions) and optionally NORMAL, each at an offset.
      Source positions, normals;
      long positionOffset = -1, normalOffset = -1, stride = 0;
      for (pugi::xml_node input : primitives.children("input")) {
        const std::string semantic = input.attribute("semantic").value();
        const long offset = input.attribute("offset").as_int(0);
        stride = std::max(stride, offset + 1);
        if (semantic == "VERTEX") positions = source(input.attribute("source").value(), here), positionOffset = offset;
        if (semantic == "NORMAL") normals = source(input.attribute("source").value(), here), normalOffset = offset;
      }
      if (positionOffset < 0) fail(here, "no VERTEX input");
      const std::vector<long> p = indices(primitives.child("p"), here + "/p");
      std::vector<long> counts;
      const long polygons = primitives.attribute("count").as_int(0);
      if (kind == "polylist") {
        counts = indices(primitives.child("vcount"), here + "/vcount");
      } else {
        counts.assign(size_t(polygons), 3);
      }
      long corners = 0;
      for (long c : counts) corners += c;
      if (long(counts.size()) != polygons || corners * stride != long(p.size())) {
        fail(here, "count, vcount and <p> disagree (" + std::to_string(p.size()) + " indices for " +
                       std::to_string(corners) + " corners of " + std::to_string(stride) + ")");
      }

      TriangleMesh out;
      out.name = where;
      std::map<std::pair<long, long>, uint32_t> vertexOf;
      auto vertex = [&](long corner) -> uint32_t {
        const long pi = p[size_t(corner * stride + positionOffset)];
        const long ni = normalOffset >= 0 ? p[size_t(corner * stride + normalOffset)] : -1;
        if (size_t(pi) >= positions.count) fail(here + "/p", "position index " + std::to_string(pi) + " out of range");
        if (ni >= 0 && size_t(ni) >= normals.count) fail(here + "/p", "normal index " + std::to_string(ni) + " out of range");
        auto [it, inserted] = vertexOf.try_emplace({pi, ni}, uint32_t(out.positions.size()));
        if (inserted) {
          const float* v = &positions.values[size_t(pi) * positions.stride];
          out.positions.emplace_back(v[0], v[1], v[2]);
          if (ni >= 0) {
            const float* n = &normals.values[size_t(ni) * normals.stride];
            Vec3 normal(n[0], n[1], n[2]);
            if (!(glm::length(normal) > 0.0f)) fail(here, "zero normal");
            out.normals.push_back(glm::normalize(normal));
          }
        }
        return it->second;
      };
      long corner = 0;
      for (long count : counts) {
        for (long k = 1; k + 1 < count; ++k) {  // fan
          out.triangles.emplace_back(vertex(corner), vertex(corner + k), vertex(corner + k + 1));
        }
        corner += count;
      }
      if (out.triangles.empty()) continue;
      const std::string symbol = primitives.attribute("material").value();
      auto bound = bindings.find(symbol);
      if (bound == bindings.end()) fail(here, "material symbol \"" + symbol + "\" is not bound by the node");
      out.material = material(bound->second, here);
      transformMesh(out, worldFromObject);
      scene_.meshes.push_back(std::move(out));
    }
  }

  void readGeometry(pugi::xml_node instance, const glm::mat4& worldFromObject) {
    pugi::xml_node geometry = resolve(instance.attribute("url").value(), "instance_geometry");
    const std::string where = std::string("geometry \"") + geometry.attribute("id").value() + "\"";
    std::map<std::string, std::string> bindings;  // symbol -> material url
    for (pugi::xml_node m : instance.child("bind_material").child("technique_common").children("instance_material")) {
      bindings[m.attribute("symbol").value()] = m.attribute("target").value();
    }
    if (pugi::xml_node mesh = geometry.child("mesh")) {
      readMesh(mesh, worldFromObject, bindings, where);
      return;
    }
    pugi::xml_node sphere = courseTechnique(geometry).child("sphere");
    if (!sphere) fail(where, "neither a <mesh> nor a course <sphere>");
    if (bindings.empty()) fail(where, "the sphere has no bound material");
    const float radius = numbers(sphere.child("radius"), where + "/sphere/radius", 1)[0];
    const float scale = glm::length(Vec3(worldFromObject[0]));
    if (!(radius > 0.0f) || !(scale > 0.0f)) fail(where + "/sphere/radius", "must be positive");
    scene_.spheres.push_back(Sphere{Point3(worldFromObject * glm::vec4(0, 0, 0, 1)), radius * scale,
                                    material(bindings.begin()->second, where)});
  }

  // ---- nodes, lights, camera -------------------------------------------------------

  glm::mat4 localTransform(pugi::xml_node node, const std::string& where) const {
    glm::mat4 m(1.0f);
    for (pugi::xml_node t : node.children()) {
      const std::string kind = t.name();
      if (kind == "matrix") {
        std::vector<float> v = numbers(t, where + "/matrix", 16);
        glm::mat4 local;
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c) local[c][r] = v[size_t(r * 4 + c)];  // COLLADA is row-major
        m = m * local;
      } else if (kind == "translate") {
        std::vector<float> v = numbers(t, where + "/translate", 3);
        m = glm::translate(m, Vec3(v[0], v[1], v[2]));
      } else if (kind == "rotate") {
        std::vector<float> v = numbers(t, where + "/rotate", 4);
        if (glm::length(Vec3(v[0], v[1], v[2])) > 0.0f) m = glm::rotate(m, glm::radians(v[3]), Vec3(v[0], v[1], v[2]));
      } else if (kind == "scale") {
        std::vector<float> v = numbers(t, where + "/scale", 3);
        m = glm::scale(m, Vec3(v[0], v[1], v[2]));
      }
    }
    return m;
  }

  void readNode(pugi::xml_node node, const glm::mat4& parent) {
    const std::string where = std::string("node \"") + node.attribute("id").value() + "\"";
    const glm::mat4 worldFromObject = parent * localTransform(node, where);
    for (pugi::xml_node instance : node.children("instance_geometry")) readGeometry(instance, worldFromObject);
    for (pugi::xml_node instance : node.children("instance_light")) {
      lights_.push_back({resolve(instance.attribute("url").value(), where + "/instance_light"), worldFromObject});
    }
    for (pugi::xml_node instance : node.children("instance_camera")) {
      camera_ = resolve(instance.attribute("url").value(), where + "/instance_camera");
      cameraFromWorld_ = worldFromObject;
    }
    for (pugi::xml_node child : node.children("node")) readNode(child, worldFromObject);
  }

  // The course's files describe the ceiling light twice: as an emissive mesh
  // (what the camera sees) and as an <area> light (what the course's renderer
  // samples). PathLab's area lights are emissive surfaces, so an <area> light
  // becomes a quad only when the scene has no emissive geometry of its own.
  void placeLights() {
    bool emissiveGeometry = false;
    for (const TriangleMesh& m : scene_.meshes) emissiveGeometry |= scene_.materials[m.material].isEmissive();
    for (const Sphere& s : scene_.spheres) emissiveGeometry |= scene_.materials[s.material].isEmissive();
    for (const auto& [light, worldFromLight] : lights_) {
      const std::string where = std::string("light \"") + light.attribute("id").value() + "\"";
      if (pugi::xml_node area = courseTechnique(light).child("area")) {
        if (emissiveGeometry) continue;
        Material emitter;
        emitter.name = where;
        emitter.albedo = Color(0.0f);
        emitter.emission = color(area.child("color"), where + "/area/color");
        scene_.materials.push_back(emitter);
        // A unit square in the light's xy plane, emitting along its -z.
        const Point3 center(worldFromLight * glm::vec4(0, 0, 0, 1));
        Vec3 u(worldFromLight * glm::vec4(1, 0, 0, 0)), v(worldFromLight * glm::vec4(0, 1, 0, 0));
        const Vec3 down(worldFromLight * glm::vec4(0, 0, -1, 0));
        if (glm::dot(glm::cross(u, v), down) < 0.0f) std::swap(u, v);
        TriangleMesh quad;
        quad.name = where;
        quad.positions = {center - 0.5f * u - 0.5f * v, center + 0.5f * u - 0.5f * v, center + 0.5f * u + 0.5f * v,
                          center - 0.5f * u + 0.5f * v};
        quad.triangles = {{0, 1, 2}, {0, 2, 3}};
        quad.material = uint32_t(scene_.materials.size() - 1);
        scene_.meshes.push_back(quad);
        continue;
      }
      pugi::xml_node common = light.child("technique_common");
      if (pugi::xml_node point = common.child("point")) {
        scene_.pointLights.push_back(
            PointLight{Point3(worldFromLight * glm::vec4(0, 0, 0, 1)), color(point.child("color"), where + "/point/color")});
        continue;
      }
      fail(where, "only point lights and the course's <area> lights are supported");
    }
  }

  // The file's camera direction, up vector and field of view; like the
  // course's viewer, it is placed along that direction at the distance where
  // the scene's bounds just fill the view.
  void placeCamera() {
    Camera& camera = scene_.camera;
    float aspect = 4.0f / 3.0f;
    Vec3 forward(0, 0, -1), up(0, 1, 0);
    if (camera_) {
      pugi::xml_node perspective = camera_.child("optics").child("technique_common").child("perspective");
      if (pugi::xml_node a = perspective.child("aspect_ratio")) aspect = numbers(a, "camera/aspect_ratio", 1)[0];
      if (!(aspect > 0.0f)) fail("camera/aspect_ratio", "must be positive");
      float vfov = 40.0f;
      if (pugi::xml_node y = perspective.child("yfov")) {
        vfov = numbers(y, "camera/yfov", 1)[0];
      } else if (pugi::xml_node x = perspective.child("xfov")) {
        const float xfov = numbers(x, "camera/xfov", 1)[0];
        vfov = glm::degrees(2.0f * std::atan(std::tan(glm::radians(xfov) * 0.5f) / aspect));
      }
      if (!(vfov > 0.0f && vfov < 180.0f)) fail("camera", "field of view out of range");
      camera.vfovDegrees = vfov;
      forward = glm::normalize(Vec3(cameraFromWorld_ * glm::vec4(0, 0, -1, 0)));
      up = glm::normalize(Vec3(cameraFromWorld_ * glm::vec4(0, 1, 0, 0)));
    }
    Aabb bounds;
    for (const TriangleMesh& m : scene_.meshes)
      for (const Point3& p : m.positions) bounds.grow(p);
    for (const Sphere& s : scene_.spheres) bounds.grow(s.center - Vec3(s.radius)), bounds.grow(s.center + Vec3(s.radius));
    const Point3 center = bounds.centroid();
    const Vec3 right = glm::normalize(glm::cross(forward, up));
    const Vec3 trueUp = glm::cross(right, forward);
    const float tanHalf = std::tan(glm::radians(camera.vfovDegrees) * 0.5f);
    float distance = 0.0f;
    for (int i = 0; i < 8; ++i) {
      const Point3 corner((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                          (i & 4) ? bounds.max.z : bounds.min.z);
      const Vec3 o = corner - center;
      const float depth = glm::dot(o, forward);
      distance = std::max({distance, std::abs(glm::dot(o, right)) / (tanHalf * aspect) - depth,
                           std::abs(glm::dot(o, trueUp)) / tanHalf - depth});
    }
    camera.lookAt = center;
    camera.position = center - forward * distance;
    camera.up = trueUp;
    scene_.render.height = std::max(1, int(std::lround(float(scene_.render.width) / aspect)));
  }

  std::string file_;
  pugi::xml_document document_;
  pugi::xml_node root_;
  std::map<std::string, pugi::xml_node> ids_;
  std::map<std::string, uint32_t> materials_;
  std::vector<std::pair<pugi::xml_node, glm::mat4>> lights_;
  pugi::xml_node camera_;
  glm::mat4 cameraFromWorld_{1.0f};
  Scene scene_;
};

}  // namespace

Scene loadColladaScene(const std::string& path) { return ColladaReader(path).read(); }

}  // namespace pathlab
