// Task @N@ — @TITLE@. Implemented in tasks/@FOLDER@/@STEM@.cpp (the student's
// file; where the task is not the student's, the programs link the course's
// reference in its place).
//
// Written from the worked example "cone-light" (new-task --from cone-light): a
// sphere light sampled by the cone of directions it subtends, in three
// functions a renderer's light sampling would call in turn.
#pragma once

#include "util/math.h"

namespace pathlab::@STEM@ {

// T@N@.1: the cosine of the cone of directions from x that hit the sphere
// (center, radius): cos(theta_max) = sqrt(1 - (radius / d)^2), d the distance
// from x to the centre. x on or inside the sphere (d <= radius): every
// direction hits it, the "cone" is the whole sphere: -1.
float coneCosThetaMax(Point3 x, Point3 center, float radius);

// A direction drawn by sampleCone, and the density it was drawn with.
struct ConeSample {
  Vec3 direction;  // unit length
  float pdf;       // per unit solid angle
};

// T@N@.2: a direction uniform over the cone around `axis` (unit length) of
// half-angle acos(cosThetaMax), cosThetaMax in [-1, 1), from a uniform u in
// [0,1)^2, and its density: 1 over the cone's solid angle,
// 1 / (2 pi (1 - cosThetaMax)). Any uniform map will do.
ConeSample sampleCone(Vec3 axis, float cosThetaMax, Vec2 u);

// T@N@.3: the density sampleCone draws w with (w unit length): the one above
// inside the cone (dot(w, axis) >= cosThetaMax), 0 outside it.
float conePdf(Vec3 axis, float cosThetaMax, Vec3 w);

}  // namespace pathlab::@STEM@
