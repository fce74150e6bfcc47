// Task 5's warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab; addPathTracingWarps is listed with the other tasks'.
#include "lab_support.h"
#include "tasks/path_tracing.h"

namespace pathlab::lab {
namespace {

Warp cosineHemisphereWarp() {
  return {"cosine-hemisphere", "T5.1", "sampleDiffuseDirection against diffuseDirectionPdf (local frame, normal +z)", {},
          [](const Values&, const WarpFiles&) {
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sample = [](Vec2 u) -> std::optional<Vec3> { return sampleDiffuseDirection(u); };
            s.pdf = pointwise([](const Vec3& w) { return double(diffuseDirectionPdf(w)); });
            s.mismatchMeans = "the pdf is not the sampler's: cosine sampling has pdf cos(theta) / pi (and 0 below "
                              "the horizon)";
            return s;
          }};
}

}  // namespace

void addPathTracingWarps(std::vector<Warp>& warps) {
  warps.push_back(cosineHemisphereWarp());
}

}  // namespace pathlab::lab
