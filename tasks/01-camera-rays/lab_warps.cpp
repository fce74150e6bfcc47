// Task 1's warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab; addCameraRaysWarps is listed with the other tasks'.
#include "lab_support.h"
#include "tasks/camera_rays.h"

namespace pathlab::lab {
namespace {

Warp pixelSampleWarp() {
  return {"pixel-sample", "T1.1", "pixelSamplePosition: points in pixel (3, 7), drawn relative to its corner", {},
          [](const Values&, const WarpFiles&) {
            WarpSetup s;
            s.lo = Vec2(-0.25f), s.hi = Vec2(1.25f);  // a margin: a sample outside the pixel shows
            s.sample = [](Vec2 u) -> std::optional<Vec3> {
              const Point2 p = pixelSamplePosition(IVec2(3, 7), u);
              return Vec3(p.x - 3.0f, p.y - 7.0f, 0.0f);
            };
            s.pdf = pointwise([](const Vec3& x) { return x.x >= 0.0f && x.x < 1.0f && x.y >= 0.0f && x.y < 1.0f ? 1.0 : 0.0; });
            s.mismatchMeans = "the sample is not pixel + u: an offset of half a pixel, or u scaled";
            return s;
          }};
}

}  // namespace

void addCameraRaysWarps(std::vector<Warp>& warps) {
  warps.push_back(pixelSampleWarp());
}

}  // namespace pathlab::lab
