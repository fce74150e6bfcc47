// Task @N@ — @TITLE@
//
// Goal: a uniform point on a triangle (the template's example: replace it
// with your course's task). Handout: tasks/@FOLDER@/README.md
//
// Functions to write (declared in framework/tasks/@STEM@.h):
//   T@N@.1 sampleTriangle   a uniform point on the triangle (0, 0), (1, 0), (0, 1)
//
// Check your work:
//   ./build/pathlab debug --task @N@ --view triangle -o triangle.png
//   ./build/pathlab lab @WARP@ -o @WARP@.png
//   ctest --test-dir build -R @FOLDER@ --output-on-failure
#include "tasks/@STEM@.h"

#include <cmath>

#include "util/todo.h"

namespace pathlab::@STEM@ {

// T@N@.1 — A uniform point on the triangle (0, 0), (1, 0), (0, 1).
//
// Uniform means equal areas get equal shares: density 2 (the triangle's area
// is 1/2). Slice the triangle by lines x = 1 - s: the slice at s has length
// s, so s has density 2s on [0, 1], whose CDF is s^2. Inverting it:
//   s = sqrt(u.x),  p = (1 - s, s u.y)
// or fold the square: p = u, and if u.x + u.y > 1, p = (1 - u.x, 1 - u.y).
//
// PITFALL: s = u.x gives every slice the same share of the points, so the
// short slices near the corner (1, 0) crowd: a slice's share must be its
// length.
Point2 sampleTriangle(Vec2 u) {
  // TODO(T@N@.1): a uniform point on the triangle.
  PATHLAB_TODO("T@N@.1");
  (void)u;
  return Point2(0.0f);
}

}  // namespace pathlab::@STEM@
