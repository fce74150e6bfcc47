// Lights as behaviour: point lights, and area lights built from every
// emissive mesh or sphere (one light per emitting object; nothing for
// objects that do not emit). Emission is one-sided: a surface emits Le
// towards the side its geometric normal points to.
#pragma once

#include <optional>
#include <vector>

#include "core/environment_distribution.h"
#include "core/hit.h"
#include "core/scene.h"
#include "core/task_functions.h"
#include "util/distribution.h"

namespace pathlab {

// A point chosen on a light's surface.
struct AreaSample {
  Point3 point{0.0f};
  Vec3 normal{0.0f, 0.0f, 1.0f};  // unit geometric normal: the side that emits
  Color radiance{0.0f};           // Le towards that side
  float pdfArea = 0.0f;           // density per unit area, 1 / total area
};

class AreaLight {
 public:
  static AreaLight fromMesh(const Scene& scene, uint32_t mesh);
  static AreaLight fromSphere(const Scene& scene, uint32_t sphere);

  // A point uniformly distributed over the light's area.
  AreaSample sample(Vec2 u) const;
  float area() const { return area_; }
  Color radiance() const { return radiance_; }

 private:
  const Scene* scene_ = nullptr;
  uint32_t object_ = 0;
  bool isSphere_ = false;
  Color radiance_{0.0f};
  float area_ = 0.0f;
  // Each triangle's corners and unit normal, copied at load so a sample reads
  // one record instead of the mesh's index and position arrays.
  struct Triangle {
    Point3 p0, p1, p2;
    Vec3 normal;
  };
  Distribution1D byArea_;  // which triangle
  std::vector<Triangle> triangles_;
};

enum class EnvironmentSampling { Importance, Uniform };

// A direction towards the environment, with the radiance arriving from it.
struct EnvironmentLightSample {
  Vec3 direction{0.0f};    // unit, towards the sky
  Color radiance{0.0f};
  float pdfSolidAngle = 0.0f;
};

// The environment as a light at infinity: a constant colour (sampled
// uniformly over the sphere) or an equirectangular map (task 7: lookup, and
// importance sampling by luminance * sin(theta), or uniform sampling; its
// functions come in an EnvironmentMapFunctions table, task_functions.h).
//
// Lighting (next-event estimation) uses the map's pixels as they are —
// piecewise constant, exactly the function the importance sampler's pdf
// follows, so a bright sun gives no fireflies. What a camera or a mirror sees
// of the sky is the bilinear lookup: the same pixels, filtered for display.
class EnvironmentLight {
 public:
  EnvironmentLight(const Environment& environment, EnvironmentSampling sampling, const EnvironmentMapFunctions& map);

  // Radiance seen along the unit direction w (bilinear for maps).
  Color radiance(const Vec3& w) const;
  // The map's pixel value along w (a constant sky: its colour), what lighting integrates.
  Color pixelRadiance(const Vec3& w) const;
  std::optional<EnvironmentLightSample> sample(Vec2 u) const;
  float pdf(const Vec3& w) const;  // the density sample() draws w with, per unit solid angle
  bool hasMap() const { return environment_->image.width > 0; }

 private:
  const Environment* environment_;
  EnvironmentSampling sampling_;
  EnvironmentMapFunctions map_;
  EnvironmentDistribution distribution_;  // built only for importance-sampled maps
};

struct Lights {
  std::vector<PointLight> points;
  std::vector<AreaLight> areas;
  std::optional<EnvironmentLight> environment;  // only when the scene has one

  // `map` is task 7's functions (kLinkedTasks.environment, task_wiring.h).
  static Lights fromScene(const Scene& scene, const EnvironmentMapFunctions& map,
                          EnvironmentSampling sampling = EnvironmentSampling::Importance);

  // The area light whose surface `hit` lies on, or null.
  const AreaLight* areaLightAt(const Scene& scene, const Hit& hit) const;
  // Solid-angle pdf with which that light's area sampling picks the
  // direction from `from` to `hit` (0 if the light faces away).
  static float areaPdfSolidAngle(const AreaLight& light, const Point3& from, const Hit& hit);

  std::vector<int> lightOfMesh, lightOfSphere;  // index into areas, or -1
  bool empty() const { return points.empty() && areas.empty() && !environment; }
};

// Le leaving the surface at `hit` towards direction wo (unit, pointing away
// from the surface): the material's emission on the front side, else 0.
Color emittedRadiance(const Scene& scene, const Hit& hit, const Vec3& wo);

}  // namespace pathlab
