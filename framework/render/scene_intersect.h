// Scene-level ray queries built on task 2's primitive tests. The brute-force
// loop is the ground truth that task 3's BVH is tested against.
#pragma once

#include <optional>

#include "core/hit.h"
#include "core/scene.h"
#include "util/ray.h"

namespace pathlab {

std::optional<PrimitiveHit> intersectPrimitive(const Scene& scene, uint32_t primitive,
                                               const Ray& ray, Interval range);

// Completes a primitive hit into the full record (point, normals, material).
Hit surfaceHit(const Scene& scene, const Ray& ray, const PrimitiveHit& hit);

// Closest hit over every primitive: O(n) per ray.
std::optional<Hit> intersectBruteForce(const Scene& scene, const Ray& ray, Interval range);

}  // namespace pathlab
