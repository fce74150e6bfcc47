// The geometry of every primitive copied into one flat array, in the order
// of a BVH's leaves, so a leaf's primitives sit next to each other in memory.
// A traversal tests "slot" i of a leaf; the hit names the scene primitive.
// The tests themselves are task 2's, handed in as a PrimitiveTests table
// (task_functions.h), so this core type depends on no task.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/hit.h"
#include "core/scene.h"
#include "core/task_functions.h"
#include "util/aabb.h"

namespace pathlab {

// Task 2's tests as the framework calls them (the leaves here, brute force in
// scene_intersect.cpp): the hit of scene primitive `primitive`, and never an
// answer outside `range`, whatever the task code returned.
inline std::optional<PrimitiveHit> sphereHit(const PrimitiveTests& tests, const Ray& ray, Interval range,
                                             const Point3& center, float radius, uint32_t primitive) {
  const std::optional<float> t = tests.intersectSphere(ray, range, center, radius);
  if (!t || !range.contains(*t)) return std::nullopt;
  return PrimitiveHit{*t, 0.0f, 0.0f, primitive};
}

inline std::optional<PrimitiveHit> triangleHit(const PrimitiveTests& tests, const Ray& ray, Interval range,
                                               const Point3& p0, const Point3& p1, const Point3& p2,
                                               uint32_t primitive) {
  const std::optional<TriangleHit> hit = tests.intersectTriangle(ray, range, p0, p1, p2);
  if (!hit || !range.contains(hit->t)) return std::nullopt;
  return PrimitiveHit{hit->t, hit->b1, hit->b2, primitive};
}

class LeafGeometry {
 public:
  LeafGeometry() = default;
  // Slot i holds scene primitive order[i]; `tests` are task 2's (kLinkedTasks.primitives).
  LeafGeometry(const Scene& scene, std::span<const uint32_t> order, const PrimitiveTests& tests);

  // 48 bytes: a triangle's three vertices, or a sphere's centre (a) and radius (b.x).
  struct Slot {
    Point3 a;            // 12
    uint32_t primitive;  //  4: index into Scene::primitives
    Point3 b;            // 12
    uint32_t isSphere;   //  4
    Point3 c;            // 12
    uint32_t unused;     //  4
  };
  static_assert(sizeof(Slot) == 48);

  uint32_t size() const { return uint32_t(slots_.size()); }
  const Slot& slot(uint32_t i) const { return slots_[i]; }

  // The debugger's record of a traversal: when set, every slot tested is
  // appended in the order the traversal tests it.
  void recordTests(std::vector<uint32_t>* log) { testLog_ = log; }

  // The hit of `ray` with the primitive in `slot`, within `range` (task 2's tests).
  std::optional<PrimitiveHit> intersect(uint32_t slot, const Ray& ray, Interval range) const {
    if (testLog_) [[unlikely]] testLog_->push_back(slot);
    const Slot& s = slots_[slot];
    return s.isSphere ? sphereHit(tests_, ray, range, s.a, s.b.x, s.primitive)
                      : triangleHit(tests_, ray, range, s.a, s.b, s.c, s.primitive);
  }

 private:
  std::vector<Slot> slots_;
  PrimitiveTests tests_;
  std::vector<uint32_t>* testLog_ = nullptr;
};

// Bounds of every scene primitive, indexed like Scene::primitives.
std::vector<Aabb> primitiveBounds(const Scene& scene);

}  // namespace pathlab
