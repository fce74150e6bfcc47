// Task 7 — environment lighting with importance sampling. Implemented in
// tasks/07-environment/environment.cpp (the student's file; where the task is
// not the student's, the programs link the course's reference in its place).
//
// Equirectangular maps, +y up: a direction w has
//   theta = atan2(sqrt(w.x^2 + w.z^2), w.y) in [0, pi]   (0 at the zenith, row 0
//           of the image; the same angle as acos(w.y), which loses it near the poles)
//   phi   = atan2(w.z, w.x) in [0, 2 pi)
//   (u, v) = (phi / (2 pi), theta / pi),   pixel (i, j) covers
//   u in [i/W, (i+1)/W), v in [j/H, (j+1)/H).
#pragma once

#include <optional>
#include <vector>

#include "core/environment_distribution.h"
#include "util/image.h"
#include "util/math.h"

namespace pathlab {

// T7.1: direction <-> (u, v) in [0, 1)^2 (u wraps around; v = 0 at the zenith).
Point2 directionToEquirect(const Vec3& direction);
Vec3 equirectToDirection(Point2 uv);

// T7.2: radiance from `map` along a unit direction: bilinear between the four
// nearest pixel centres, wrapping around in u (the seam) and clamping in v.
Color lookupEnvironment(const Image& map, const Vec3& direction);

// T7.3: a uniformly distributed direction on the unit sphere (pdf 1 / (4 pi)).
Vec3 sampleUniformSphere(Vec2 u);

// EnvironmentDistribution (the map's marginal and conditional CDFs) and
// EnvironmentSample are core data: core/environment_distribution.h.

// T7.4: the distribution of `map`.
EnvironmentDistribution buildEnvironmentDistribution(const Image& map);

// T7.5: a direction drawn from the distribution with u in [0,1)^2 (rows by
// the marginal CDF, then a column by the row's CDF, both by binary search,
// then a uniform point inside the pixel), with its solid-angle pdf
// p(u, v) / (2 pi^2 sin(theta)); nothing for a black map or a pole.
std::optional<EnvironmentSample> sampleEnvironment(const EnvironmentDistribution& distribution, Vec2 u);

// T7.5: the solid-angle pdf of sampleEnvironment choosing `direction`.
float environmentPdf(const EnvironmentDistribution& distribution, const Vec3& direction);

}  // namespace pathlab
