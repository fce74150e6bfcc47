#include "scene/procedural.h"

#include <cmath>
#include <numbers>
#include <string>

namespace pathlab {

using DVec3 = glm::dvec3;
constexpr double kPiD = std::numbers::pi;

TriangleMesh bumpySphere(int rings, int segments, double radius, DVec3 center, DVec3 stretch) {
  TriangleMesh mesh;
  mesh.name = "bumpy sphere (" + std::to_string(2 * (rings - 1) * segments) + " triangles)";
  auto point = [&](double theta, double phi) {
    const double r = radius * (1.0 + 0.08 * std::sin(7.0 * theta) * std::cos(5.0 * phi) +
                               0.03 * std::sin(23.0 * theta + 3.0 * phi));
    DVec3 unit(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    return Point3(center + r * stretch * unit);
  };
  // Vertex 0 is the north pole, then rings - 1 bands of `segments` vertices, then the south pole.
  mesh.positions.push_back(point(0.0, 0.0));
  for (int i = 1; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) mesh.positions.push_back(point(kPiD * i / rings, 2.0 * kPiD * j / segments));
  }
  mesh.positions.push_back(point(kPiD, 0.0));
  const uint32_t south = uint32_t(mesh.positions.size() - 1);
  auto at = [segments](int ring, int j) { return uint32_t(1 + (ring - 1) * segments + (j % segments)); };
  // Counter-clockwise seen from outside: the normals point away from the centre.
  for (int j = 0; j < segments; ++j) {
    mesh.triangles.emplace_back(0u, at(1, j + 1), at(1, j));
    mesh.triangles.emplace_back(south, at(rings - 1, j), at(rings - 1, j + 1));
  }
  for (int i = 1; i + 1 < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      mesh.triangles.emplace_back(at(i, j), at(i, j + 1), at(i + 1, j + 1));
      mesh.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i + 1, j));
    }
  }
  return mesh;
}

TriangleMesh coil(int turns, int segments, int sides, double wire) {
  TriangleMesh mesh;
  const int steps = turns * segments;
  mesh.name = "coil (" + std::to_string(2 * steps * sides) + " triangles)";
  const double around = 2.0 * kPiD * turns;  // the helix's angle at s in [0, 1] is around * s
  for (int i = 0; i <= steps; ++i) {
    const double s = double(i) / steps, angle = around * s;
    const DVec3 centre(std::cos(angle), -1.0 + 2.0 * s, std::sin(angle));
    const DVec3 tangent = glm::normalize(DVec3(-std::sin(angle) * around, 2.0, std::cos(angle) * around));
    const DVec3 outward(std::cos(angle), 0.0, std::sin(angle));  // perpendicular to the tangent
    const DVec3 across = glm::cross(tangent, outward);
    for (int j = 0; j < sides; ++j) {
      const double phi = 2.0 * kPiD * j / sides;
      mesh.positions.push_back(Point3(centre + wire * (std::cos(phi) * outward + std::sin(phi) * across)));
    }
  }
  auto at = [sides](int i, int j) { return uint32_t(i * sides + j % sides); };
  // Counter-clockwise seen from outside the wire.
  for (int i = 0; i < steps; ++i) {
    for (int j = 0; j < sides; ++j) {
      mesh.triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i + 1, j));
      mesh.triangles.emplace_back(at(i, j), at(i, j + 1), at(i + 1, j + 1));
    }
  }
  return mesh;
}

Scene scanLikeScene() {
  Scene scene;
  scene.materials.push_back(Material{.name = "default"});
  scene.meshes.push_back(bumpySphere(128, 256, 0.075, DVec3(-0.02, 0.1, 0.0), DVec3(1.0, 0.8, 0.65)));
  scene.meshes[0].name = "scan-like mesh (65,024 triangles, 0.15 units across)";
  scene.indexPrimitives();
  return scene;
}

Scene veachPlatesScene(const PlatesSetup& setup) {
  Scene scene;
  scene.camera = Camera{Point3(0, 2, 15), Point3(0, -2, 2.5f), Vec3(0, 1, 0), 28.0f};
  const Point3 corners[4] = {{-4, -1.0588f, 2.7971f}, {-4, -1.8032f, 3.8976f}, {-4, -2.5899f, 4.8987f}, {-4, -3.4226f, 5.7996f}};
  const Vec3 slopes[4] = {{0, 0.1177f, -1.1942f}, {0, 0.1063f, -1.1953f}, {0, 0.0799f, -1.1973f}, {0, 0.0453f, -1.1991f}};
  for (int i = 0; i < 4; ++i) {
    scene.materials.push_back(Material{.name = "plate " + std::to_string(i), .type = MaterialType::RoughConductor,
                                       .albedo = Color(0.9f), .roughness = setup.roughness[i]});
    TriangleMesh plate;
    plate.name = scene.materials.back().name;
    const Point3 c = corners[i];
    const Vec3 u(8, 0, 0), v = slopes[i];
    plate.positions = {c, c + u, c + u + v, c + v};
    plate.triangles = {{0, 1, 2}, {0, 2, 3}};
    plate.material = uint32_t(i);
    scene.meshes.push_back(plate);
  }
  const float x[4] = {-3.75f, -1.25f, 1.25f, 3.75f};
  for (int j = 0; j < 4; ++j) {
    const float r = setup.radius[j];
    scene.materials.push_back(Material{.name = "light " + std::to_string(j), .albedo = Color(0.0f),
                                       .emission = Color(0.8f / (r * r))});  // equal power
    scene.spheres.push_back(Sphere{Point3(x[j], 0, 0), r, uint32_t(4 + j)});
  }
  return scene;
}

}  // namespace pathlab
