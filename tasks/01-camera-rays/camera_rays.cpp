// Task 1 — camera rays
//
// Goal: turn a pixel and two random numbers into the ray a pinhole camera
// sees through that point of the image. Handout: tasks/01-camera-rays/README.md
//
// Functions to write (declared in framework/tasks/camera_rays.h):
//   T1.1 pixelSamplePosition   a jittered point inside a pixel
//   T1.2 cameraBasis           the camera's orthonormal frame
//   T1.3 generateCameraRay     the ray through a raster position
//
// Check your work:
//   ./build/pathlab debug --task 1 --view directions -o directions.png
//   ./build/pathlab debug --task 1 --view samples -o samples.png
//   ctest --test-dir build -R 01-camera-rays --output-on-failure
#include "tasks/camera_rays.h"

#include <cmath>

#include "util/todo.h"

namespace pathlab {

// T1.1 — A sample position inside a pixel.
//
// Raster space has x to the right and y down; pixel (i, j) is the square
// [i, i+1) x [j, j+1). Averaging many samples spread uniformly over the
// square estimates the pixel's mean radiance (a box filter), which is what
// removes jagged edges.
//
//   u is uniform in [0, 1)^2   ->   return a point uniform over the square.
//
// PITFALL: (i + 0.5, j + 0.5) is the pixel centre; using it for every sample
// gives a correct but aliased image, and the tests check the spread.
Point2 pixelSamplePosition(IVec2 pixel, Vec2 u) {
  // TODO(T1.1): map u onto the pixel's square.
  PATHLAB_TODO("T1.1");
  (void)u;
  return Point2(pixel);
}

// T1.2 — The camera frame.
//
//   forward = normalize(lookAt - position)
//   right   = normalize(forward x up)
//   up'     = right x forward          (unit: right and forward are orthonormal)
//
// camera.up only says which way is "up" on the image; it need not be
// perpendicular to forward, so re-orthogonalise as above. Nor need it be a
// unit vector (an up 1e-6 long is as good as any): normalise it first.
//
// PITFALL: when camera.up is parallel to forward (looking straight down with
// up = +y), forward x up is the zero vector and normalize() returns NaN.
// Detect it (|forward x unit up| tiny) and use any other vector perpendicular to
// forward instead; the tests accept any orthonormal frame in that case.
CameraBasis cameraBasis(const Camera& camera) {
  // TODO(T1.2): build forward, right, up as described above.
  PATHLAB_TODO("T1.2");
  (void)camera;
  return CameraBasis{};
}

// T1.3 — The primary ray through raster position `raster`.
//
// 1. Normalised device coordinates, in [-1, 1] across the image:
//      ndcX = 2 * raster.x / width - 1
//      ndcY = 1 - 2 * raster.y / height     (raster y grows downwards)
// 2. The image plane sits at distance 1 along forward. Its half-height is
//      tan(vfov / 2)       (vfov is in degrees: glm::radians converts)
//    and its half-width is aspect * tan(vfov / 2), with aspect = width / height.
// 3. direction = normalize(forward + ndcX * halfWidth * right + ndcY * halfHeight * up)
// 4. The ray starts at the camera position.
//
// PITFALL: width / height on ints is integer division.
Ray generateCameraRay(const Camera& camera, const CameraBasis& basis, Point2 raster, IVec2 resolution) {
  // TODO(T1.3): compute the direction through `raster` and return the ray.
  PATHLAB_TODO("T1.3");
  (void)raster;
  (void)resolution;
  return Ray{camera.position, basis.forward};
}

}  // namespace pathlab
