// Task @N@ — @TITLE@. Implemented in tasks/@FOLDER@/@STEM@.cpp (the student's
// file; where the task is not the student's, the programs link the course's
// reference in its place).
//
// Written from the task template: a uniform point on a triangle, a worked
// example of every file a task has. Replace it with your
// own functions; keep each contract here, where the tests read it too.
#pragma once

#include "util/math.h"

// The task's functions live in a namespace of their own, so that no name
// can clash with another task's.
namespace pathlab::@STEM@ {

// T@N@.1: a point uniform over the triangle (0, 0), (1, 0), (0, 1) (density 2
// per unit area), from a uniform random point u in [0,1)^2. Any map that is
// uniform will do.
Point2 sampleTriangle(Vec2 u);

}  // namespace pathlab::@STEM@
