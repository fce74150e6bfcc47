#include "render/scene_intersect.h"

#include "core/leaf_geometry.h"
#include "render/task_wiring.h"
#include "tasks/intersection.h"

namespace pathlab {

std::optional<PrimitiveHit> intersectPrimitive(const Scene& scene, uint32_t primitive,
                                               const Ray& ray, Interval range) {
  const PrimitiveRef& ref = scene.primitives[primitive];
  if (ref.isSphere()) {
    const Sphere& sphere = scene.spheres[ref.index];
    return sphereHit(kLinkedTasks.primitives, ray, range, sphere.center, sphere.radius, primitive);
  }
  const TriangleMesh& mesh = scene.meshes[ref.mesh];
  const glm::uvec3& v = mesh.triangles[ref.index];
  return triangleHit(kLinkedTasks.primitives, ray, range, mesh.positions[v.x], mesh.positions[v.y], mesh.positions[v.z], primitive);
}

Hit surfaceHit(const Scene& scene, const Ray& ray, const PrimitiveHit& hit) {
  const PrimitiveRef& ref = scene.primitives[hit.primitive];
  SurfacePoint surface;
  if (ref.isSphere()) {
    const Sphere& sphere = scene.spheres[ref.index];
    surface = sphereSurfacePoint(ray, hit.t, sphere.center, sphere.radius);
  } else {
    const TriangleMesh& mesh = scene.meshes[ref.mesh];
    const glm::uvec3& v = mesh.triangles[ref.index];
    Vec3 normals[3];
    const bool smooth = !mesh.normals.empty();
    if (smooth) {
      normals[0] = mesh.normals[v.x];
      normals[1] = mesh.normals[v.y];
      normals[2] = mesh.normals[v.z];
    }
    surface = triangleSurfacePoint(TriangleHit{hit.t, hit.b1, hit.b2}, mesh.positions[v.x],
                                   mesh.positions[v.y], mesh.positions[v.z], smooth ? normals : nullptr);
  }
  Hit result;
  result.t = hit.t;
  result.point = surface.point;
  result.geometricNormal = surface.geometricNormal;
  result.shadingNormal = surface.shadingNormal;
  result.primitive = hit.primitive;
  result.material = scene.materialOf(hit.primitive);
  return result;
}

std::optional<Hit> intersectBruteForce(const Scene& scene, const Ray& ray, Interval range) {
  std::optional<PrimitiveHit> closest;
  for (uint32_t p = 0; p < scene.primitives.size(); ++p) {
    if (auto hit = intersectPrimitive(scene, p, ray, range)) {
      closest = hit;
      range.max = hit->t;  // only closer hits from now on
    }
  }
  if (!closest) return std::nullopt;
  return surfaceHit(scene, ray, *closest);
}

}  // namespace pathlab
