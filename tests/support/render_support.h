// A scene with its BVH and lights, ready for estimator tests: build the
// Scene, then `Rig rig(std::move(scene));` and call rig.context().
#pragma once

#include <memory>

#include "core/lights.h"
#include "core/trace.h"
#include "render/accelerator.h"
#include "render/task_wiring.h"

namespace pathlab::test {

class Rig {
 public:
  explicit Rig(Scene scene) : scene_(std::make_unique<Scene>(std::move(scene))) {
    scene_->indexPrimitives();
    accelerator_ = std::make_unique<Accelerator>(*scene_);
    lights_ = Lights::fromScene(*scene_, kLinkedTasks.environment);
  }

  TraceContext context(int maxDepth = 4, int lightSamples = 1) const {
    TraceContext c(*scene_, *accelerator_, lights_, kLinkedTasks.lobes);
    c.settings.maxDepth = maxDepth;
    c.settings.lightSamples = lightSamples;
    return c;
  }
  const Scene& scene() const { return *scene_; }
  const Lights& lights() const { return lights_; }

 private:
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<Accelerator> accelerator_;
  Lights lights_;
};

inline uint32_t addMaterial(Scene& scene, Color albedo, Color emission = Color(0.0f)) {
  Material m;
  m.name = std::to_string(scene.materials.size());
  m.name.insert(0, 1, 'm');
  m.albedo = albedo;
  m.emission = emission;
  scene.materials.push_back(m);
  return uint32_t(scene.materials.size() - 1);
}

// A quad corner + s u + t v, facing u x v.
inline void addQuad(Scene& scene, Point3 corner, Vec3 u, Vec3 v, uint32_t material) {
  TriangleMesh mesh;
  mesh.positions = {corner, corner + u, corner + u + v, corner + v};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.material = material;
  scene.meshes.push_back(mesh);
}

}  // namespace pathlab::test
