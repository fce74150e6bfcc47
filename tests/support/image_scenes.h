// Building blocks of the image tests' scenes (image_test.h): scenes written
// as the JSON a user would write, meshes with vertex normals, and small
// environment maps made in code.
#pragma once

#include <cmath>
#include <string>

#include "meshes.h"
#include "scene/scene_io.h"

namespace pathlab::test {

// A scene from the JSON scene format (docs/scene-format.md).
inline Scene sceneFromJson(const std::string& json, const std::string& name) {
  return loadSceneFromJson(json, name, ".");
}

// An icosphere whose vertex normals point away from `center`: the shading
// normal varies smoothly across each flat triangle.
inline TriangleMesh smoothSphere(int subdivisions, Point3 center, float radius, uint32_t material) {
  TriangleMesh mesh = icosphere(subdivisions, center, radius);
  for (const Point3& p : mesh.positions) mesh.normals.push_back(glm::normalize(p - center));
  mesh.material = material;
  return mesh;
}

inline uint32_t materialIndex(const Scene& scene, const std::string& name) {
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (scene.materials[i].name == name) return uint32_t(i);
  }
  throw std::runtime_error("no material " + name);
}

// A small sky: a blue gradient from the zenith to a darker ground, and a sun
// of `sunRadiance` covering a few pixels at (sunU, sunV).
inline Image skyMap(int width, int height, float sunU, float sunV, float sunRadiance) {
  Image map(width, height);
  for (int y = 0; y < height; ++y) {
    const float v = (y + 0.5f) / float(height);
    const Color sky = v < 0.5f ? Color(0.35f, 0.5f, 0.9f) * (1.2f - v) : Color(0.25f, 0.22f, 0.2f);
    for (int x = 0; x < width; ++x) map.at(x, y) = sky;
  }
  const int sx = int(sunU * width), sy = int(sunV * height);
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) map.at((sx + dx) % width, std::min(height - 1, sy + dy)) = Color(sunRadiance);
  return map;
}

// The course's Cornell box (media/scenes/cornell-*.json) at image-test size:
// a ceiling light, red and blue walls, and two spheres that are diffuse, or
// a mirror and a glass sphere.
inline Scene cornellBox(int width, int height, int spp, int maxDepth, bool mirrorAndGlass) {
  const std::string spheres = mirrorAndGlass ? "\"mirror\"" : "\"ball\"";
  const std::string second = mirrorAndGlass ? "\"glass\"" : "\"ball\"";
  Scene scene = sceneFromJson(R"({
    "camera": { "position": [0, 0.75, 3.1], "look_at": [0, 0.75, 0], "up": [0, 1, 0], "vfov": 38 },
    "materials": {
      "white": { "albedo": [0.6, 0.6, 0.6] },
      "red":   { "albedo": [0.6, 0.2, 0.2] },
      "blue":  { "albedo": [0.2, 0.2, 0.6] },
      "ball":  { "albedo": [0.8, 0.8, 0.8] },
      "mirror": { "type": "mirror", "reflectance": [0.95, 0.95, 0.95] },
      "glass":  { "type": "glass", "reflectance": [1, 1, 1], "transmittance": [1, 1, 1], "ior": 1.45 },
      "light": { "albedo": [0.8, 0.8, 0.8], "emission": [10, 10, 10] }
    },
    "meshes": [
      { "name": "floor",     "material": "white", "quad": { "corner": [-1, 0, 1],    "edge_u": [2, 0, 0],  "edge_v": [0, 0, -2] } },
      { "name": "ceiling",   "material": "white", "quad": { "corner": [-1, 1.5, -1], "edge_u": [2, 0, 0],  "edge_v": [0, 0, 2] } },
      { "name": "back wall", "material": "white", "quad": { "corner": [-1, 0, -1],   "edge_u": [2, 0, 0],  "edge_v": [0, 1.5, 0] } },
      { "name": "left wall", "material": "red",   "quad": { "corner": [-1, 0, 1],    "edge_u": [0, 0, -2], "edge_v": [0, 1.5, 0] } },
      { "name": "right wall","material": "blue",  "quad": { "corner": [1, 0, -1],    "edge_u": [0, 0, 2],  "edge_v": [0, 1.5, 0] } },
      { "name": "light",     "material": "light", "quad": { "corner": [-0.4, 1.49, -0.3], "edge_u": [0.8, 0, 0], "edge_v": [0, 0, 0.6] } }
    ],
    "spheres": [
      { "center": [0.4, 0.3, 0.3],   "radius": 0.3, "material": )" + second + R"( },
      { "center": [-0.4, 0.3, -0.3], "radius": 0.3, "material": )" + spheres + R"( }
    ]
  })", "cornell box");
  scene.render.width = width;
  scene.render.height = height;
  scene.render.samplesPerPixel = spp;
  scene.render.maxDepth = maxDepth;
  return scene;
}

}  // namespace pathlab::test
