// Scenes built in code for the suites: only the objects a test needs.
#pragma once

#include <string>

#include "check.h"
#include "scene/procedural.h"
#include "core/scene.h"
#include "scene/scene_io.h"

namespace pathlab::test {

// `triangles` random triangles (size ~ scale / 10) and `spheres` spheres
// scattered in a cube of half-size `scale` around `offset`.
inline Scene randomScene(Random& random, int triangles, int spheres, double scale, DVec3 offset = DVec3(0.0)) {
  Scene scene;
  scene.materials.push_back(Material{.name = "default"});
  TriangleMesh mesh;
  for (int i = 0; i < triangles; ++i) {
    DVec3 center = offset + random.inCube(scale);
    for (int k = 0; k < 3; ++k) mesh.positions.push_back(Point3(center + random.inCube(scale * 0.1)));
    mesh.triangles.emplace_back(3 * i, 3 * i + 1, 3 * i + 2);
  }
  if (triangles > 0) scene.meshes.push_back(std::move(mesh));
  for (int i = 0; i < spheres; ++i) {
    scene.spheres.push_back(Sphere{Point3(offset + random.inCube(scale)), float(scale * random.uniform(0.01, 0.08)), 0});
  }
  scene.indexPrimitives();
  return scene;
}

}  // namespace pathlab::test
