// Task 10 — a thin-lens camera
//
// Goal: depth of field. Task 1's pinhole sees everything sharp; a real lens
// gathers light over an aperture and is sharp at one distance only. Here
// each camera ray starts at a random point of the lens and aims at the point
// the pinhole ray finds on the plane of focus. Handout:
// tasks/10-thin-lens/README.md
//
// Functions to write (declared in framework/tasks/thin_lens.h):
//   T10.1 sampleUnitDisk        a uniform point on the unit disk
//   T10.2 generateThinLensRay   the ray through the lens and the point in focus
//
// Check your work:
//   ./build/pathlab media/scenes/depth-of-field.json -o dof.png
//   ./build/pathlab debug --task 10 --view confusion media/scenes/depth-of-field.json -o confusion.png
//   ctest --test-dir build -R 10-thin-lens --output-on-failure
#include "tasks/thin_lens.h"

#include <cmath>

#include "util/todo.h"

namespace pathlab {

// T10.1 — A uniform point on the unit disk.
//
// Uniform means equal areas of the disk get equal shares of the samples:
// density 1/pi per unit area. In polar coordinates dA = r dr dphi, so the
// radius r is not uniform: its density is 2r on [0, 1], whose CDF is r^2.
// Inverting it:
//   polar map       r = sqrt(u.x),  phi = 2 pi u.y,  p = r (cos phi, sin phi)
// or Shirley and Chiu's concentric map, which sends each square ring of
// [-1, 1]^2 onto a ring of the disk (strata of u stay compact on the lens):
//   a = 2 u - 1;  if a = (0, 0) return (0, 0)
//   |a.x| > |a.y|:  r = a.x,  phi = (pi/4) a.y / a.x
//   otherwise:      r = a.y,  phi = pi/2 - (pi/4) a.x / a.y
//   p = r (cos phi, sin phi)
//
// PITFALL: r = u.x crowds the samples at the centre (a disk's outer ring
// holds most of its area); the lens then blurs too little, and the
// out-of-focus disks glow in the middle.
Point2 sampleUnitDisk(Vec2 u) {
  // TODO(T10.1): a uniform point on the unit disk.
  PATHLAB_TODO("T10.1");
  (void)u;
  return Point2(0.0f);
}

// T10.2 — The ray through the thin lens.
//
// The lens is a disk of radius A = camera.apertureRadius around
// camera.position, in the plane spanned by basis.right and basis.up. The
// plane of focus lies F = camera.focalDistance in front of it: the points x
// with dot(x - camera.position, basis.forward) = F. An ideal thin lens
// bends every ray from one film point through one point of that plane: the
// point the ray through the lens's centre (the pinhole ray) reaches there.
//   1. the point in focus: p = o + t d, with t such that p lies on the
//      plane: t = F / dot(d, forward)   (o, d: the pinhole ray's)
//   2. the lens point: (x, y) = A sampleUnitDisk(uLens), then in world
//      space  l = camera.position + x right + y up
//   3. the ray: origin l, direction normalize(p - l).
// With A = 0 this is the pinhole ray again.
//
// PITFALL: F is measured along the view axis, not along each ray (t = F
// would focus on a sphere, and the edges of the image would blur); (x, y,
// 0) is a point in the camera's frame, not in the world; and moving the
// origin without aiming the ray at p shifts the image instead of blurring it.
Ray generateThinLensRay(const Camera& camera, const CameraBasis& basis, const Ray& pinholeRay, Vec2 uLens) {
  // TODO(T10.2): a ray from a point of the lens through the point in focus.
  PATHLAB_TODO("T10.2");
  (void)camera, (void)basis, (void)uLens;
  return pinholeRay;
}

}  // namespace pathlab
