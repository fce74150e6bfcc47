// Task @N@'s warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab and lists add@NAME@Warps with the other tasks'.
#include "lab_support.h"
#include "tasks/@STEM@.h"

namespace pathlab::lab {
namespace {

Warp triangleWarp() {
  return {"@WARP@", "T@N@.1", "sampleTriangle: points on the triangle (0, 0), (1, 0), (0, 1) against the uniform density 2",
          {},
          [](const Values&, const WarpFiles&) {
            WarpSetup s;
            s.lo = Vec2(-0.1f), s.hi = Vec2(1.1f);  // a margin: a point outside the triangle shows
            s.sample = [](Vec2 u) -> std::optional<Vec3> {
              const Point2 p = @STEM@::sampleTriangle(u);
              return Vec3(p.x, p.y, 0.0f);
            };
            s.pdf = pointwise([](const Vec3& x) { return x.x >= 0.0f && x.y >= 0.0f && x.x + x.y <= 1.0f ? 2.0 : 0.0; });
            s.mismatchMeans = "the points are not uniform by area: the slice x = 1 - s has length s, so s = sqrt(u), "
                              "not u (or a map that leaves the triangle)";
            return s;
          }};
}

}  // namespace

void add@NAME@Warps(std::vector<Warp>& warps) {
  warps.push_back(triangleWarp());
}

}  // namespace pathlab::lab
