// Task 12's warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab; addMediaWarps is listed with the other tasks'.
#include "lab_support.h"
#include "tasks/media.h"

namespace pathlab::lab {
namespace {

Warp freeFlightWarp() {
  return {"free-flight", "T12.1",
          "sampleFreeFlight: distances against sigmaT exp(-sigmaT t) up to the surface at tMax; the flights that "
          "reach it are drawn spread over the band past tMax, their share P(pass) = exp(-sigmaT tMax)",
          {{"sigma", 1.5, 0.05, 20.0, false, true, "the extinction sigmaT"},
           {"surface", 1.5, 0.05, 10.0, false, true, "the distance tMax to the surface"}},
          [](const Values& p, const WarpFiles&) {
            const float sigmaT = float(p.at("sigma")), tMax = float(p.at("surface"));
            const float band = tMax / 8.0f;  // where the surface's share is drawn
            WarpSetup s;
            s.domain = Domain::Interval;
            s.lo = {0.0f, 0.0f}, s.hi = {tMax + band, 1.0f};
            s.sample = [=](Vec2 u) -> std::optional<Vec3> {
              const FreeFlight f = sampleFreeFlight(sigmaT, tMax, u.x);
              return Vec3(f.scattered ? f.t : tMax + band * u.y, 0.0f, 0.0f);
            };
            s.pdf = pointwise([=](const Vec3& x) {
              const double t = x.x;
              if (t < tMax) return double(sigmaT) * std::exp(-double(sigmaT) * t);
              return std::exp(-double(sigmaT) * tMax) / band;
            });
            s.mismatchMeans = "the distances are not exponential with rate sigmaT (sigmaS used, or sigmaT multiplied "
                              "where it divides), or the flights past the surface did not stop there";
            return s;
          }};
}

Warp henyeyGreensteinWarp() {
  return {"henyey-greenstein", "T12.2",
          "sampleHenyeyGreenstein against henyeyGreenstein over the sphere (travelling along +z)",
          {{"g", 0.5, -0.9, 0.9, false, false, "the mean cosine g"}},
          [](const Values& p, const WarpFiles&) {
            const float g = float(p.at("g"));
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sample = [g](Vec2 u) -> std::optional<Vec3> { return sampleHenyeyGreenstein(Vec3(0, 0, 1), g, u); };
            s.pdf = pointwise([g](const Vec3& w) { return double(henyeyGreenstein(w.z, g)); });
            s.mismatchMeans = "the sampled cosines do not follow the phase function: the CDF inverted wrongly, or "
                              "the sign of g flipped in one of the two";
            return s;
          }};
}

}  // namespace

void addMediaWarps(std::vector<Warp>& warps) {
  warps.push_back(freeFlightWarp());
  warps.push_back(henyeyGreensteinWarp());
}

}  // namespace pathlab::lab
