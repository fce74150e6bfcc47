// Task 2 — ray–triangle and ray–sphere intersection (reference solution).
#include "tasks/intersection.h"

#include <cmath>
#include <utility>

namespace pathlab {
namespace {

int largestAxis(const Vec3& v) { return (v.x > v.y) ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2); }

Vec3 permute(const Vec3& v, int x, int y, int z) { return {v[x], v[y], v[z]}; }

}  // namespace

// Watertight test of Woop, Benthin and Wald (JCGT 2013), as in pbrt-v4.
std::optional<TriangleHit> intersectTriangle(const Ray& ray, Interval range, const Point3& p0,
                                             const Point3& p1, const Point3& p2) {
  // Translate the vertices so the ray starts at the origin.
  Vec3 a = p0 - ray.origin, b = p1 - ray.origin, c = p2 - ray.origin;

  // Permute so the ray direction's largest component is z.
  const int kz = largestAxis(glm::abs(ray.direction));
  const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  const Vec3 d = permute(ray.direction, kx, ky, kz);
  a = permute(a, kx, ky, kz);
  b = permute(b, kx, ky, kz);
  c = permute(c, kx, ky, kz);

  // Shear x and y so the ray runs along +z; z is scaled later, only if needed.
  const float shearX = -d.x / d.z, shearY = -d.y / d.z, shearZ = 1.0f / d.z;
  a.x += shearX * a.z, a.y += shearY * a.z;
  b.x += shearX * b.z, b.y += shearY * b.z;
  c.x += shearX * c.z, c.y += shearY * c.z;

  // 2D edge functions: twice the signed areas seen from the ray. A shared
  // edge gives exactly opposite values in its two triangles.
  float e0 = b.x * c.y - b.y * c.x;
  float e1 = c.x * a.y - c.y * a.x;
  float e2 = a.x * b.y - a.y * b.x;
  if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
    // Exactly on an edge in float: decide in double so neighbours agree.
    e0 = float(double(b.x) * c.y - double(b.y) * c.x);
    e1 = float(double(c.x) * a.y - double(c.y) * a.x);
    e2 = float(double(a.x) * b.y - double(a.y) * b.x);
  }
  if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return std::nullopt;
  const float det = e0 + e1 + e2;
  if (det == 0.0f) return std::nullopt;  // edge-on, or a degenerate projection

  // Scaled hit distance, compared against the range without dividing.
  a.z *= shearZ, b.z *= shearZ, c.z *= shearZ;
  const float tScaled = e0 * a.z + e1 * b.z + e2 * c.z;
  if (det < 0.0f && (tScaled >= range.min * det || tScaled <= range.max * det)) return std::nullopt;
  if (det > 0.0f && (tScaled <= range.min * det || tScaled >= range.max * det)) return std::nullopt;

  // A zero-area triangle has no normal: never report a hit on it.
  const Vec3 n = glm::cross(p1 - p0, p2 - p0);
  if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f) return std::nullopt;

  const float invDet = 1.0f / det;
  return TriangleHit{tScaled * invDet, e1 * invDet, e2 * invDet};
}

// Haines, Günther and Akenine-Möller, "Precision improvements for ray/sphere
// intersection", Ray Tracing Gems (2019), chapter 7.
std::optional<float> intersectSphere(const Ray& ray, Interval range, const Point3& center, float radius) {
  const Vec3 f = ray.origin - center;
  const Vec3& d = ray.direction;
  const float a = glm::dot(d, d);
  const float halfB = glm::dot(f, d);
  const float c = glm::dot(f, f) - radius * radius;

  // b^2 - 4ac loses r^2 when the sphere is small and far; the squared
  // distance from the centre to the ray's line does not.
  const Vec3 perpendicular = f - (halfB / a) * d;
  const float discriminant = a * (radius * radius - glm::dot(perpendicular, perpendicular));
  if (discriminant < 0.0f) return std::nullopt;

  // Stable root pair: never subtract two nearly equal numbers.
  const float q = -(halfB + std::copysign(std::sqrt(discriminant), halfB));
  float t0 = (q != 0.0f) ? c / q : 0.0f;
  float t1 = q / a;
  if (t0 > t1) std::swap(t0, t1);
  if (range.contains(t0)) return t0;
  if (range.contains(t1)) return t1;
  return std::nullopt;
}

SurfacePoint triangleSurfacePoint(const TriangleHit& hit, const Point3& p0, const Point3& p1,
                                  const Point3& p2, const Vec3* normals) {
  SurfacePoint s;
  const float b0 = 1.0f - hit.b1 - hit.b2;
  // From the barycentrics rather than origin + t * direction: the point lands
  // on the triangle's plane to within the vertices' own rounding.
  s.point = b0 * p0 + hit.b1 * p1 + hit.b2 * p2;
  s.geometricNormal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  s.shadingNormal = s.geometricNormal;
  if (normals) {
    Vec3 n = b0 * normals[0] + hit.b1 * normals[1] + hit.b2 * normals[2];
    if (glm::dot(n, n) > 0.0f) {
      s.shadingNormal = glm::normalize(n);
      // Vertex normals say which side is outside; the winding follows them.
      if (glm::dot(s.geometricNormal, s.shadingNormal) < 0.0f) s.geometricNormal = -s.geometricNormal;
    }
  }
  return s;
}

SurfacePoint sphereSurfacePoint(const Ray& ray, float t, const Point3& center, float radius) {
  SurfacePoint s;
  const Vec3 outward = glm::normalize(ray.at(t) - center);
  s.point = center + radius * outward;  // re-project onto the sphere
  s.geometricNormal = outward;
  s.shadingNormal = outward;
  return s;
}

}  // namespace pathlab
