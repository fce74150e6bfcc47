// Task 10 — a thin-lens camera: depth of field. Implemented in
// tasks/10-thin-lens/thin_lens.cpp (the student's file; where the task is not
// the student's, the programs link the course's reference in its place).
#pragma once

#include "core/camera.h"
#include "tasks/camera_rays.h"
#include "util/math.h"
#include "util/ray.h"

namespace pathlab {

// T10.1: a point uniform over the unit disk (density 1/pi per unit area)
// from a uniform random point u in [0,1)^2: the polar map or Shirley and
// Chiu's concentric map; any map that is uniform will do.
Point2 sampleUnitDisk(Vec2 u);

// T10.2: the ray a thin lens sees through the same film point as
// `pinholeRay` (task 1's ray for that raster position: origin
// camera.position, unit direction). Its origin is a point of the lens, a
// disk of radius camera.apertureRadius centred on camera.position and
// spanned by basis.right and basis.up, chosen by sampleUnitDisk(uLens); its
// unit direction aims at the point where the pinhole ray meets the plane of
// focus (perpendicular to basis.forward, camera.focalDistance in front of
// the lens). Every lens point then sees that point in focus.
Ray generateThinLensRay(const Camera& camera, const CameraBasis& basis, const Ray& pinholeRay, Vec2 uLens);

}  // namespace pathlab
