// Task 10's warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab; addThinLensWarps is listed with the other tasks'.
#include "lab_support.h"
#include "tasks/thin_lens.h"

namespace pathlab::lab {
namespace {

Warp lensDiskWarp() {
  return {"lens-disk", "T10.1", "sampleUnitDisk: points on the lens (the unit disk) against the uniform density 1/pi", {},
          [](const Values&, const WarpFiles&) {
            WarpSetup s;
            s.lo = Vec2(-1.1f), s.hi = Vec2(1.1f);  // a margin: a point outside the disk shows
            s.sample = [](Vec2 u) -> std::optional<Vec3> {
              const Point2 p = sampleUnitDisk(u);
              return Vec3(p.x, p.y, 0.0f);
            };
            s.pdf = pointwise([](const Vec3& x) { return double(x.x) * x.x + double(x.y) * x.y <= 1.0 ? 1.0 / kPi : 0.0; });
            s.mismatchMeans = "the points are not uniform by area: dA = r dr dphi, so r = sqrt(u), not u (or a "
                              "map that covers part of the disk twice)";
            return s;
          }};
}

}  // namespace

void addThinLensWarps(std::vector<Warp>& warps) {
  warps.push_back(lensDiskWarp());
}

}  // namespace pathlab::lab
