// Scene data: everything a render needs, as plain data owned by one struct.
// Geometry is flattened at load time (transforms applied, quads split), and
// every triangle and sphere is one entry of `primitives`, so accelerators and
// the debugger refer to any surface by a single index.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/hit.h"
#include "core/microfacet_material.h"
#include "util/image.h"
#include "util/math.h"

namespace pathlab {

// Interface: no surface at all, only where a medium begins (task 12): light
// passes straight through, and the medium changes.
enum class MaterialType { Diffuse, Mirror, Glass, RoughConductor, RoughPlastic, Interface };

// The name a scene file gives each type ("diffuse", ..., "conductor", "plastic").
inline const char* materialTypeName(MaterialType type) {
  switch (type) {
    case MaterialType::Diffuse: return "diffuse";
    case MaterialType::Mirror: return "mirror";
    case MaterialType::Glass: return "glass";
    case MaterialType::RoughConductor: return "conductor";
    case MaterialType::RoughPlastic: return "plastic";
    case MaterialType::Interface: return "interface";
  }
  return "?";
}

// Task 12: a homogeneous participating medium. Light travelling a length
// dt in it is scattered with probability sigmaS dt and absorbed with
// sigmaA dt; extinction sigmaT = sigmaA + sigmaS is the same for every
// colour (so one free-flight distance serves all three), the albedo
// sigmaS / sigmaT is a colour. Scattered light leaves by the Henyey-Greenstein
// phase function of asymmetry g.
struct Medium {
  std::string name;
  float sigmaT = 1.0f;  // extinction per unit length
  Color albedo{1.0f};   // sigmaS / sigmaT, in [0, 1] per colour
  float g = 0.0f;       // in (-1, 1): > 0 mostly onwards, < 0 mostly back

  Color sigmaS() const { return albedo * sigmaT; }
  Color sigmaA() const { return (Color(1.0f) - albedo) * sigmaT; }
};

// An index into Scene::media, or kVacuum.
using MediumIndex = int32_t;
inline constexpr MediumIndex kVacuum = -1;

struct Material {
  std::string name;
  MaterialType type = MaterialType::Diffuse;
  Color albedo{0.8f};          // diffuse reflectance, mirror/glass reflectance tint, a rough
                               // conductor's F0 (Schlick), or a rough plastic's diffuse base
  Color transmittance{1.0f};   // glass only
  float ior = 1.5f;            // glass, and a rough plastic's coat: index of refraction inside / outside
  Color emission{0.0f};        // emitted radiance Le, on any material
  // Rough conductor and rough plastic (task 8).
  float roughness = 0.5f;      // perceptual roughness in [0, 1]: alpha = roughness^2
  bool exactFresnel = false;   // conductor: Fresnel from eta and k instead of Schlick from albedo
  Color eta{0.0f}, k{0.0f};    // conductor: the complex index of refraction eta + i k, per channel
  // Glass and interface (task 12): the medium inside the closed surface they
  // bound (its geometric normals point out); outside is the scene's medium.
  MediumIndex interior = kVacuum;

  bool isEmissive() const { return maxComponent(emission) > 0.0f; }
  // Mirror and glass: one direction per sample (task 6); an interface: straight on.
  bool isDelta() const {
    return type == MaterialType::Mirror || type == MaterialType::Glass || type == MaterialType::Interface;
  }
  // Rough conductor and rough plastic: GGX lobes (task 8).
  bool isRough() const { return type == MaterialType::RoughConductor || type == MaterialType::RoughPlastic; }
  // The parameters task 8's functions take, for a rough conductor or plastic.
  RoughConductor roughConductor() const { return RoughConductor{roughness, albedo, exactFresnel, eta, k}; }
  RoughPlastic roughPlastic() const { return RoughPlastic{roughness, albedo, ior}; }
};

struct TriangleMesh {
  std::string name;
  std::vector<Point3> positions;
  std::vector<Vec3> normals;          // empty, or one unit normal per position
  std::vector<glm::uvec3> triangles;  // counter-clockwise = front face
  uint32_t material = 0;
};

struct Sphere {
  Point3 center{0.0f};
  float radius = 1.0f;
  uint32_t material = 0;
};

struct PointLight {
  Point3 position{0.0f};
  Color intensity{1.0f};  // radiant intensity, W/sr per channel
};

struct Environment {
  Color color{0.0f};        // constant radiance, used when there is no image
  std::string imagePath;    // equirectangular map (task 7), resolved path
  Image image;              // loaded map (empty when imagePath is empty)
  float scale = 1.0f;
};

struct RenderSettings {
  int width = 400;
  int height = 300;
  int samplesPerPixel = 16;
  int lightSamples = 1;  // samples per area light (task 4)
  int maxDepth = 4;      // path length cap (task 5)
  uint64_t seed = 0;
};

// One surface of the scene: triangle `index` of mesh `mesh`, or sphere
// `index` when mesh == kSphere.
struct PrimitiveRef {
  static constexpr uint32_t kSphere = 0xffffffffu;
  uint32_t mesh = kSphere;
  uint32_t index = 0;

  bool isSphere() const { return mesh == kSphere; }
};

struct Scene {
  std::string source;  // file path, or "<default>" for the embedded scene
  Camera camera;
  RenderSettings render;
  std::vector<Material> materials;
  std::vector<TriangleMesh> meshes;
  std::vector<Sphere> spheres;
  std::vector<PointLight> pointLights;
  std::optional<Environment> environment;
  std::vector<PrimitiveRef> primitives;  // all triangles, then all spheres
  // Task 12: the media, and the one that fills the scene around every
  // object (a fog; the camera is in it). Media do not nest: leaving an
  // object's interior is entering the scene's medium.
  std::vector<Medium> media;
  MediumIndex medium = kVacuum;

  bool hasMedia() const { return !media.empty(); }
  // The medium a ray is in after it crosses the surface at `hit` along
  // `direction` (unit): the surface's interior going in (against its
  // geometric normal), the scene's medium going out; `current` where the
  // surface bounds no medium.
  MediumIndex mediumAcross(const Hit& hit, const Vec3& direction, MediumIndex current) const;

  // Rebuilds `primitives` from meshes and spheres; loaders call it once.
  void indexPrimitives();
  uint32_t materialOf(uint32_t primitive) const;
  size_t triangleCount() const;
};

// ---- Limits every loader checks (docs/reliability.md, "Limits") ----------

// Geometry and camera within +-1e12 of the origin: float32 maths squares
// distances (a sphere test forms r^2 and |o - c|^2), so coordinates near
// 1e19 overflow to infinity and a BVH's bounds become NaN. 1e12 leaves the
// squares (1e24), their sums and the tree's surface areas far from float's
// 3.4e38, and still spans a sky dome a million times a scene of 1e6 units.
constexpr float kMaxSceneCoordinate = 1e12f;
constexpr int kMaxImageSide = 16384;
constexpr int64_t kMaxImagePixels = int64_t(1) << 26;  // 67 M pixels, 800 MB of float RGB

// Throws pathlab::Error "WHERE: ..." unless 1 <= side <= kMaxImageSide and
// the image has at most kMaxImagePixels.
void checkResolution(int64_t width, int64_t height, const std::string& where);

// Throws pathlab::Error naming the scene file and the object when a mesh
// vertex, a sphere's extent or the camera lies outside kMaxSceneCoordinate
// (or is not finite), or the camera has no usable direction.
void checkSceneLimits(const Scene& scene);

// Applies a transform to a mesh's positions and normals; a mirroring
// transform also flips the winding, so front faces stay in front.
void transformMesh(TriangleMesh& mesh, const glm::mat4& worldFromObject);

}  // namespace pathlab
