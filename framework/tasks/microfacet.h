// Task 8 — rough metal and plastic: the GGX microfacet model, sampled by its
// visible normals. Implemented in tasks/08-microfacet/microfacet.cpp (the
// student's file; where the task is not the student's, the programs link the
// course's reference in its place).
// Every direction here is in the local shading frame: the surface normal is
// +z; directions are unit and point away from the surface. wo is above the
// surface (wo.z > 0: the framework turns the frame to wo's side).
// Materials give a perceptual roughness r in [0, 1]; the functions of T8.1 to
// T8.5 take the distribution's width alpha = alphaFromRoughness(r).
#pragma once

#include <optional>

#include "core/bsdf_sample.h"
#include "core/microfacet_material.h"
#include "util/math.h"

namespace pathlab {

// T8.1: alpha = roughness^2, at least 0.001 (so that a roughness of 0 stays finite).
float alphaFromRoughness(float roughness);

// T8.1: the GGX (Trowbridge-Reitz) distribution of microfacet normals m:
// D(m) = alpha^2 / (pi ((alpha^2 - 1) cos^2 theta_m + 1)^2); 0 for m.z <= 0.
// Normalised so that the integral of D(m) cos theta_m over the hemisphere is 1.
float ggxD(const Vec3& m, float alpha);

// T8.2: Smith's shadowing-masking. Lambda(w) = (-1 + sqrt(1 + alpha^2 tan^2 theta)) / 2;
// G1(w, m) = 1 / (1 + Lambda(w)) where w and m are on the same side of the
// microfacet (w.m and w.z of one sign), else 0; the height-correlated
// G2(wo, wi, m) = 1 / (1 + Lambda(wo) + Lambda(wi)) under the same condition for both.
float smithLambda(const Vec3& w, float alpha);
float smithG1(const Vec3& w, const Vec3& m, float alpha);
float smithG2(const Vec3& wo, const Vec3& wi, const Vec3& m, float alpha);

// T8.3: Fresnel reflectance of a conductor at a facet seen at angle theta
// (cosTheta in [0, 1]): Schlick's from the reflectance at normal incidence
// F0, and the exact formula for the complex index eta + i k, per channel.
Color schlickFresnelF0(float cosTheta, const Color& f0);
Color conductorFresnel(float cosTheta, const Color& eta, const Color& k);

// T8.4: the rough conductor's BRDF, f = D(h) G2(wo, wi, h) F(wo.h) / (4 cos theta_o cos theta_i)
// with the half vector h = normalize(wo + wi); 0 unless both are above the surface.
Color conductorBrdf(const Vec3& wo, const Vec3& wi, const RoughConductor& conductor);

// T8.5: sampling microfacet normals from u in [0, 1)^2. sampleGgxNormal
// draws m with density D(m) cos theta_m; sampleVisibleNormal draws the
// normals wo sees (Heitz 2018), with density visibleNormalPdf:
// D_wo(m) = G1(wo, m) max(0, wo.m) D(m) / wo.z.
Vec3 sampleGgxNormal(Vec2 u, float alpha);
Vec3 sampleVisibleNormal(const Vec3& wo, Vec2 u, float alpha);
float visibleNormalPdf(const Vec3& wo, const Vec3& m, float alpha);

// T8.6: the rough conductor sampled by its visible normals: wi = reflect(wo, m),
// pdf = D_wo(m) / (4 |wo.m|) (the Jacobian of the reflection), f = conductorBrdf;
// nothing when wi falls below the surface. conductorPdf is that density for a given wi.
std::optional<BsdfSample> sampleConductor(const Vec3& wo, Vec2 u, const RoughConductor& conductor);
float conductorPdf(const Vec3& wo, const Vec3& wi, const RoughConductor& conductor);

// T8.7: rough plastic: a diffuse base under a GGX dielectric coat.
// f = D G2 F_c(wo.h) / (4 cos theta_o cos theta_i)  +  (1 - F_c(cos theta_o)) (1 - F_c(cos theta_i)) diffuse / pi
// with F_c Schlick's for the coat's index (F0 = ((ior - 1) / (ior + 1))^2).
// sample: the coat's visible normals or the base's cosine lobe, chosen with a
// probability of your choice that depends on wo only; the sample's pdf is the
// mixture's, P pdf_coat + (1 - P) pdf_base, and plasticPdf gives the same.
Color plasticBrdf(const Vec3& wo, const Vec3& wi, const RoughPlastic& plastic);
std::optional<BsdfSample> samplePlastic(const Vec3& wo, Vec2 u, const RoughPlastic& plastic);
float plasticPdf(const Vec3& wo, const Vec3& wi, const RoughPlastic& plastic);

}  // namespace pathlab
