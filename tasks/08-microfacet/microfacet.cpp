// Task 8 — rough metal and plastic
//
// Goal: surfaces between the diffuse wall and the perfect mirror: brushed
// metal, a glossy plastic ball, a highlight that spreads as the surface gets
// rougher. Handout: tasks/08-microfacet/README.md
//
// Functions to write (declared in framework/tasks/microfacet.h):
//   T8.1 alphaFromRoughness, ggxD          the distribution of microfacet normals
//   T8.2 smithLambda, smithG1, smithG2     how much of it is hidden
//   T8.3 schlickFresnelF0, conductorFresnel  how much a facet reflects
//   T8.4 conductorBrdf                     the rough metal's BRDF
//   T8.5 sampleGgxNormal, sampleVisibleNormal, visibleNormalPdf
//   T8.6 sampleConductor, conductorPdf     sampling the rough metal
//   T8.7 plasticBrdf, samplePlastic, plasticPdf   rough plastic
//
// All directions are in the local frame: the normal is +z; wo and wi are
// unit and point away from the surface; m (or h) is a microfacet's normal.
//
// Check your work:
//   ./build/pathlab media/scenes/roughness-sweep.json -o sweep.png
//   ./build/pathlab debug --task 8 --view lobe --pixel 120 96 media/scenes/roughness-sweep.json -o lobe.png
//   ctest --test-dir build -R 08-microfacet --output-on-failure
#include "tasks/microfacet.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include "tasks/path_tracing.h"
#include "util/todo.h"

namespace pathlab {

// T8.1 — Roughness and the GGX distribution.
//
// Materials give a perceptual roughness r in [0, 1]; the distribution's
// width is alpha = r^2, kept at least 0.001 so that r = 0 stays finite.
//
// GGX (Trowbridge-Reitz): the density of microfacet normals m, per unit
// solid angle and per unit area of the surface,
//   D(m) = alpha^2 / (pi ((alpha^2 - 1) cos^2(theta_m) + 1)^2),   cos(theta_m) = m.z,
// and 0 for m.z <= 0. Projected onto the surface the facets cover it once:
// the integral of D(m) cos(theta_m) over the hemisphere is 1.
float alphaFromRoughness(float roughness) {
  // TODO(T8.1): alpha = roughness^2, at least 0.001.
  PATHLAB_TODO("T8.1");
  (void)roughness;
  return 1.0f;
}

float ggxD(const Vec3& m, float alpha) {
  // TODO(T8.1): the GGX distribution.
  PATHLAB_TODO("T8.1");
  (void)m, (void)alpha;
  return 0.0f;
}

// T8.2 — Smith's masking and shadowing.
//
// Seen from a direction w at angle theta, part of the facets hide behind
// others. For GGX, with tan^2(theta) = (1 - cos^2) / cos^2,
//   Lambda(w) = (sqrt(1 + alpha^2 tan^2(theta)) - 1) / 2
//   G1(w, m)  = 1 / (1 + Lambda(w))                    the fraction w sees
//   G2(wo, wi, m) = 1 / (1 + Lambda(wo) + Lambda(wi))  seen from both (height-correlated)
// Both are 0 where a direction sees the facet from behind: w.m and w.z of
// opposite signs.
// PITFALL: at cos(theta) = 0 tan is infinite: Lambda is infinite, G1 is 0.
float smithLambda(const Vec3& w, float alpha) {
  // TODO(T8.2): Lambda.
  PATHLAB_TODO("T8.2");
  (void)w, (void)alpha;
  return 0.0f;
}

float smithG1(const Vec3& w, const Vec3& m, float alpha) {
  // TODO(T8.2): G1.
  PATHLAB_TODO("T8.2");
  (void)w, (void)m, (void)alpha;
  return 1.0f;
}

float smithG2(const Vec3& wo, const Vec3& wi, const Vec3& m, float alpha) {
  // TODO(T8.2): the height-correlated G2.
  PATHLAB_TODO("T8.2");
  (void)wo, (void)wi, (void)m, (void)alpha;
  return 1.0f;
}

// T8.3 — Fresnel reflectance of a metal facet seen at angle theta
// (cosTheta = |wo . m|), per colour channel.
//   Schlick:  F = F0 + (1 - F0) (1 - cos)^5,  F0 the colour at normal incidence.
//   Exact, for the complex index n = eta + i k (std::complex<float>):
//     sin^2_t = (1 - cos^2) / n^2,   cos_t = sqrt(1 - sin^2_t)     (complex)
//     r_p = (n cos - cos_t) / (n cos + cos_t),   r_s = (cos - n cos_t) / (cos + n cos_t)
//     F = (|r_p|^2 + |r_s|^2) / 2                 (std::norm(z) is |z|^2)
Color schlickFresnelF0(float cosTheta, const Color& f0) {
  // TODO(T8.3): Schlick's approximation.
  PATHLAB_TODO("T8.3");
  (void)cosTheta;
  return f0;
}

Color conductorFresnel(float cosTheta, const Color& eta, const Color& k) {
  // TODO(T8.3): the exact conductor Fresnel, per channel.
  PATHLAB_TODO("T8.3");
  (void)cosTheta, (void)eta, (void)k;
  return Color(1.0f);
}

// T8.4 — The rough conductor (Cook-Torrance with GGX).
//
// Light reflects off the facets whose normal is the half vector
// h = normalize(wo + wi):
//   f(wo, wi) = D(h) G2(wo, wi, h) F(wo . h) / (4 cos(theta_o) cos(theta_i))
// with alpha = alphaFromRoughness(conductor.roughness), and F by Schlick from
// conductor.f0 or, if conductor.exactFresnel, exactly from eta and k.
// 0 unless both wo.z and wi.z are > 0 (a metal transmits nothing).
Color conductorBrdf(const Vec3& wo, const Vec3& wi, const RoughConductor& conductor) {
  // TODO(T8.4): the microfacet BRDF.
  PATHLAB_TODO("T8.4");
  (void)wo, (void)wi, (void)conductor;
  return Color(0.0f);
}

// T8.5 — Sampling microfacet normals, from u in [0, 1)^2.
//
// GGX normals, density D(m) cos(theta_m): invert the CDF over theta,
//   tan^2(theta) = alpha^2 u.x / (1 - u.x),   phi = 2 pi u.y.
//
// The normals wo sees (Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals"), density D_wo(m) = G1(wo, m) max(0, wo . m) D(m) / wo.z:
//   1. stretch: v = normalize(alpha wo.x, alpha wo.y, wo.z)
//   2. a basis: t1 = normalize(-v.y, v.x, 0) (or (1, 0, 0) if v is +z), t2 = v x t1
//   3. a point on the unit disk: r = sqrt(u.x), phi = 2 pi u.y, p1 = r cos(phi), p2 = r sin(phi);
//      squeeze it onto the part v sees: s = (1 + v.z) / 2, p2 = (1 - s) sqrt(max(0, 1 - p1^2)) + s p2
//   4. up onto the hemisphere: n = p1 t1 + p2 t2 + sqrt(max(0, 1 - p1^2 - p2^2)) v
//   5. unstretch: m = normalize(alpha n.x, alpha n.y, max(0, n.z))
// Why visible normals: the facets wo cannot see never reflect toward it;
// sampling them wastes samples, which D cos sampling does at grazing angles.
Vec3 sampleGgxNormal(Vec2 u, float alpha) {
  // TODO(T8.5): a normal with density D(m) cos(theta_m).
  PATHLAB_TODO("T8.5");
  (void)u, (void)alpha;
  return Vec3(0.0f, 0.0f, 1.0f);
}

Vec3 sampleVisibleNormal(const Vec3& wo, Vec2 u, float alpha) {
  // TODO(T8.5): a visible normal (Heitz 2018).
  PATHLAB_TODO("T8.5");
  (void)wo, (void)u, (void)alpha;
  return Vec3(0.0f, 0.0f, 1.0f);
}

float visibleNormalPdf(const Vec3& wo, const Vec3& m, float alpha) {
  // TODO(T8.5): D_wo(m).
  PATHLAB_TODO("T8.5");
  (void)wo, (void)m, (void)alpha;
  return 0.0f;
}

// T8.6 — Sampling the rough conductor.
//
// Draw m from the visible normals and reflect wo about it:
//   wi = 2 (wo . m) m - wo;   nothing if wi.z <= 0 (a shadowed reflection).
// The density of wi: p(wi) = D_wo(m) / (4 |wo . m|) with m = h, because a
// change dm of the normal turns the reflected direction by dwi = 4 |wo . m| dm.
// Return f = conductorBrdf(wo, wi) and pdf = conductorPdf(wo, wi): the path
// tracer multiplies by f cos(theta_i) / pdf, which here is F G2 / G1(wo).
std::optional<BsdfSample> sampleConductor(const Vec3& wo, Vec2 u, const RoughConductor& conductor) {
  // TODO(T8.6): sample wi by the visible normals.
  PATHLAB_TODO("T8.6");
  (void)wo, (void)u, (void)conductor;
  return std::nullopt;
}

float conductorPdf(const Vec3& wo, const Vec3& wi, const RoughConductor& conductor) {
  // TODO(T8.6): the density of sampleConductor's wi.
  PATHLAB_TODO("T8.6");
  (void)wo, (void)wi, (void)conductor;
  return 0.0f;
}

// T8.7 — Rough plastic: a diffuse base under a clear GGX coat of index ior.
//   F_c(cos) = Schlick's with F0 = ((ior - 1) / (ior + 1))^2
//   f = D(h) G2 F_c(wo . h) / (4 cos_o cos_i)                  the coat
//     + (1 - F_c(cos_o)) (1 - F_c(cos_i)) diffuse / pi         the base, seen through it
// Sample as a mixture: with a probability P that depends on wo only (e.g.
// the coat's share of the reflected light, kept in [0.1, 0.9]), the coat's
// visible normals as in T8.6; else the base's cosine lobe
// (sampleDiffuseDirection, task 5). Re-use u.x: u.x < P picks the coat and
// u.x / P is a fresh number in [0, 1); else (u.x - P) / (1 - P).
// Whichever lobe drew wi, its pdf is the mixture's:
//   pdf(wi) = P pdf_coat(wi) + (1 - P) pdf_base(wi)
// PITFALL: returning only the chosen lobe's pdf is wrong: the other lobe
// could have drawn the same wi.
Color plasticBrdf(const Vec3& wo, const Vec3& wi, const RoughPlastic& plastic) {
  // TODO(T8.7): the coat plus the base.
  PATHLAB_TODO("T8.7");
  (void)wo, (void)wi, (void)plastic;
  return Color(0.0f);
}

std::optional<BsdfSample> samplePlastic(const Vec3& wo, Vec2 u, const RoughPlastic& plastic) {
  // TODO(T8.7): sample the mixture.
  PATHLAB_TODO("T8.7");
  (void)wo, (void)u, (void)plastic;
  return std::nullopt;
}

float plasticPdf(const Vec3& wo, const Vec3& wi, const RoughPlastic& plastic) {
  // TODO(T8.7): the mixture's density.
  PATHLAB_TODO("T8.7");
  (void)wo, (void)wi, (void)plastic;
  return 0.0f;
}

}  // namespace pathlab
