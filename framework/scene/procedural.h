// Geometry made in code, so tests and benchmarks need no data files.
#pragma once

#include "core/scene.h"

namespace pathlab {

// A closed, bumpy sphere: `rings` bands of `segments` quads, closed at each
// pole by a fan (2 (rings - 1) segments triangles, no degenerate ones),
// about `radius` from `center`, scaled per axis by `stretch`.
TriangleMesh bumpySphere(int rings, int segments, double radius = 1.0, glm::dvec3 center = glm::dvec3(0.0),
                         glm::dvec3 stretch = glm::dvec3(1.0));

// A coiled wire: a helix of radius 1 around the y axis from y = -1 to 1,
// `turns` turns of `segments` steps each, wrapped in an open tube of `sides`
// sides and radius `wire`: 2 turns segments sides long, thin triangles
// (at wire 0.01, 8 sides and 32 segments, 25 times longer than wide).
TriangleMesh coil(int turns, int segments, int sides, double wire);

// A stand-in for a scanned model with the Stanford bunny's hard properties:
// 65,024 triangles about 1.5e-3 across (so |det| in Moller-Trumbore is
// ~1e-6), closed, 0.15 units across and off the origin, slivers at the poles.
// One diffuse material; primitives indexed.
Scene scanLikeScene();

// Veach's plates, the task 9 scene (media/scenes/veach-plates.json without
// its floor and wall): four rough-metal plates (F0 0.9), each tilted to
// mirror the camera into a row of four spherical lights of equal power.
// Plate i (material i, the first four) has roughness[i], top to bottom;
// light j (sphere j, material 4 + j) radius[j], left to right.
struct PlatesSetup {
  float roughness[4] = {0.08f, 0.15f, 0.25f, 0.35f};
  float radius[4] = {0.033f, 0.1f, 0.3f, 0.9f};
};
Scene veachPlatesScene(const PlatesSetup& setup = {});

}  // namespace pathlab
