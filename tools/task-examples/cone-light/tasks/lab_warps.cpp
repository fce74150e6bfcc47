// Task @N@'s warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab and lists add@NAME@Warps with the other tasks'.
#include <array>

#include "lab_support.h"
#include "tasks/@STEM@.h"

namespace pathlab::lab {
namespace {

Warp coneWarp() {
  return {"@WARP@", "T@N@.2", "sampleCone against conePdf over the sphere: a cone around a tilted axis",
          {{"width", 1, 0, 2, true, false, "the cone: cos theta_max 0.9 (narrow), 0 (a hemisphere) or -0.5 (wider)",
            {"narrow", "hemisphere", "wide"}}},
          [](const Values& p, const WarpFiles&) {
            const float cosThetaMax = std::array<float, 3>{0.9f, 0.0f, -0.5f}[size_t(count(p, "width"))];
            const Vec3 axis = glm::normalize(Vec3(0.3f, -0.5f, 0.8f));
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sample = [=](Vec2 u) -> std::optional<Vec3> { return @STEM@::sampleCone(axis, cosThetaMax, u).direction; };
            s.pdf = pointwise([=](const Vec3& w) { return double(@STEM@::conePdf(axis, cosThetaMax, w)); });
            s.mismatchMeans = "the directions are not uniform over the cone (theta uniform crowds the axis: cos theta "
                              "must be), or conePdf is not their density";
            return s;
          }};
}

}  // namespace

void add@NAME@Warps(std::vector<Warp>& warps) {
  warps.push_back(coneWarp());
}

}  // namespace pathlab::lab
