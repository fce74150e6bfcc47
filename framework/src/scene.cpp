#include "pathlab/scene.h"

namespace pathlab {

void Scene::indexPrimitives() {
  primitives.clear();
  primitives.reserve(triangleCount() + spheres.size());
  for (uint32_t m = 0; m < meshes.size(); ++m) {
    for (uint32_t i = 0; i < meshes[m].triangles.size(); ++i) primitives.push_back({m, i});
  }
  for (uint32_t i = 0; i < spheres.size(); ++i) primitives.push_back({PrimitiveRef::kSphere, i});
}

uint32_t Scene::materialOf(uint32_t primitive) const {
  const PrimitiveRef& ref = primitives[primitive];
  return ref.isSphere() ? spheres[ref.index].material : meshes[ref.mesh].material;
}

size_t Scene::triangleCount() const {
  size_t n = 0;
  for (const TriangleMesh& mesh : meshes) n += mesh.triangles.size();
  return n;
}

}  // namespace pathlab
