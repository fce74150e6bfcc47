#include "core/lights.h"

#include <algorithm>
#include <cmath>

#include "util/sampling.h"

namespace pathlab {

AreaLight AreaLight::fromMesh(const Scene& scene, uint32_t mesh) {
  AreaLight light;
  light.scene_ = &scene;
  light.object_ = mesh;
  const TriangleMesh& m = scene.meshes[mesh];
  light.radiance_ = scene.materials[m.material].emission;
  std::vector<float> areas;
  for (const glm::uvec3& t : m.triangles) {
    const Point3 &p0 = m.positions[t.x], &p1 = m.positions[t.y], &p2 = m.positions[t.z];
    const Vec3 cross = glm::cross(p1 - p0, p2 - p0);
    areas.push_back(0.5f * glm::length(cross));
    light.triangles_.push_back({p0, p1, p2, glm::normalize(cross)});
  }
  light.byArea_ = Distribution1D(areas);
  light.area_ = float(light.byArea_.total());
  return light;
}

AreaLight AreaLight::fromSphere(const Scene& scene, uint32_t sphere) {
  AreaLight light;
  light.scene_ = &scene;
  light.object_ = sphere;
  light.isSphere_ = true;
  const Sphere& s = scene.spheres[sphere];
  light.radiance_ = scene.materials[s.material].emission;
  light.area_ = 4.0f * kPi * s.radius * s.radius;
  return light;
}

AreaSample AreaLight::sample(Vec2 u) const {
  AreaSample result;
  result.radiance = radiance_;
  result.pdfArea = 1.0f / area_;
  if (isSphere_) {
    const Sphere& s = scene_->spheres[object_];
    result.normal = uniformSphereDirection(u);
    result.point = s.center + s.radius * result.normal;
    return result;
  }
  // Pick a triangle by area (u.x is re-used), then a uniform point in it:
  // Heitz's map from the square to the triangle ("A Low-Distortion Map
  // Between Triangle and Square", 2019), which folds the square's two halves
  // onto it with a constant Jacobian. No square root, and neighbouring
  // samples stay neighbours, so stratified and Sobol points stay spread.
  // Heitz writes it with a branch (halve the smaller coordinate, subtract
  // that from the other); subtracting half the smaller from both is the
  // same, exactly, and leaves the CPU no coin-flip branch to mispredict.
  Vec2 b(0.0f, u.y);
  const Triangle& t = triangles_[byArea_.sample(u.x, &b.x)];
  b -= 0.5f * std::min(b.x, b.y);
  result.point = b.x * t.p0 + b.y * t.p1 + (1.0f - b.x - b.y) * t.p2;
  result.normal = t.normal;
  return result;
}

EnvironmentLight::EnvironmentLight(const Environment& environment, EnvironmentSampling sampling,
                                   const EnvironmentMapFunctions& map)
    : environment_(&environment), sampling_(sampling), map_(map) {
  if (hasMap() && sampling_ == EnvironmentSampling::Importance) {
    distribution_ = map_.buildEnvironmentDistribution(environment.image);
  }
}

Color EnvironmentLight::pixelRadiance(const Vec3& w) const {
  if (!hasMap()) return radiance(w);  // a constant sky: its colour is what lighting integrates
  const Image& map = environment_->image;
  const Point2 uv = map_.directionToEquirect(w);
  const int i = std::clamp(int(uv.x * float(map.width)), 0, map.width - 1);
  const int j = std::clamp(int(uv.y * float(map.height)), 0, map.height - 1);
  return map.at(i, j) * environment_->scale;
}

Color EnvironmentLight::radiance(const Vec3& w) const {
  const Color value = hasMap() ? map_.lookupEnvironment(environment_->image, w) : environment_->color;
  return value * environment_->scale;
}

std::optional<EnvironmentLightSample> EnvironmentLight::sample(Vec2 u) const {
  EnvironmentLightSample s;
  if (hasMap() && sampling_ == EnvironmentSampling::Importance) {
    std::optional<EnvironmentSample> drawn = map_.sampleEnvironment(distribution_, u);
    if (!drawn) return std::nullopt;
    s.direction = drawn->direction;
    s.pdfSolidAngle = drawn->pdfSolidAngle;
  } else if (hasMap()) {
    s.direction = map_.sampleUniformSphere(u);  // the student's baseline (task 7)
    s.pdfSolidAngle = 1.0f / (4.0f * kPi);
  } else {
    // A constant colour: uniform over the sphere (framework code, so tasks
    // 4-6 need nothing from task 7).
    s.direction = uniformSphereDirection(u);
    s.pdfSolidAngle = 1.0f / (4.0f * kPi);
  }
  if (!(s.pdfSolidAngle > 0.0f) || !isFinite(s.direction)) return std::nullopt;
  s.radiance = hasMap() ? pixelRadiance(s.direction) : radiance(s.direction);
  return s;
}

float EnvironmentLight::pdf(const Vec3& w) const {
  if (hasMap() && sampling_ == EnvironmentSampling::Importance) return map_.environmentPdf(distribution_, w);
  return 1.0f / (4.0f * kPi);
}

Lights Lights::fromScene(const Scene& scene, const EnvironmentMapFunctions& map, EnvironmentSampling sampling) {
  Lights lights;
  if (scene.environment) lights.environment.emplace(*scene.environment, sampling, map);
  lights.points = scene.pointLights;
  lights.lightOfMesh.assign(scene.meshes.size(), -1);
  lights.lightOfSphere.assign(scene.spheres.size(), -1);
  for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
    if (!scene.materials[scene.meshes[m].material].isEmissive()) continue;
    lights.lightOfMesh[m] = int(lights.areas.size());
    lights.areas.push_back(AreaLight::fromMesh(scene, m));
  }
  for (uint32_t s = 0; s < scene.spheres.size(); ++s) {
    if (!scene.materials[scene.spheres[s].material].isEmissive()) continue;
    lights.lightOfSphere[s] = int(lights.areas.size());
    lights.areas.push_back(AreaLight::fromSphere(scene, s));
  }
  return lights;
}

const AreaLight* Lights::areaLightAt(const Scene& scene, const Hit& hit) const {
  const PrimitiveRef& ref = scene.primitives[hit.primitive];
  const int index = ref.isSphere() ? lightOfSphere[ref.index] : lightOfMesh[ref.mesh];
  return index >= 0 ? &areas[size_t(index)] : nullptr;
}

float Lights::areaPdfSolidAngle(const AreaLight& light, const Point3& from, const Hit& hit) {
  const Vec3 toLight = hit.point - from;
  const float distanceSquared = glm::dot(toLight, toLight);
  if (!(distanceSquared > 0.0f)) return 0.0f;
  const float cosLight = -glm::dot(hit.geometricNormal, toLight) / std::sqrt(distanceSquared);
  if (cosLight <= 0.0f) return 0.0f;
  return distanceSquared / (cosLight * light.area());
}

Color emittedRadiance(const Scene& scene, const Hit& hit, const Vec3& wo) {
  const Material& material = scene.materials[hit.material];
  if (!material.isEmissive() || glm::dot(hit.geometricNormal, wo) <= 0.0f) return Color(0.0f);
  return material.emission;
}

}  // namespace pathlab
