#include "core/scene.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include "util/error.h"

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

MediumIndex Scene::mediumAcross(const Hit& hit, const Vec3& direction, MediumIndex current) const {
  const Material& material = materials[hit.material];
  if (material.type != MaterialType::Interface && material.interior == kVacuum) return current;
  return glm::dot(direction, hit.geometricNormal) < 0.0f ? material.interior : medium;
}

size_t Scene::triangleCount() const {
  size_t n = 0;
  for (const TriangleMesh& mesh : meshes) n += mesh.triangles.size();
  return n;
}

void checkResolution(int64_t width, int64_t height, const std::string& where) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels) {
    throw Error(where + ": an image of " + std::to_string(width) + "x" + std::to_string(height) +
                " pixels is out of range (each side 1.." + std::to_string(kMaxImageSide) + ", at most " +
                std::to_string(kMaxImagePixels >> 20) + "M pixels)");
  }
}

namespace {

bool withinLimits(const Vec3& p) {
  for (int k = 0; k < 3; ++k) {
    if (!(std::abs(p[k]) <= kMaxSceneCoordinate)) return false;  // NaN fails too
  }
  return true;
}

std::string formatted(const Vec3& p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%g, %g, %g)", double(p.x), double(p.y), double(p.z));
  return buffer;
}

}  // namespace

void checkSceneLimits(const Scene& scene) {
  const std::string file = shown(scene.source, 200) + ": ";
  const std::string limit = " (geometry must lie within 1e12 of the origin on every axis)";
  for (const TriangleMesh& mesh : scene.meshes) {
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      if (!withinLimits(mesh.positions[i])) {
        throw Error(file + "mesh " + shown(mesh.name) + ": vertex " + std::to_string(i) + " at " +
                    formatted(mesh.positions[i]) + " is out of range" + limit);
      }
    }
  }
  for (size_t i = 0; i < scene.spheres.size(); ++i) {
    const Sphere& s = scene.spheres[i];
    // Every point of the sphere in range: |center| + radius, in double.
    bool ok = std::isfinite(s.radius) && s.radius <= kMaxSceneCoordinate;
    for (int k = 0; k < 3 && ok; ++k) ok = std::abs(double(s.center[k])) + double(s.radius) <= double(kMaxSceneCoordinate);
    if (!ok) {
      char radius[32];
      std::snprintf(radius, sizeof radius, "%g", double(s.radius));
      throw Error(file + "sphere " + std::to_string(i) + " (center " + formatted(s.center) + ", radius " + radius +
                  ") reaches out of range" + limit);
    }
  }
  const Camera& camera = scene.camera;
  for (const auto& [name, point] : {std::pair{"position", camera.position}, std::pair{"look_at", camera.lookAt}}) {
    if (!withinLimits(point)) throw Error(file + "camera " + name + " " + formatted(point) + " is out of range" + limit);
  }
  if (!(camera.apertureRadius >= 0.0f && camera.apertureRadius <= kMaxSceneCoordinate) ||
      !(camera.focalDistance > 0.0f && std::isfinite(camera.focalDistance))) {
    char lens[96];
    std::snprintf(lens, sizeof lens, "aperture radius %g, focal distance %g", double(camera.apertureRadius),
                  double(camera.focalDistance));
    throw Error(file + "camera lens (" + lens + "): expected a radius in [0, 1e12] and a positive distance");
  }
  const Vec3 forward = camera.lookAt - camera.position;
  if (!(glm::length(forward) > 0.0f) || !(glm::length(glm::cross(forward, camera.up)) > 0.0f) ||
      !isFinite(glm::normalize(glm::cross(forward, camera.up)))) {
    throw Error(file + "camera: the view direction " + formatted(forward) + " and up " + formatted(camera.up) +
                " do not define a view (zero or parallel)");
  }
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
