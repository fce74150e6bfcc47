// Metamorphic relations: a whole scene moved, turned, mirrored or resized,
// whose answer the judge knows without computing it (the same picture, the
// same estimate at the moved point). Each suite picks the relations its
// task's code could break (docs/metamorphic.md lists them and what each
// catches): an absolute epsilon fails at another scale, a y-up assumption
// under a rotation, a winding assumption under a mirror.
#pragma once

#include <glm/gtc/matrix_transform.hpp>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "check.h"
#include "core/scene.h"
#include "statistics.h"
#include "util/ray.h"

namespace pathlab::test {

using DMat3 = glm::dmat3;

// x -> scale R x + offset, in double and rounded once. R is a rotation, or
// a rotation times a mirror (determinant -1). What the scene's light does
// under it: radiance is unchanged; a point light's intensity grows with
// scale^2 (irradiance I cos / r^2 stays); a medium's extinction per unit
// length shrinks with 1 / scale (the optical depth stays).
struct Similarity {
  std::string name;  // for the hint: "the scene 1000 times smaller"
  double scale = 1.0;
  DMat3 rotation{1.0};
  DVec3 offset{0.0};

  Point3 point(const Point3& p) const { return Point3(scale * (rotation * DVec3(p)) + offset); }
  // (Not normalised again: R keeps lengths, and a mirror or the identity stays exact.)
  Vec3 direction(const Vec3& d) const { return Vec3(rotation * DVec3(d)); }
  bool mirrors() const { return glm::determinant(rotation) < 0.0; }
  Ray ray(const Ray& r) const { return Ray{point(r.origin), direction(r.direction)}; }
};

// A rotation by `degrees` about `axis` (any length).
inline DMat3 rotationAbout(DVec3 axis, double degrees) {
  return DMat3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::normalize(axis)));
}
// The mirror x -> -x.
inline DMat3 mirrorX() { return DMat3(DVec3(-1, 0, 0), DVec3(0, 1, 0), DVec3(0, 0, 1)); }

// The scene under t. A mirror swaps two corners of every triangle, so that
// each face still faces the mirror image of where it faced (one-sided lights
// keep lighting the same things). An environment map is fixed to the world
// axes: only a constant sky is moved with the scene (a rotation of a map is
// refused, not silently wrong).
inline Scene transformed(const Scene& scene, const Similarity& t) {
  Scene out = scene;
  const bool rotates = t.rotation != DMat3(1.0);
  if (rotates && out.environment && !out.environment->image.pixels.empty()) {
    throw std::logic_error("a rotation of a scene lit by an environment map: the map would have to turn too");
  }
  for (TriangleMesh& mesh : out.meshes) {
    for (Point3& p : mesh.positions) p = t.point(p);
    for (Vec3& n : mesh.normals) n = t.direction(n);
    if (t.mirrors()) {
      for (glm::uvec3& triangle : mesh.triangles) std::swap(triangle.y, triangle.z);
    }
  }
  for (Sphere& sphere : out.spheres) {
    sphere.center = t.point(sphere.center);
    sphere.radius = float(t.scale * double(sphere.radius));
  }
  for (PointLight& light : out.pointLights) {
    light.position = t.point(light.position);
    light.intensity *= float(t.scale * t.scale);
  }
  for (Medium& medium : out.media) medium.sigmaT = float(double(medium.sigmaT) / t.scale);
  Camera& camera = out.camera;
  camera.position = t.point(camera.position);
  camera.lookAt = t.point(camera.lookAt);
  camera.up = t.direction(camera.up);
  camera.apertureRadius = float(t.scale * double(camera.apertureRadius));
  camera.focalDistance = float(t.scale * double(camera.focalDistance));
  out.primitives.clear();  // Rig indexes them again
  return out;
}

// Camera rays into the Cornell box's open volume (image_scenes.h's
// cornellBox), `count` of them drawn with `seed`.
inline std::vector<Ray> raysIntoCornellBox(const Scene& box, int count, uint64_t seed) {
  Random random(seed);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const DVec3 target(random.uniform(-0.9, 0.9), random.uniform(0.05, 1.45), random.uniform(-0.9, 0.5));
    rays.push_back(Ray{box.camera.position, Vec3(glm::normalize(target - DVec3(box.camera.position)))});
  }
  return rays;
}

// Path queries (ray, stream, seed) for the rays under t, `perRay` random
// streams each, the same streams whatever t is: a paired relation's input.
inline std::vector<std::tuple<Ray, uint32_t, uint64_t>> pairedPathQueries(const Similarity& t,
                                                                          const std::vector<Ray>& rays, int perRay,
                                                                          uint64_t seed) {
  std::vector<std::tuple<Ray, uint32_t, uint64_t>> queries;
  for (size_t r = 0; r < rays.size(); ++r)
    for (int i = 0; i < perRay; ++i) queries.emplace_back(t.ray(rays[r]), uint32_t(r * perRay + i), seed);
  return queries;
}

// One value per answer, the mean of its channels.
inline std::vector<double> channelMeans(const std::vector<Color>& answers) {
  std::vector<double> values;
  for (const Color& L : answers) values.push_back((double(L.x) + L.y + L.z) / 3.0);
  return values;
}

// Paired answers: "" when `moved` gives the same answers as `base` (more
// than 1e-3 apart, relative, in at most 0.5 % of them: a rounding may move
// a sample across a shadow's edge); else how many differ, and where (answers
// come `perPoint` to a point).
inline std::string brokenPairs(const std::vector<double>& base, size_t perPoint, const std::vector<double>& moved) {
  if (moved.size() != base.size()) return "a different number of answers";
  size_t differing = 0;
  std::ostringstream where;
  for (size_t k = 0; k < base.size(); ++k) {
    if (std::abs(moved[k] - base[k]) <= 1e-3 * std::max(std::abs(base[k]), std::abs(moved[k])) + 1e-12) continue;
    if (differing++ < 3) where << " point " << k / perPoint << ": " << base[k] << " became " << moved[k] << ";";
  }
  if (differing <= base.size() / 200) return "";
  return std::to_string(differing) + " of " + std::to_string(base.size()) + " answers differ by more than 1e-3;" +
         where.str();
}

// |a - b| within 5 standard errors of their difference, each capped at its
// suite's ceiling (limitNoise: the candidate's own noise can only make this
// fail), plus `relative` of the larger for float rounding. For two estimates
// from the same random numbers the difference is far smaller; from different
// ones, a correct estimator fails one check in 1.7 million.
inline bool sameEstimate(const MeanEstimate& a, const MeanEstimate& b, double relative = 1e-3) {
  const double sa = a.judgedStandardError(), sb = b.judgedStandardError();
  return std::abs(a.mean() - b.mean()) <=
         5.0 * std::sqrt(sa * sa + sb * sb) + relative * std::max(std::abs(a.mean()), std::abs(b.mean())) + 1e-12;
}

}  // namespace pathlab::test
