// Task 8 — rough metal and plastic (reference solution).
#include "tasks/microfacet.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include "tasks/path_tracing.h"

namespace pathlab {
namespace {

// The mirror direction of w about the unit normal m.
Vec3 reflectAbout(const Vec3& w, const Vec3& m) { return 2.0f * glm::dot(w, m) * m - w; }

// Schlick's Fresnel of the plastic's coat (a dielectric of index ior, seen from outside).
float coatFresnel(float cosTheta, float ior) {
  const float r0 = (ior - 1.0f) / (ior + 1.0f);
  return schlickFresnelF0(cosTheta, Color(r0 * r0)).x;
}

// The probability of sampling the plastic's coat: its share of the light wo
// sends back, roughly (any probability in (0, 1) that depends on wo alone is right).
float coatProbability(const Vec3& wo, const RoughPlastic& plastic) {
  const float coat = coatFresnel(wo.z, plastic.ior);
  const float base = (1.0f - coat) * (plastic.diffuse.x + plastic.diffuse.y + plastic.diffuse.z) / 3.0f;
  return std::clamp(coat / (coat + base), 0.1f, 0.9f);
}

}  // namespace

float alphaFromRoughness(float roughness) { return std::max(roughness * roughness, 1e-3f); }

float ggxD(const Vec3& m, float alpha) {
  if (m.z <= 0.0f) return 0.0f;
  const float a2 = alpha * alpha;
  const float t = (a2 - 1.0f) * m.z * m.z + 1.0f;
  return a2 / (kPi * t * t);
}

float smithLambda(const Vec3& w, float alpha) {
  const float cos2 = w.z * w.z;
  if (cos2 <= 0.0f) return kInfinity;  // grazing: fully masked
  const float tan2 = std::max(0.0f, 1.0f - cos2) / cos2;
  return 0.5f * (std::sqrt(1.0f + alpha * alpha * tan2) - 1.0f);
}

float smithG1(const Vec3& w, const Vec3& m, float alpha) {
  if (glm::dot(w, m) * w.z <= 0.0f) return 0.0f;  // the facet's back, seen from w
  return 1.0f / (1.0f + smithLambda(w, alpha));
}

float smithG2(const Vec3& wo, const Vec3& wi, const Vec3& m, float alpha) {
  if (glm::dot(wo, m) * wo.z <= 0.0f || glm::dot(wi, m) * wi.z <= 0.0f) return 0.0f;
  return 1.0f / (1.0f + smithLambda(wo, alpha) + smithLambda(wi, alpha));
}

Color schlickFresnelF0(float cosTheta, const Color& f0) {
  const float m = 1.0f - std::clamp(cosTheta, 0.0f, 1.0f);
  return f0 + (Color(1.0f) - f0) * ((m * m) * (m * m) * m);
}

// pbrt-v4's FrComplex, per channel: the average of the s and p reflectances.
Color conductorFresnel(float cosTheta, const Color& eta, const Color& k) {
  const float cosI = std::clamp(cosTheta, 0.0f, 1.0f);
  Color result;
  for (int c = 0; c < 3; ++c) {
    const std::complex<float> n(eta[c], k[c]);
    const float sin2I = 1.0f - cosI * cosI;
    const std::complex<float> sin2T = sin2I / (n * n);
    const std::complex<float> cosT = std::sqrt(1.0f - sin2T);
    const std::complex<float> rParallel = (n * cosI - cosT) / (n * cosI + cosT);
    const std::complex<float> rPerpendicular = (cosI - n * cosT) / (cosI + n * cosT);
    result[c] = 0.5f * (std::norm(rParallel) + std::norm(rPerpendicular));
  }
  return result;
}

Color conductorBrdf(const Vec3& wo, const Vec3& wi, const RoughConductor& conductor) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return Color(0.0f);
  const Vec3 sum = wo + wi;
  if (!(glm::dot(sum, sum) > 0.0f)) return Color(0.0f);
  const Vec3 h = glm::normalize(sum);
  const float alpha = alphaFromRoughness(conductor.roughness);
  const float cosH = glm::dot(wo, h);
  const Color fresnel = conductor.exactFresnel ? conductorFresnel(cosH, conductor.eta, conductor.k)
                                               : schlickFresnelF0(cosH, conductor.f0);
  return fresnel * (ggxD(h, alpha) * smithG2(wo, wi, h, alpha) / (4.0f * wo.z * wi.z));
}

Vec3 sampleGgxNormal(Vec2 u, float alpha) {
  // tan^2 theta = alpha^2 u / (1 - u) inverts the CDF of D cos theta over theta.
  const float tan2 = alpha * alpha * u.x / (1.0f - u.x);
  const float cosTheta = 1.0f / std::sqrt(1.0f + tan2);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * kPi * u.y;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// Heitz, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4), 2018.
Vec3 sampleVisibleNormal(const Vec3& wo, Vec2 u, float alpha) {
  // Stretch wo to the hemisphere configuration (alpha = 1).
  const Vec3 v = glm::normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
  // An orthonormal basis around v.
  const float length2 = v.x * v.x + v.y * v.y;
  const Vec3 t1 = length2 > 0.0f ? Vec3(-v.y, v.x, 0.0f) / std::sqrt(length2) : Vec3(1.0f, 0.0f, 0.0f);
  const Vec3 t2 = glm::cross(v, t1);
  // A point on the disk, squeezed onto the half of it v sees.
  const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
  const float p1 = r * std::cos(phi);
  const float s = 0.5f * (1.0f + v.z);
  const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
  // Onto the hemisphere, then back to the ellipsoid configuration.
  const Vec3 n = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * v;
  return glm::normalize(Vec3(alpha * n.x, alpha * n.y, std::max(0.0f, n.z)));
}

float visibleNormalPdf(const Vec3& wo, const Vec3& m, float alpha) {
  if (wo.z <= 0.0f) return 0.0f;
  return smithG1(wo, m, alpha) * std::max(0.0f, glm::dot(wo, m)) * ggxD(m, alpha) / wo.z;
}

std::optional<BsdfSample> sampleConductor(const Vec3& wo, Vec2 u, const RoughConductor& conductor) {
  if (wo.z <= 0.0f) return std::nullopt;
  const Vec3 m = sampleVisibleNormal(wo, u, alphaFromRoughness(conductor.roughness));
  const Vec3 wi = reflectAbout(wo, m);
  if (wi.z <= 0.0f) return std::nullopt;  // reflected below the surface: this facet is shadowed
  BsdfSample s;
  s.wi = wi;
  s.f = conductorBrdf(wo, wi, conductor);
  s.pdf = conductorPdf(wo, wi, conductor);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  return s;
}

float conductorPdf(const Vec3& wo, const Vec3& wi, const RoughConductor& conductor) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const Vec3 sum = wo + wi;
  if (!(glm::dot(sum, sum) > 0.0f)) return 0.0f;
  const Vec3 h = glm::normalize(sum);
  // dwi = 4 |wo.h| dh: the reflection's Jacobian.
  return visibleNormalPdf(wo, h, alphaFromRoughness(conductor.roughness)) / (4.0f * std::abs(glm::dot(wo, h)));
}

Color plasticBrdf(const Vec3& wo, const Vec3& wi, const RoughPlastic& plastic) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return Color(0.0f);
  const Vec3 h = glm::normalize(wo + wi);
  const float alpha = alphaFromRoughness(plastic.roughness);
  const float coat = ggxD(h, alpha) * smithG2(wo, wi, h, alpha) *
                     coatFresnel(glm::dot(wo, h), plastic.ior) / (4.0f * wo.z * wi.z);
  const float through = (1.0f - coatFresnel(wo.z, plastic.ior)) * (1.0f - coatFresnel(wi.z, plastic.ior));
  return Color(coat) + plastic.diffuse * (through * kInvPi);
}

std::optional<BsdfSample> samplePlastic(const Vec3& wo, Vec2 u, const RoughPlastic& plastic) {
  if (wo.z <= 0.0f) return std::nullopt;
  const float coatChance = coatProbability(wo, plastic);
  Vec3 wi;
  if (u.x < coatChance) {
    const Vec3 m = sampleVisibleNormal(wo, Vec2(u.x / coatChance, u.y), alphaFromRoughness(plastic.roughness));
    wi = reflectAbout(wo, m);
  } else {
    wi = sampleDiffuseDirection(Vec2((u.x - coatChance) / (1.0f - coatChance), u.y));
  }
  if (wi.z <= 0.0f) return std::nullopt;
  BsdfSample s;
  s.wi = wi;
  s.f = plasticBrdf(wo, wi, plastic);
  s.pdf = plasticPdf(wo, wi, plastic);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  return s;
}

float plasticPdf(const Vec3& wo, const Vec3& wi, const RoughPlastic& plastic) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const Vec3 h = glm::normalize(wo + wi);
  const float coatChance = coatProbability(wo, plastic);
  const float coat = visibleNormalPdf(wo, h, alphaFromRoughness(plastic.roughness)) / (4.0f * std::abs(glm::dot(wo, h)));
  return coatChance * coat + (1.0f - coatChance) * diffuseDirectionPdf(wi);
}

}  // namespace pathlab
