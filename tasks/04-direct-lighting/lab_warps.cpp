// Task 4's warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab; addDirectLightingWarps is listed with the other tasks'.
#include "lab_support.h"
#include "scene/procedural.h"
#include "tasks/direct_lighting.h"
#include "util/distribution.h"

namespace pathlab::lab {
namespace {

// The area lights the lab samples points on, in the plane z = 0 (a mesh's
// triangles counter-clockwise) or a sphere.
struct LabLightShape {
  std::vector<Point3> positions;
  std::vector<glm::uvec3> triangles;
  bool sphere = false;
};

LabLightShape labLight(int which) {
  if (which == 2) return {{}, {}, true};
  if (which == 0) {  // the Cornell box's ceiling light, 1.3 x 1.05: two equal triangles
    return {{{-0.65f, -0.525f, 0.0f}, {0.65f, -0.525f, 0.0f}, {0.65f, 0.525f, 0.0f}, {-0.65f, 0.525f, 0.0f}},
            {{0, 1, 2}, {0, 2, 3}}};
  }
  // An L of four triangles and two strays of very different areas (0.4 to 0.02):
  // choosing a triangle by count rather than by area shows at once.
  return {{{-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {1.0f, -0.6f, 0.0f}, {-1.0f, -0.6f, 0.0f},
           {-0.6f, -0.6f, 0.0f}, {-0.6f, 1.0f, 0.0f}, {-1.0f, 1.0f, 0.0f},
           {0.0f, -0.4f, 0.0f}, {1.0f, -0.4f, 0.0f}, {1.0f, 1.0f, 0.0f},
           {-0.4f, 0.6f, 0.0f}, {-0.2f, 0.6f, 0.0f}, {-0.4f, 0.8f, 0.0f}},
          {{0, 1, 2}, {0, 2, 3}, {3, 4, 5}, {3, 5, 6}, {7, 8, 9}, {10, 11, 12}}};
}

// Twice the signed area of (a, b, p) in the plane: >= 0 when p is left of a -> b.
float edgeSide(const Point3& a, const Point3& b, const Point3& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

Warp lightPointsWarp() {
  return {"light-points", "T4",
          "AreaLight::sample (the framework's, used by task 4): points uniform by area on a mesh or sphere light",
          {{"shape", 0, 0, 2, true, false, "0 the Cornell box's ceiling light, 1 triangles of unequal areas, 2 a sphere"},
           {"mistake", 0, 0, 2, true, false,
            "1: the triangle picked uniformly, not by area (a sphere: theta = pi u, not cos theta = 1 - 2u); "
            "2: b = u, not sqrt(u) (points crowd at a corner)"}},
          [](const Values& p, const WarpFiles&) {
            const LabLightShape shape = labLight(count(p, "shape"));
            const int mistake = count(p, "mistake");
            // A scene holding just the light, as Lights::fromScene would build it.
            auto scene = std::make_shared<Scene>();
            Material glow;
            glow.emission = Color(1.0f);
            scene->materials.push_back(glow);
            if (shape.sphere) {
              scene->spheres.push_back({Point3(0.0f), 1.0f, 0});
            } else {
              scene->meshes.push_back({});
              scene->meshes[0].positions = shape.positions;
              scene->meshes[0].triangles = shape.triangles;
            }
            scene->indexPrimitives();
            const auto light = std::make_shared<AreaLight>(shape.sphere ? AreaLight::fromSphere(*scene, 0)
                                                                        : AreaLight::fromMesh(*scene, 0));
            WarpSetup s;
            if (shape.sphere) {
              // A uniform point on the unit sphere is a uniform direction: 1 / (4 pi) per steradian.
              s.domain = Domain::Sphere;
              s.sample = [scene, light, mistake](Vec2 u) -> std::optional<Vec3> {
                if (mistake == 0) return light->sample(u).point;
                const double theta = kPi * u.x, phi = 2.0 * kPi * u.y;  // the mistake: uniform in theta
                return Vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                            float(std::cos(theta)));
              };
              s.pdf = pointwise([](const Vec3&) { return 1.0 / (4.0 * kPi); });
              s.mismatchMeans = "the point is not uniform over the sphere: z = 1 - 2u, not cos(theta) = u";
              return s;
            }
            s.domain = Domain::Plane;
            s.lo = Vec2(1e9f), s.hi = Vec2(-1e9f);
            for (const Point3& v : shape.positions) s.lo = glm::min(s.lo, Vec2(v)), s.hi = glm::max(s.hi, Vec2(v));
            std::vector<float> areas;
            for (const glm::uvec3& t : shape.triangles) {
              areas.push_back(0.5f * edgeSide(shape.positions[t.x], shape.positions[t.y], shape.positions[t.z]));
            }
            const auto byArea = std::make_shared<Distribution1D>(areas);
            s.sample = [scene, light, shape, mistake, byArea](Vec2 u) -> std::optional<Vec3> {
              if (mistake == 0) return light->sample(u).point;
              // The two classic mistakes, written here (the framework's sampler makes neither).
              size_t i = 0;
              float ux = u.x;
              if (mistake == 1) {
                const size_t count = shape.triangles.size();
                i = std::min(count - 1, size_t(u.x * float(count)));
                ux = u.x * float(count) - float(i);
              } else {
                i = byArea->sample(u.x, &ux);
              }
              const glm::uvec3& t = shape.triangles[i];
              const float root = mistake == 2 ? ux : std::sqrt(ux);
              const float b1 = root * (1.0f - u.y), b2 = root * u.y;
              return (1.0f - b1 - b2) * shape.positions[t.x] + b1 * shape.positions[t.y] + b2 * shape.positions[t.z];
            };
            const double inverseArea = 1.0 / double(light->area());
            s.pdf = pointwise([shape, inverseArea](const Vec3& x) {
              for (const glm::uvec3& t : shape.triangles) {
                const Point3 &a = shape.positions[t.x], &b = shape.positions[t.y], &c = shape.positions[t.z];
                if (edgeSide(a, b, x) >= 0.0f && edgeSide(b, c, x) >= 0.0f && edgeSide(c, a, x) >= 0.0f) {
                  return inverseArea;
                }
              }
              return 0.0;
            });
            s.mismatchMeans = "the points are not uniform by area: a triangle must be chosen with probability "
                              "area / total, and a point in it needs sqrt(u) (b1 = sqrt(u1) (1 - u2), "
                              "b2 = sqrt(u1) u2)";
            return s;
          }};
}

Warp lightDirectionsWarp() {
  return {"light-directions", "T4.3",
          "lightDirection: points sampled by area on a square light, as directions with their solid-angle pdf",
          {{"height", 1.0, 0.05, 10.0, false, true, "the light's height above the shading point"},
           {"size", 1.0, 0.05, 10.0, false, true, "the light's side"},
           {"offset", 0.5, 0.0, 10.0, false, false, "the light's centre, sideways from straight above"}},
          [](const Values& p, const WarpFiles&) {
            const float h = float(p.at("height")), side = float(p.at("size")), offset = float(p.at("offset"));
            // The light faces down (-z) towards the shading point at the origin.
            auto lightPoint = [=](Point3 point) {
              AreaSample a;
              a.point = point;
              a.normal = Vec3(0.0f, 0.0f, -1.0f);
              a.radiance = Color(1.0f);
              a.pdfArea = 1.0f / (side * side);
              return a;
            };
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sphereSubdivision = 32;  // the light's outline is a sharp edge of the pdf
            s.sample = [=](Vec2 u) -> std::optional<Vec3> {
              const Point3 point(offset + (u.x - 0.5f) * side, (u.y - 0.5f) * side, h);
              const std::optional<LightDirection> d = lightDirection(Point3(0.0f), lightPoint(point));
              if (!d) return std::nullopt;
              return d->wi;
            };
            s.pdf = pointwise([=](const Vec3& w) {
              if (!(w.z > 0.0f)) return 0.0;
              const Point3 hit = w * (h / w.z);
              if (std::abs(hit.x - offset) > 0.5f * side || std::abs(hit.y) > 0.5f * side) return 0.0;
              const std::optional<LightDirection> d = lightDirection(Point3(0.0f), lightPoint(hit));
              return d ? double(d->pdfSolidAngle) : 0.0;
            });
            s.mismatchMeans = "the area-to-solid-angle conversion: pdf = pdfArea r^2 / cos(theta') with the cosine "
                              "at the light";
            return s;
          }};
}

}  // namespace

void addDirectLightingWarps(std::vector<Warp>& warps) {
  warps.push_back(lightPointsWarp());
  warps.push_back(lightDirectionsWarp());
}

}  // namespace pathlab::lab
