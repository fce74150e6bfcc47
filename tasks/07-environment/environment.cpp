// Task 7 — environment lighting with importance sampling
//
// Goal: light from a photograph of the sky (an equirectangular map) — and
// sampling it where it is bright, so a small sun does not drown the image in
// noise. Handout: tasks/07-environment/README.md
//
// Functions to write (declared in framework/tasks/environment.h,
// which also states the map's conventions):
//   T7.1 directionToEquirect, equirectToDirection   the map's coordinates
//   T7.2 lookupEnvironment                           bilinear lookup, wrapping at the seam
//   T7.3 sampleUniformSphere                         the baseline strategy
//   T7.4 buildEnvironmentDistribution                marginal and conditional CDFs
//   T7.5 sampleEnvironment, environmentPdf           importance sampling and its pdf
//
// Check your work:
//   ./build/pathlab media/scenes/sky-spheres.json -o sky.png
//   ./build/pathlab debug --task 7 --view samples media/scenes/sky-spheres.json -o samples.png
//   ctest --test-dir build -R 07-environment --output-on-failure
#include "tasks/environment.h"

#include <algorithm>
#include <cmath>

#include "util/todo.h"

namespace pathlab {

// T7.1 — Spherical coordinates of the map (y is up):
//   theta = atan2(sqrt(w.x^2 + w.z^2), w.y),  phi = atan2(w.z, w.x) moved into [0, 2 pi),
//   u = phi / (2 pi),   v = theta / pi;
// and back: w = (sin(theta) cos(phi), cos(theta), sin(theta) sin(phi)).
// PITFALL: not theta = acos(w.y). Near a pole w.y = cos(theta) = 1 - theta^2 / 2
// is 1 to within float rounding: below theta = 3.45e-4 it rounds to exactly 1
// (theta reads 0, the pdf 0), and below about 5e-3 sin(theta) is off by more
// than 0.1 %. The horizontal length sqrt(x^2 + z^2) = sin(theta) keeps its digits.
// PITFALL: phi + 2 pi rounds to exactly 2 pi for a phi just below 0 (u = 1):
// keep u below 1: min(u, the largest float below 1), or wrap a u of 1 to 0
// (u is periodic: both name the seam's meridian).
Point2 directionToEquirect(const Vec3& direction) {
  // TODO(T7.1): direction -> (u, v).
  PATHLAB_TODO("T7.1");
  (void)direction;
  return Point2(0.0f);
}

Vec3 equirectToDirection(Point2 uv) {
  // TODO(T7.1): (u, v) -> direction.
  PATHLAB_TODO("T7.1");
  (void)uv;
  return Vec3(0.0f, 1.0f, 0.0f);
}

// T7.2 — Bilinear lookup. Pixel centres sit at ((i + 0.5) / W, (j + 0.5) / H):
//   x = u W - 0.5,  y = v H - 0.5,  x0 = floor(x), tx = x - x0 (same for y);
//   blend the four pixels (x0, y0), (x0 + 1, y0), (x0, y0 + 1), (x0 + 1, y0 + 1).
// PITFALL: columns wrap around (x0 = -1 is the last column, x0 + 1 = W the
// first): the seam at u = 0 must be invisible. Rows clamp to [0, H - 1].
Color lookupEnvironment(const Image& map, const Vec3& direction) {
  // TODO(T7.2): bilinear lookup with wrapping.
  PATHLAB_TODO("T7.2");
  (void)map, (void)direction;
  return Color(0.0f);
}

// T7.3 — Uniform directions on the sphere: z = 1 - 2 u.x is uniform in
// [-1, 1] (Archimedes: equal heights, equal areas), phi = 2 pi u.y, and
// (r cos(phi), r sin(phi), z) with r = sqrt(1 - z^2). pdf = 1 / (4 pi).
Vec3 sampleUniformSphere(Vec2 u) {
  // TODO(T7.3): a uniform direction.
  PATHLAB_TODO("T7.3");
  (void)u;
  return Vec3(0.0f, 1.0f, 0.0f);
}

// T7.4 — The importance distribution.
//
// We want directions with probability proportional to the light they bring:
// weight(i, j) = luminance(pixel(i, j)) * sin(theta_j), theta_j = pi (j + 0.5) / H.
// The sin(theta) is there because a pixel near a pole covers less solid angle
// (a row's pixels shrink to a point at the pole).
//
// Recipe:
//   1. For every row j, the running sums of its weights, normalised:
//      conditionalCdf[j (W + 1) + i] = (sum of weights of pixels 0..i-1) / (row sum);
//      a row with sum 0 gets the uniform CDF i / W.
//   2. marginalCdf[j] = (sum of the row sums of rows 0..j-1) / (total), with
//      marginalCdf[H] = 1; all zero for a black map.
//   3. totalWeight = the total (0 means: nothing to sample).
// PITFALL: accumulate in double; a sun can be 10^5 times brighter than the sky.
EnvironmentDistribution buildEnvironmentDistribution(const Image& map) {
  // TODO(T7.4): the marginal and conditional CDFs.
  PATHLAB_TODO("T7.4");
  EnvironmentDistribution distribution;
  distribution.width = map.width;
  distribution.height = map.height;
  return distribution;
}

// T7.5 — Sampling by inversion, and the pdf.
//
//   1. Row j: the interval of marginalCdf containing u.y (binary search,
//      std::upper_bound); its width is P(row j).
//   2. Column i: the interval of row j's CDF containing u.x; width P(i | j).
//   3. A uniform point in the pixel: du = (u.x - cdf_i) / width (reuse the
//      random number), likewise dv; (u, v) = ((i + du) / W, (j + dv) / H).
//   4. p(u, v) = P(j) P(i | j) W H is the density over the unit square. The
//      map (u, v) -> direction stretches areas by dw = 2 pi^2 sin(theta) du dv,
//      so pdfSolidAngle = p(u, v) / (2 pi^2 sin(theta)), theta = pi v.
// Return nothing when totalWeight is 0, or when sin(theta) is 0 (a pole).
// environmentPdf(w): steps 4 for the pixel that contains w's (u, v).
// PITFALL: never choose an interval of zero width (its pdf would be 0 and
// the estimate Inf).
std::optional<EnvironmentSample> sampleEnvironment(const EnvironmentDistribution& distribution, Vec2 u) {
  // TODO(T7.5): invert the CDFs.
  PATHLAB_TODO("T7.5");
  (void)distribution, (void)u;
  return std::nullopt;
}

float environmentPdf(const EnvironmentDistribution& distribution, const Vec3& direction) {
  // TODO(T7.5): the pdf of the sampler above.
  PATHLAB_TODO("T7.5");
  (void)distribution, (void)direction;
  return 0.0f;
}

}  // namespace pathlab
