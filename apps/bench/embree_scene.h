// Intel Embree 3 over the same triangles, for the BVH benchmark. Compiled
// only when Debian's libembree-dev was found (PATHLAB_HAVE_EMBREE).
#pragma once

#include <memory>
#include <optional>

#include "core/hit.h"
#include "core/scene.h"
#include "util/ray.h"

namespace pathlab::bench {

class EmbreeScene {
 public:
  // Builds over every triangle of mesh 0; `buildThreads` threads for the build.
  EmbreeScene(const TriangleMesh& mesh, int buildThreads);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  std::optional<PrimitiveHit> intersect(const Ray& ray, Interval range) const;
  bool occluded(const Ray& ray, Interval range) const;
  double buildSeconds() const { return buildSeconds_; }

 private:
  struct Handles;
  std::unique_ptr<Handles> handles_;
  double buildSeconds_ = 0.0;
};

}  // namespace pathlab::bench
