#include "pathlab/scene.h"

#include <utility>

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

void transformMesh(TriangleMesh& mesh, const glm::mat4& worldFromObject) {
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(worldFromObject)));
  for (Point3& p : mesh.positions) p = Point3(worldFromObject * glm::vec4(p, 1.0f));
  for (Vec3& n : mesh.normals) n = glm::normalize(normalMatrix * n);
  if (glm::determinant(glm::mat3(worldFromObject)) < 0.0f) {
    for (glm::uvec3& t : mesh.triangles) std::swap(t.y, t.z);
  }
}

}  // namespace pathlab
