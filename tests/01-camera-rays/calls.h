// Task 1's remote calls: the judge's view of the student's camera_rays.cpp.
// Tests call candidate::generateCameraRay(...) exactly as they would call
// generateCameraRay(...); the candidate process computes the answer.
#pragma once

#include "wire/call.h"
#include "tasks/camera_rays.h"

namespace pathlab::calls {
PATHLAB_REMOTE_CALL(PixelSamplePosition, 1, shape::Fixed, Point2(IVec2, Vec2));
PATHLAB_REMOTE_CALL(CameraBasisOf, 2, shape::Fixed, CameraBasis(Camera));
PATHLAB_REMOTE_CALL(GenerateCameraRay, 3, shape::Fixed, Ray(Camera, CameraBasis, Point2, IVec2));
}  // namespace pathlab::calls

namespace pathlab::candidate {
inline Point2 pixelSamplePosition(IVec2 pixel, Vec2 u) { return remote::call<calls::PixelSamplePosition>(pixel, u); }
inline CameraBasis cameraBasis(const Camera& camera) { return remote::call<calls::CameraBasisOf>(camera); }
inline Ray generateCameraRay(const Camera& camera, const CameraBasis& basis, Point2 raster, IVec2 resolution) {
  return remote::call<calls::GenerateCameraRay>(camera, basis, raster, resolution);
}
}  // namespace pathlab::candidate
