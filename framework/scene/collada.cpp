// COLLADA 1.4 scenes with the course's extensions (technique profile
// "CMU462", identical in the CS184 "CGL" copies): meshes (polylist and
// triangles), node transforms, analytic spheres, point and area lights,
// emission, diffuse / mirror / glass materials, the camera.
//
// Leniencies, each reported by one "warning:" line per file on stderr:
// node matrices with fewer than 16 numbers (as the course's viewer reads
// them: missing numbers are 0), and the CS184 <microfacet> and <refraction>
// materials, approximated by the closest PathLab material.
#include <pugixml.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "scene/collada_document.h"
#include "scene/scene_io.h"
#include "util/aabb.h"
#include "util/error.h"
#include "util/input_file.h"

namespace pathlab {
namespace {

using collada::formatted;

std::string printable(std::string_view text) { return printableLine(text); }

void warn(const std::string& file, const std::string& what) {
  std::fputs(("warning: " + printable(file + ": " + what) + "\n").c_str(), stderr);
}

// "1 more node", "2 more nodes"
std::string count(size_t n, const std::string& noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }

// A 3x3 part that maps no volume to zero volume, relative to its columns'
// lengths (so uniformly scaled or tiny transforms still count as usable).
bool usableLinearPart(const glm::mat4& m) {
  const glm::mat3 linear(m);
  const float lengths = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
  const float det = glm::determinant(linear);
  return std::isfinite(lengths) && std::isfinite(det) && lengths > 0.0f && std::abs(det) > 1e-6f * lengths;
}

class ColladaReader {
 public:
  explicit ColladaReader(const std::string& path) : doc_(path) {}

  Scene read() {
    scene_.source = doc_.file();
    pugi::xml_node visualScene = doc_.resolve(doc_.root().child("scene").child("instance_visual_scene").attribute("url").value(),
                                         "scene/instance_visual_scene");
    for (pugi::xml_node node : visualScene.children("node")) readNode(node, glm::mat4(1.0f), {});
    placeLights();
    if (scene_.meshes.empty() && scene_.spheres.empty()) fail("library_visual_scenes", "the scene has no geometry");
    scene_.indexPrimitives();
    placeCamera();
    checkSceneLimits(scene_);
    reportRepairs();
    return std::move(scene_);
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& what) const { doc_.fail(where, what); }

  // ---- materials ----------------------------------------------------------

  uint32_t material(const std::string& url, const std::string& where) {
    auto cached = materials_.find(url);
    if (cached != materials_.end()) return cached->second;
    scene_.materials.push_back(collada::readMaterial(doc_, doc_.resolve(url, where), [&](const std::string& effect,
                                                                                         const std::string& what) {
      noteApproximation(effect, what);
    }));
    return materials_[url] = uint32_t(scene_.materials.size() - 1);
  }

  void noteApproximation(const std::string& effectWhere, const std::string& what) {
    if (!approximatedEffects_.insert(effectWhere).second) return;
    if (approximation_.empty()) approximation_ = effectWhere + " " + what;
  }

  // ---- geometry -------------------------------------------------------------


  // `flattened`: the transform is singular (a short <matrix>, see
  // localTransform). Returns whether anything was left out for that.
  bool readMesh(pugi::xml_node mesh, const glm::mat4& worldFromObject, const std::map<std::string, std::string>& bindings,
                const std::string& where, bool flattened) {
    bool leftOut = false;
    for (pugi::xml_node primitives : mesh.children()) {
      const std::string kind = primitives.name();
      if (kind != "polylist" && kind != "triangles") continue;
      const std::string here = where + "/" + kind;
      // Inputs: VERTEX (positions) and optionally NORMAL, each at an offset.
      collada::FloatSource positions, normals;
      long positionOffset = -1, normalOffset = -1, stride = 0;
      for (pugi::xml_node input : primitives.children("input")) {
        const std::string semantic = input.attribute("semantic").value();
        const long offset = doc_.integerAttribute(input, "offset", 0, 63, here + "/input");
        stride = std::max(stride, offset + 1);
        if (semantic == "VERTEX") positions = doc_.source(input.attribute("source").value(), here), positionOffset = offset;
        if (semantic == "NORMAL") normals = doc_.source(input.attribute("source").value(), here), normalOffset = offset;
      }
      if (positionOffset < 0) fail(here, "no VERTEX input");
      const std::vector<long> p = doc_.indices(primitives.child("p"), here + "/p");
      std::vector<long> counts;
      // Sizes checked against the indices actually present before anything
      // is allocated from them (a count of 300 million cost 2.4 GB).
      const long polygons = doc_.integerAttribute(primitives, "count", 0, long(p.size()), here);
      if (kind == "polylist") {
        counts = doc_.indices(primitives.child("vcount"), here + "/vcount");
      } else {
        counts.assign(size_t(polygons), 3);
      }
      long corners = 0;
      for (long c : counts) {
        if (c > long(p.size()) || corners > long(p.size())) break;  // disagrees below, without overflow
        corners += c;
      }
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
      if (flattened) {
        // Flattened, as the course's viewer would draw it: no normal matrix
        // exists (so no vertex normals), and triangles that lost their area
        // (all but a millionth of what the transform's scale would give
        // them, which is the exporter's rounding noise) cannot be seen.
        out.normals.clear();
        const std::vector<Point3> local = out.positions;
        transformMesh(out, worldFromObject);
        const float scale = std::max({glm::length(Vec3(worldFromObject[0])), glm::length(Vec3(worldFromObject[1])),
                                      glm::length(Vec3(worldFromObject[2]))});
        auto area = [](const std::vector<Point3>& points, const glm::uvec3& t) {
          return glm::length(glm::cross(points[t.y] - points[t.x], points[t.z] - points[t.x]));
        };
        const size_t before = out.triangles.size();
        std::erase_if(out.triangles, [&](const glm::uvec3& t) {
          return !(area(out.positions, t) > 1e-6f * scale * scale * area(local, t));
        });
        leftOut |= out.triangles.size() < before;
        if (out.triangles.empty()) continue;
      } else {
        transformMesh(out, worldFromObject);
      }
      scene_.meshes.push_back(std::move(out));
    }
    return leftOut;
  }

  // Returns whether a flattened transform left something out (readMesh).
  bool readGeometry(pugi::xml_node instance, const glm::mat4& worldFromObject, bool flattened) {
    pugi::xml_node geometry = doc_.resolve(instance.attribute("url").value(), "instance_geometry");
    const std::string where = std::string("geometry \"") + geometry.attribute("id").value() + "\"";
    std::map<std::string, std::string> bindings;  // symbol -> material url
    for (pugi::xml_node m : instance.child("bind_material").child("technique_common").children("instance_material")) {
      bindings[m.attribute("symbol").value()] = m.attribute("target").value();
    }
    if (pugi::xml_node mesh = geometry.child("mesh")) {
      return readMesh(mesh, worldFromObject, bindings, where, flattened);
    }
    pugi::xml_node sphere = collada::Document::courseTechnique(geometry).child("sphere");
    if (!sphere) fail(where, "neither a <mesh> nor a course <sphere>");
    if (bindings.empty()) fail(where, "the sphere has no bound material");
    const float radius = doc_.numbers(sphere.child("radius"), where + "/sphere/radius", 1)[0];
    const float scale = glm::length(Vec3(worldFromObject[0]));
    // A sphere has no flattened form: it stays a sphere at the node's origin,
    // scaled by the x axis as always, unless that axis is gone too.
    if (flattened && !(scale > 0.0f)) return true;
    if (!(radius > 0.0f) || !(scale > 0.0f)) fail(where + "/sphere/radius", "must be positive");
    scene_.spheres.push_back(Sphere{Point3(worldFromObject * glm::vec4(0, 0, 0, 1)), radius * scale,
                                    material(bindings.begin()->second, where)});
    return false;
  }

  // ---- nodes, lights, camera -------------------------------------------------------

  // `flattens` is set when a short <matrix> (below) makes the node's 3x3
  // part singular.
  glm::mat4 localTransform(pugi::xml_node node, const std::string& where, bool& shortMatrix, bool& flattens) {
    glm::mat4 m(1.0f);
    for (pugi::xml_node t : node.children()) {
      const std::string kind = t.name();
      if (kind == "matrix") {
        std::vector<float> v = doc_.numbers(t, where + "/matrix");
        if (v.size() > 16) fail(where + "/matrix", "expected 16 numbers, got " + std::to_string(v.size()));
        const size_t count = v.size();
        // Fewer than 16 (a course Cornell box's camera has 15): the course's
        // viewer reads the matrix with a stream, which leaves the missing
        // numbers at 0. So do we, with a warning. PathLab's node transforms
        // are affine, so the bottom row (where a 15th or 16th number is
        // missing; Blender always writes 0 0 0 1) is not used: it is kept at
        // 0 0 0 1 rather than 0 0 0 0, which would also drop a parent's
        // translation from nested nodes. So 12 to 15 numbers change nothing.
        // Fewer zero part of the 3x3 and translation; if that makes the 3x3
        // singular, the node (and its children) are flattened as the viewer
        // would flatten them: meshes lose the triangles that lose their
        // area (readMesh), spheres stay spheres, and a camera there is
        // framed from the scene's bounds (placeCamera).
        v.resize(16, 0.0f);
        glm::mat4 local;
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c) local[c][r] = v[size_t(r * 4 + c)];  // COLLADA is row-major
        if (count < 16) {
          local = glm::mat4(glm::vec4(local[0].x, local[0].y, local[0].z, 0.0f),
                            glm::vec4(local[1].x, local[1].y, local[1].z, 0.0f),
                            glm::vec4(local[2].x, local[2].y, local[2].z, 0.0f),
                            glm::vec4(local[3].x, local[3].y, local[3].z, 1.0f));
          shortMatrix = true;
          flattens = flattens || !usableLinearPart(local);
          if (shortMatrices_++ == 0) shortMatrix_ = {where, count};
        }
        m = m * local;
      } else if (kind == "translate") {
        std::vector<float> v = doc_.numbers(t, where + "/translate", 3);
        m = glm::translate(m, Vec3(v[0], v[1], v[2]));
      } else if (kind == "rotate") {
        std::vector<float> v = doc_.numbers(t, where + "/rotate", 4);
        if (glm::length(Vec3(v[0], v[1], v[2])) > 0.0f) m = glm::rotate(m, glm::radians(v[3]), Vec3(v[0], v[1], v[2]));
      } else if (kind == "scale") {
        std::vector<float> v = doc_.numbers(t, where + "/scale", 3);
        m = glm::scale(m, Vec3(v[0], v[1], v[2]));
      }
    }
    return m;
  }

  // What the node's ancestors did to it.
  struct Inherited {
    bool shortMatrix = false;  // some ancestor's <matrix> was short
    bool flattened = false;    // ... and made the transform singular
  };

  void readNode(pugi::xml_node node, const glm::mat4& parent, Inherited inherited) {
    const std::string where = std::string("node \"") + node.attribute("id").value() + "\"";
    bool shortMatrix = false, flattens = false;
    const glm::mat4 worldFromObject = parent * localTransform(node, where, shortMatrix, flattens);
    inherited.shortMatrix |= shortMatrix;
    inherited.flattened |= flattens;
    bool leftOut = false;
    for (pugi::xml_node instance : node.children("instance_geometry")) {
      leftOut |= readGeometry(instance, worldFromObject, inherited.flattened);
    }
    if (leftOut && flattenedNodes_++ == 0) flattenedNode_ = where;
    for (pugi::xml_node instance : node.children("instance_light")) {
      lights_.push_back(
          {doc_.resolve(instance.attribute("url").value(), where + "/instance_light"), worldFromObject, inherited.flattened});
    }
    for (pugi::xml_node instance : node.children("instance_camera")) {
      camera_ = doc_.resolve(instance.attribute("url").value(), where + "/instance_camera");
      cameraFromWorld_ = worldFromObject;
      cameraNode_ = where;
      cameraShortMatrix_ = inherited.shortMatrix;
    }
    for (pugi::xml_node child : node.children("node")) readNode(child, worldFromObject, inherited);
  }

  // The course's files describe the ceiling light twice: as an emissive mesh
  // (what the camera sees) and as an <area> light (what the course's renderer
  // samples). PathLab's area lights are emissive surfaces, so an <area> light
  // becomes a quad only when the scene has no emissive geometry of its own.
  void placeLights() {
    bool emissiveGeometry = false;
    for (const TriangleMesh& m : scene_.meshes) emissiveGeometry |= scene_.materials[m.material].isEmissive();
    for (const Sphere& s : scene_.spheres) emissiveGeometry |= scene_.materials[s.material].isEmissive();
    for (const auto& [light, worldFromLight, flattened] : lights_) {
      const std::string where = std::string("light \"") + light.attribute("id").value() + "\"";
      if (pugi::xml_node area = collada::Document::courseTechnique(light).child("area")) {
        if (emissiveGeometry || flattened) continue;  // a flattened quad has no area
        Material emitter;
        emitter.name = where;
        emitter.albedo = Color(0.0f);
        emitter.emission = doc_.color(area.child("color"), where + "/area/color");
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
            PointLight{Point3(worldFromLight * glm::vec4(0, 0, 0, 1)), doc_.color(point.child("color"), where + "/point/color")});
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
      if (pugi::xml_node a = perspective.child("aspect_ratio")) aspect = doc_.numbers(a, "camera/aspect_ratio", 1)[0];
      if (!(aspect > 0.0f)) fail("camera/aspect_ratio", "must be positive");
      float vfov = 40.0f;
      if (pugi::xml_node y = perspective.child("yfov")) {
        vfov = doc_.numbers(y, "camera/yfov", 1)[0];
      } else if (pugi::xml_node x = perspective.child("xfov")) {
        const float xfov = doc_.numbers(x, "camera/xfov", 1)[0];
        vfov = glm::degrees(2.0f * std::atan(std::tan(glm::radians(xfov) * 0.5f) / aspect));
      }
      if (!(vfov > 0.0f && vfov < 180.0f)) fail("camera", "field of view out of range");
      camera.vfovDegrees = vfov;
    }
    Aabb bounds;
    for (const TriangleMesh& m : scene_.meshes)
      for (const Point3& p : m.positions) bounds.grow(p);
    for (const Sphere& s : scene_.spheres) bounds.grow(s.center - Vec3(s.radius)), bounds.grow(s.center + Vec3(s.radius));
    const Point3 center = bounds.centroid();
    if (camera_) {
      const Vec3 cameraForward(cameraFromWorld_ * glm::vec4(0, 0, -1, 0)), cameraUp(cameraFromWorld_ * glm::vec4(0, 1, 0, 0));
      if (usableLinearPart(cameraFromWorld_) && glm::length(glm::cross(cameraForward, cameraUp)) > 0.0f) {
        forward = glm::normalize(cameraForward);
        up = glm::normalize(cameraUp);
      } else {
        frameFromBounds(bounds, forward, up);
      }
    }
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
    camera.focalDistance = std::max(distance, 1e-3f);  // COLLADA has no lens; --aperture opens one, focused at lookAt
    const double height = std::max(1.0, std::round(double(scene_.render.width) / double(aspect)));
    if (height > double(kMaxImageSide)) {
      char asked[96];
      std::snprintf(asked, sizeof asked, "%g asks for an image %d pixels wide and %.0f tall", double(aspect),
                    scene_.render.width, height);
      fail("camera/aspect_ratio", std::string(asked) + " (at most " + std::to_string(kMaxImageSide) + " a side)");
    }
    scene_.render.height = int(height);
    checkResolution(scene_.render.width, scene_.render.height, printable(doc_.file() + ": camera/aspect_ratio"));
  }

  // A camera whose transform gives no direction (singular or not finite):
  // like the course's viewer, frame it from the scene's bounds. It looks from
  // where the file puts it (the translation, if that is finite and outside
  // the bounds: a position zeroed by a short matrix is often inside) at the
  // bounds' centre, or else along the file's horizontal view axis (-z for
  // y-up files, +y, Blender's front view, for z-up ones), with the file's
  // <up_axis> up.
  void frameFromBounds(const Aabb& bounds, Vec3& forward, Vec3& up) {
    const std::string axis = doc_.root().child("asset").child_value("up_axis");
    up = axis == "Z_UP" ? Vec3(0, 0, 1) : axis == "X_UP" ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    forward = axis == "Z_UP" ? Vec3(0, 1, 0) : Vec3(0, 0, -1);
    const Point3 position(cameraFromWorld_[3]);
    const bool outside = glm::any(glm::lessThan(position, bounds.min)) || glm::any(glm::greaterThan(position, bounds.max));
    if (outside && std::isfinite(position.x) && std::isfinite(position.y) && std::isfinite(position.z)) {
      forward = glm::normalize(bounds.centroid() - position);
    }
    if (!(glm::length(glm::cross(forward, up)) > 1e-3f)) up = std::abs(forward.z) < 0.9f ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
    cameraFraming_ = "so it is framed from the scene's bounds: it looks along " + formatted(forward) +
                     " at their centre, from the distance where they fill the view";
  }

  // One warning line per kind of repair, after a successful load.
  void reportRepairs() const {
    bool cameraReported = cameraFraming_.empty();
    if (shortMatrices_) {
      std::string line = shortMatrix_.node + "/matrix has " + std::to_string(shortMatrix_.count) +
                         " numbers, not 16; the missing ones are taken as 0";
      if (shortMatrices_ > 1) line += " (as are those of " + count(shortMatrices_ - 1, "more node") + ")";
      if (!cameraReported && cameraShortMatrix_) {
        line += ", which leaves the camera" + (cameraNode_ == shortMatrix_.node ? "" : " of " + cameraNode_) +
                " no usable direction, " + cameraFraming_;
        cameraReported = true;
      }
      if (flattenedNodes_) {
        line += "; that flattens the geometry of " + flattenedNode_;
        if (flattenedNodes_ > 1) line += " (and of " + count(flattenedNodes_ - 1, "more node") + ")";
        line += ", and what has no area left is left out";
      }
      warn(doc_.file(), line);
    }
    if (!cameraReported) warn(doc_.file(), cameraNode_ + ": the camera's transform gives no usable direction, " + cameraFraming_);
    if (!approximation_.empty()) {
      std::string line = approximation_;
      if (approximatedEffects_.size() > 1) {
        const size_t n = approximatedEffects_.size() - 1;
        line += " (" + count(n, "more effect") + (n == 1 ? " is" : " are") + " approximated likewise)";
      }
      warn(doc_.file(), line);
    }
  }

  collada::Document doc_;
  std::map<std::string, uint32_t> materials_;
  struct LightInstance {
    pugi::xml_node light;
    glm::mat4 worldFromLight;
    bool flattened;
  };
  std::vector<LightInstance> lights_;
  pugi::xml_node camera_;
  glm::mat4 cameraFromWorld_{1.0f};
  std::string cameraNode_;
  bool cameraShortMatrix_ = false;
  Scene scene_;

  // Repairs, reported once per file by reportRepairs().
  struct ShortMatrix {
    std::string node;
    size_t count = 0;
  } shortMatrix_;            // the first short <matrix>
  size_t shortMatrices_ = 0;
  std::string flattenedNode_;  // the first node a short matrix flattened something out of
  size_t flattenedNodes_ = 0;
  std::string cameraFraming_;  // how the camera was framed from the bounds, if it was
  std::string approximation_;  // the first approximated material
  std::set<std::string> approximatedEffects_;
};

}  // namespace

Scene loadColladaScene(const std::string& path) { return ColladaReader(path).read(); }

}  // namespace pathlab
