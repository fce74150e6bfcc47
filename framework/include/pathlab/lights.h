// Lights as behaviour: point lights, and area lights built from every
// emissive mesh or sphere (one light per emitting object; nothing for
// objects that do not emit). Emission is one-sided: a surface emits Le
// towards the side its geometric normal points to.
#pragma once

#include <vector>

#include "pathlab/distribution.h"
#include "pathlab/hit.h"
#include "pathlab/scene.h"

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
  Distribution1D triangles_;  // by area
};

struct Lights {
  std::vector<PointLight> points;
  std::vector<AreaLight> areas;

  static Lights fromScene(const Scene& scene);
  bool empty() const { return points.empty() && areas.empty(); }
};

// Le leaving the surface at `hit` towards direction wo (unit, pointing away
// from the surface): the material's emission on the front side, else 0.
Color emittedRadiance(const Scene& scene, const Hit& hit, const Vec3& wo);

}  // namespace pathlab
