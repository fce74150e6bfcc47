// Task 6's warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab; addMirrorGlassWarps is listed with the other tasks'.
#include "lab_support.h"
#include "tasks/mirror_glass.h"

namespace pathlab::lab {
namespace {

// The outcome of a delta BSDF sample: 0 reflection, 1 refraction.
int lobeOf(const Vec3& wo, const BsdfSample& s) { return s.wi.z * wo.z > 0.0f ? 0 : 1; }

Warp mirrorWarp() {
  return {"mirror", "T6.4", "sampleMirror: every sample the mirror direction of wo, reported with probability 1",
          {{"angle", 40.0, 0.0, 89.9, false, false, "incident angle from the normal, degrees"}},
          [](const Values& p, const WarpFiles&) {
            const float theta = float(p.at("angle") * kPi / 180.0);
            const Vec3 wo(std::sin(theta), 0.0f, std::cos(theta)), mirrored(-wo.x, -wo.y, wo.z);
            // The probability the sample reports for the mirror direction (the lab's own, not reflect()'s).
            const BsdfSample first = sampleMirror(wo, Color(1.0f));
            const double reported = glm::length(first.wi - mirrored) < 1e-4f ? double(first.pdf) : 0.0;
            WarpSetup w;
            w.domain = Domain::Discrete;
            w.outcomes = {"the mirror direction", "elsewhere"};
            w.sample = [=](Vec2) -> std::optional<Vec3> {
              const BsdfSample s = sampleMirror(wo, Color(1.0f));
              if (!(s.pdf > 0.0f)) return std::nullopt;
              return Vec3(glm::length(s.wi - mirrored) < 1e-4f ? 0.0f : 1.0f, 0.0f, 0.0f);
            };
            w.pdf = pointwise([reported](const Vec3& k) { return k.x == 0.0f ? reported : 0.0; });
            w.mismatchMeans = "wi is not wo mirrored about the normal (-wo.x, -wo.y, wo.z), or its probability is not 1";
            return w;
          }};
}

Warp glassWarp() {
  return {"glass", "T6.5", "sampleGlass: how often each lobe is chosen against the probability it reports",
          {{"angle", 40.0, 0.0, 89.9, false, false, "incident angle from the normal, degrees"},
           {"ior", 1.5, 1.0, 3.0, false, false, "index of refraction"},
           {"inside", 0, 0, 1, true, false, "1: wo inside the glass (below the surface)"}},
          [](const Values& p, const WarpFiles&) {
            const float theta = float(p.at("angle") * kPi / 180.0), ior = float(p.at("ior"));
            const float side = count(p, "inside") == 1 ? -1.0f : 1.0f;
            const Vec3 wo(std::sin(theta), 0.0f, side * std::cos(theta));
            // The probability each lobe reports, seen over a fine sweep of u.
            std::vector<double> reported(2, 0.0);
            for (int i = 0; i < 1000; ++i) {
              const BsdfSample s = sampleGlass(wo, Color(1.0f), Color(1.0f), ior, (float(i) + 0.5f) / 1000.0f);
              if (s.pdf > 0.0f) reported[size_t(lobeOf(wo, s))] = s.pdf;
            }
            WarpSetup w;
            w.domain = Domain::Discrete;
            w.outcomes = {"reflection", "refraction"};
            w.sample = [=](Vec2 u) -> std::optional<Vec3> {
              const BsdfSample s = sampleGlass(wo, Color(1.0f), Color(1.0f), ior, u.x);
              if (!(s.pdf > 0.0f)) return std::nullopt;
              return Vec3(float(lobeOf(wo, s)), 0.0f, 0.0f);
            };
            w.pdf = pointwise([reported](const Vec3& k) { return reported[size_t(k.x)]; });
            w.mismatchMeans = "the lobe is not chosen with the probability the sample reports (Fresnel F for "
                              "reflection, 1 - F for refraction; total internal reflection always reflects)";
            return w;
          }};
}

}  // namespace

void addMirrorGlassWarps(std::vector<Warp>& warps) {
  warps.push_back(mirrorWarp());
  warps.push_back(glassWarp());
}

}  // namespace pathlab::lab
