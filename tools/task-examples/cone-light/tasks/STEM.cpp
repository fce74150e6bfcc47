// Task @N@ — @TITLE@
//
// Goal: sample a sphere light by the cone of directions it subtends, as a
// renderer does for a small or distant light (the worked example of a task:
// replace it with your course's). Handout: tasks/@FOLDER@/README.md
//
// Functions to write (declared in framework/tasks/@STEM@.h):
//   T@N@.1 coneCosThetaMax   the cosine of the cone a sphere subtends from x
//   T@N@.2 sampleCone        a direction uniform over that cone, with its pdf
//   T@N@.3 conePdf           the density sampleCone draws a direction with
//
// Check your work:
//   ./build/pathlab debug --task @N@ --view cone -o cone.png
//   ./build/pathlab lab @WARP@ -o @WARP@.png
//   ctest --test-dir build -R @FOLDER@ --output-on-failure
#include "tasks/@STEM@.h"

#include <algorithm>
#include <cmath>

#include "util/frame.h"
#include "util/todo.h"

namespace pathlab::@STEM@ {

// T@N@.1 — The cone of directions from x that hit the sphere.
//
// A ray from x at angle theta from the direction to the centre grazes the
// sphere when sin(theta) = radius / d (d = |center - x|: the right angle is
// at the point of contact). So
//   cos(theta_max) = sqrt(1 - (radius / d)^2).
// When x is on or inside the sphere (radius / d >= 1), every direction hits
// it: return -1, the cosine of a cone that is the whole sphere.
//
// PITFALL: radius / d is sin(theta_max), not its cosine.
float coneCosThetaMax(Point3 x, Point3 center, float radius) {
  // TODO(T@N@.1): cos(theta_max), or -1 on or inside the sphere.
  PATHLAB_TODO("T@N@.1");
  (void)x;
  (void)center;
  (void)radius;
  return 0.0f;
}

// T@N@.2 — A direction uniform over the cone.
//
// A cap of the unit sphere between theta = 0 and theta_max has solid angle
// 2 pi (1 - cos(theta_max)), and the band at theta has area proportional
// to d(cos theta): uniform in solid angle means cos(theta) uniform on
// [cos(theta_max), 1] and phi uniform on [0, 2 pi):
//   cos(theta) = 1 - u.x (1 - cos(theta_max)),  phi = 2 pi u.y,
//   local = (sin(theta) cos(phi), sin(theta) sin(phi), cos(theta)),
// turned to the world by a frame whose +z is the axis
// (Frame::fromNormal(axis).toWorld(local), util/frame.h). The pdf is 1 over
// the cone's solid angle.
//
// PITFALL: theta = u.x theta_max (theta uniform) crowds the axis: the band
// at theta has area 2 pi sin(theta) d(theta), not 2 pi d(theta).
ConeSample sampleCone(Vec3 axis, float cosThetaMax, Vec2 u) {
  // TODO(T@N@.2): a direction uniform over the cone, and its pdf.
  PATHLAB_TODO("T@N@.2");
  (void)axis;
  (void)cosThetaMax;
  (void)u;
  return {Vec3(0.0f, 0.0f, 1.0f), 0.0f};
}

// T@N@.3 — The density of sampleCone's directions.
//
// The same constant, 1 / (2 pi (1 - cos(theta_max))), for w inside the cone
// (dot(w, axis) >= cos(theta_max)), and 0 outside: a renderer weighing this
// strategy against another (multiple importance sampling) asks it for
// directions the cone does not hold.
float conePdf(Vec3 axis, float cosThetaMax, Vec3 w) {
  // TODO(T@N@.3): the density inside the cone, 0 outside.
  PATHLAB_TODO("T@N@.3");
  (void)axis;
  (void)cosThetaMax;
  (void)w;
  return 0.0f;
}

}  // namespace pathlab::@STEM@
