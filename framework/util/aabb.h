// Axis-aligned bounding boxes.
#pragma once

#include "util/math.h"

namespace pathlab {

struct Aabb {
  Point3 min{kInfinity};   // an empty box: min > max on every axis
  Point3 max{-kInfinity};

  void grow(const Point3& p) { min = glm::min(min, p), max = glm::max(max, p); }
  void grow(const Aabb& b) { min = glm::min(min, b.min), max = glm::max(max, b.max); }
  bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  Point3 centroid() const { return 0.5f * (min + max); }
  Vec3 extent() const { return max - min; }
  // Surface area; 0 for an empty box. The SAH's probability of a hit.
  float surfaceArea() const {
    if (isEmpty()) return 0.0f;
    Vec3 e = extent();
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  bool contains(const Aabb& b) const {
    return b.min.x >= min.x && b.min.y >= min.y && b.min.z >= min.z && b.max.x <= max.x && b.max.y <= max.y &&
           b.max.z <= max.z;
  }
  int largestAxis() const {
    Vec3 e = extent();
    return (e.x >= e.y && e.x >= e.z) ? 0 : (e.y >= e.z ? 1 : 2);
  }
};

}  // namespace pathlab
