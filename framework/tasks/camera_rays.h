// Task 1 — camera rays. Implemented in tasks/01-camera-rays/camera_rays.cpp
// (the student's file; where the task is not the student's, the programs
// link the course's reference in its place).
#pragma once

#include "core/camera.h"
#include "util/math.h"
#include "util/ray.h"

namespace pathlab {

// Raster space: x to the right, y down, pixel (i, j) covers [i, i+1) x [j, j+1),
// the image covers [0, width] x [0, height].

// T1.1: a sample position inside `pixel`, from a uniform random point u in [0,1)^2.
Point2 pixelSamplePosition(IVec2 pixel, Vec2 u);

// The camera's orthonormal, right-handed frame in world space.
struct CameraBasis {
  Vec3 forward{0.0f, 0.0f, -1.0f};  // unit, from the position towards lookAt
  Vec3 right{1.0f, 0.0f, 0.0f};     // unit, forward x up
  Vec3 up{0.0f, 1.0f, 0.0f};        // unit, right x forward: "up" on the image
};

// T1.2: the camera frame, also when camera.up is parallel to the view direction.
CameraBasis cameraBasis(const Camera& camera);

// T1.3: the primary ray through raster position `raster` of an image of
// `resolution` pixels: origin at the camera, unit direction.
Ray generateCameraRay(const Camera& camera, const CameraBasis& basis, Point2 raster,
                      IVec2 resolution);

}  // namespace pathlab
