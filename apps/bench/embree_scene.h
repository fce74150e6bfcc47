// Intel Embree 3 over the same triangles (and spheres), for the benchmarks'
// comparisons. Compiled only when Debian's libembree-dev was found
// (PATHLAB_HAVE_EMBREE).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/hit.h"
#include "core/scene.h"
#include "util/ray.h"

namespace pathlab::bench {

class EmbreeScene {
 public:
  // Builds over every triangle of mesh 0; `buildThreads` threads for the build.
  EmbreeScene(const TriangleMesh& mesh, int buildThreads);
  // Builds over the whole scene: every mesh, and the spheres as Embree's
  // sphere points. Hits name the scene's primitive (Scene::primitives).
  EmbreeScene(const Scene& scene, int buildThreads);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  std::optional<PrimitiveHit> intersect(const Ray& ray, Interval range) const;
  bool occluded(const Ray& ray, Interval range) const;
  double buildSeconds() const { return buildSeconds_; }

 private:
  struct Handles;
  void build(const Scene& scene, int buildThreads);
  std::unique_ptr<Handles> handles_;
  std::vector<uint32_t> firstPrimitive_;  // per Embree geometry: its first scene primitive
  uint32_t sphereGeometry_ = ~0u;         // the spheres' geometry, if any
  double buildSeconds_ = 0.0;
};

}  // namespace pathlab::bench
