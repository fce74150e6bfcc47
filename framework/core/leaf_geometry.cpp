#include "core/leaf_geometry.h"

namespace pathlab {

LeafGeometry::LeafGeometry(const Scene& scene, std::span<const uint32_t> order, const PrimitiveTests& tests)
    : tests_(tests) {
  slots_.reserve(order.size());
  for (uint32_t primitive : order) {
    const PrimitiveRef& ref = scene.primitives[primitive];
    Slot slot{};
    slot.primitive = primitive;
    if (ref.isSphere()) {
      const Sphere& sphere = scene.spheres[ref.index];
      slot.isSphere = 1;
      slot.a = sphere.center;
      slot.b = Point3(sphere.radius, 0.0f, 0.0f);
    } else {
      const TriangleMesh& mesh = scene.meshes[ref.mesh];
      const glm::uvec3& v = mesh.triangles[ref.index];
      slot.a = mesh.positions[v.x];
      slot.b = mesh.positions[v.y];
      slot.c = mesh.positions[v.z];
    }
    slots_.push_back(slot);
  }
}

std::vector<Aabb> primitiveBounds(const Scene& scene) {
  std::vector<Aabb> bounds(scene.primitives.size());
  for (size_t i = 0; i < scene.primitives.size(); ++i) {
    const PrimitiveRef& ref = scene.primitives[i];
    if (ref.isSphere()) {
      const Sphere& s = scene.spheres[ref.index];
      bounds[i].grow(s.center - Vec3(s.radius));
      bounds[i].grow(s.center + Vec3(s.radius));
    } else {
      const TriangleMesh& mesh = scene.meshes[ref.mesh];
      const glm::uvec3& v = mesh.triangles[ref.index];
      for (int k = 0; k < 3; ++k) bounds[i].grow(mesh.positions[v[k]]);
    }
  }
  return bounds;
}

}  // namespace pathlab
