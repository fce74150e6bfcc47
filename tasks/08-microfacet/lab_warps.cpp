// Task 8's warps in the sampling lab (lab/lab.h): its sampling
// routines, called as this build links them (the student's file or the
// reference), each against its own pdf. lab/CMakeLists.txt compiles this
// file into the lab; addMicrofacetWarps is listed with the other tasks'.
#include "lab_support.h"
#include "tasks/microfacet.h"

namespace pathlab::lab {
namespace {

// wo at `degrees` from the normal, in the x-z plane.
Vec3 incident(const Values& p) {
  const float theta = float(p.at("angle") * kPi / 180.0);
  return {std::sin(theta), 0.0f, std::cos(theta)};
}

// The lab's histogram is over directions themselves (50 x 101 cells), not
// over stretched half vectors as task 8's suite uses: a lobe much narrower
// than a cell, or squeezed against the horizon, is beyond its quadrature,
// and it rejected the reference there (at roughness 0.05 to 0.2236, and for
// the BSDF at 85 degrees and more below roughness 0.5). The ranges stop
// where the reference was accepted in every run of a grid of settings and
// seeds (docs/debugger.md); the suite tests the sharper lobes.
constexpr double kLabRoughnessMin = 0.3, kLabBsdfAngleMax = 80.0;

Warp ggxNormalsWarp() {
  return {"ggx-normals", "T8.5", "sampleGgxNormal against D(m) cos theta_m (local frame, normal +z)",
          {{"roughness", 0.5, kLabRoughnessMin, 1.0, false, false, "perceptual roughness (alpha = roughness^2)"}},
          [](const Values& p, const WarpFiles&) {
            const float alpha = alphaFromRoughness(float(p.at("roughness")));
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sample = [alpha](Vec2 u) -> std::optional<Vec3> { return sampleGgxNormal(u, alpha); };
            s.pdf = pointwise([alpha](const Vec3& m) { return double(ggxD(m, alpha)) * std::max(0.0f, m.z); });
            s.mismatchMeans = "the normals do not follow D cos theta: tan^2 theta = alpha^2 u / (1 - u) inverts its "
                              "CDF (or D itself is not normalised)";
            return s;
          }};
}

Warp visibleNormalsWarp() {
  return {"visible-normals", "T8.5", "sampleVisibleNormal against visibleNormalPdf for wo at a chosen angle",
          {{"angle", 70.0, 0.0, 89.0, false, false, "wo's angle from the normal, degrees"},
           {"roughness", 0.5, kLabRoughnessMin, 1.0, false, false, "perceptual roughness (alpha = roughness^2)"}},
          [](const Values& p, const WarpFiles&) {
            const float alpha = alphaFromRoughness(float(p.at("roughness")));
            const Vec3 wo = incident(p);
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sample = [=](Vec2 u) -> std::optional<Vec3> { return sampleVisibleNormal(wo, u, alpha); };
            s.pdf = pointwise([=](const Vec3& m) { return double(visibleNormalPdf(wo, m, alpha)); });
            s.mismatchMeans = "the normals are not the visible ones: D_wo(m) = G1(wo, m) max(0, wo.m) D(m) / wo.z "
                              "(stretch wo, sample the disk it sees, unstretch)";
            return s;
          }};
}

Warp microfacetBsdfWarp() {
  return {"microfacet-bsdf", "T8.6", "sampleConductor (or samplePlastic) against its pdf for wo at a chosen angle",
          {{"angle", 45.0, 0.0, kLabBsdfAngleMax, false, false, "wo's angle from the normal, degrees"},
           {"roughness", 0.5, kLabRoughnessMin, 1.0, false, false, "perceptual roughness (alpha = roughness^2)"},
           {"plastic", 0, 0, 1, true, false, "1: the rough plastic (T8.7) instead of the conductor"}},
          [](const Values& p, const WarpFiles&) {
            const Vec3 wo = incident(p);
            const float roughness = float(p.at("roughness"));
            const bool plastic = count(p, "plastic") == 1;
            const RoughConductor c{roughness, Color(0.9f), false, Color(0.0f), Color(0.0f)};
            const RoughPlastic q{roughness, Color(0.5f), 1.5f};
            WarpSetup s;
            s.domain = Domain::Sphere;
            s.sample = [=](Vec2 u) -> std::optional<Vec3> {
              const std::optional<BsdfSample> b = plastic ? samplePlastic(wo, u, q) : sampleConductor(wo, u, c);
              if (!b || !(b->pdf > 0.0f)) return std::nullopt;
              return b->wi;
            };
            s.pdf = pointwise([=](const Vec3& wi) {
              return double(plastic ? plasticPdf(wo, wi, q) : conductorPdf(wo, wi, c));
            });
            s.mismatchMeans = plastic ? "the pdf is not the mixture's: P pdf_coat + (1 - P) pdf_base for every wi, "
                                        "whichever lobe drew it"
                                      : "the pdf is not the sampler's: D_wo(m) / (4 |wo.m|) for visible normals (the "
                                        "Jacobian of the reflection)";
            return s;
          }};
}

}  // namespace

void addMicrofacetWarps(std::vector<Warp>& warps) {
  warps.push_back(ggxNormalsWarp());
  warps.push_back(visibleNormalsWarp());
  warps.push_back(microfacetBsdfWarp());
}

}  // namespace pathlab::lab
