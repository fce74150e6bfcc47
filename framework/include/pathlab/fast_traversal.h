// The framework's traversal of task 3's tree for rendering (--accel fast):
// the model answer's ordered walk with both children's boxes tested at once
// in SIMD lanes. Same hits as task 3's model answer, in the same order; the
// tree must have passed validateBvh (accelerator.h).
#pragma once

#include <optional>

#include "pathlab/leaf_geometry.h"
#include "pathlab/tasks/bvh.h"

namespace pathlab {

std::optional<PrimitiveHit> fastIntersectClosest(const Bvh& bvh, const LeafGeometry& geometry, const Ray& ray,
                                                 Interval range);
bool fastIntersectAny(const Bvh& bvh, const LeafGeometry& geometry, const Ray& ray, Interval range);

}  // namespace pathlab
