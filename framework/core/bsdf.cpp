#include "core/bsdf.h"

#include <cmath>

namespace pathlab {

Bsdf::Bsdf(const Material& material, const Hit& hit, const Vec3& wo, const BsdfLobes& lobes)
    : material_(material), lobes_(&lobes) {
  // Two-sided: look at the surface from the side wo leaves from.
  const float side = glm::dot(hit.geometricNormal, wo) < 0.0f ? -1.0f : 1.0f;
  geometricNormal_ = side * hit.geometricNormal;
  Vec3 n = side * hit.shadingNormal;
  if (glm::dot(n, geometricNormal_) <= 0.0f) n = geometricNormal_;  // a shading normal past the horizon
  frame_ = Frame::fromNormal(n);
  // Glass needs to know inside from outside: the frame of the outward normal
  // (made only for glass: a diffuse hit, the common case, never reads it).
  if (material.type == MaterialType::Glass) outwardFrame_ = side > 0.0f ? frame_ : Frame::fromNormal(-n);
}

Color Bsdf::f(const Vec3& wo, const Vec3& wi) const {
  if (isDelta()) return Color(0.0f);
  // Both directions above the surface, by the shading and the geometric normal.
  if (glm::dot(wi, frame_.n) <= 0.0f || glm::dot(wi, geometricNormal_) <= 0.0f || glm::dot(wo, frame_.n) <= 0.0f) {
    return Color(0.0f);
  }
  switch (material_.type) {
    case MaterialType::RoughConductor:
      return lobes_->conductorBrdf(frame_.toLocal(wo), frame_.toLocal(wi), material_.roughConductor());
    case MaterialType::RoughPlastic:
      return lobes_->plasticBrdf(frame_.toLocal(wo), frame_.toLocal(wi), material_.roughPlastic());
    default:
      return lobes_->lambertianBrdf(material_.albedo);
  }
}

float Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  if (isDelta()) return 0.0f;
  switch (material_.type) {
    case MaterialType::RoughConductor:
      return lobes_->conductorPdf(frame_.toLocal(wo), frame_.toLocal(wi), material_.roughConductor());
    case MaterialType::RoughPlastic:
      return lobes_->plasticPdf(frame_.toLocal(wo), frame_.toLocal(wi), material_.roughPlastic());
    default:
      return lobes_->diffuseDirectionPdf(frame_.toLocal(wi));
  }
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, Vec2 u) const {
  if (material_.type == MaterialType::Interface) {  // no surface: straight on, all of it (f cos / pdf = 1)
    const float cosine = std::abs(glm::dot(wo, frame_.n));
    if (!(cosine > 0.0f)) return std::nullopt;
    return BsdfSample{-wo, Color(1.0f / cosine), 1.0f, true};
  }
  if (isDelta()) {
    // Glass lives in the frame of its outward normal, not the side wo is on.
    const Frame& frame = material_.type == MaterialType::Glass ? outwardFrame_ : frame_;
    const Vec3 woLocal = frame.toLocal(wo);
    BsdfSample s = material_.type == MaterialType::Mirror
                       ? lobes_->sampleMirror(woLocal, material_.albedo)
                       : lobes_->sampleGlass(woLocal, material_.albedo, material_.transmittance, material_.ior, u.x);
    // A grazing direction (cos theta = 0) carries no light, and its f (value / |cos|) is not finite.
    if (!(glm::dot(s.wi, s.wi) > 0.0f) || !isFinite(s.wi) || !(std::abs(s.wi.z) > 0.0f) || !isFinite(s.f)) {
      return std::nullopt;
    }
    s.wi = glm::normalize(frame.toWorld(s.wi));
    s.isDelta = true;
    return s;
  }
  if (material_.isRough()) {
    const Vec3 woLocal = frame_.toLocal(wo);
    std::optional<BsdfSample> s = material_.type == MaterialType::RoughConductor
                                      ? lobes_->sampleConductor(woLocal, u, material_.roughConductor())
                                      : lobes_->samplePlastic(woLocal, u, material_.roughPlastic());
    if (!s || !(s->pdf > 0.0f) || !std::isfinite(s->pdf) || !isFinite(s->wi) || !(s->wi.z > 0.0f) || !isFinite(s->f)) {
      return std::nullopt;
    }
    s->wi = glm::normalize(frame_.toWorld(s->wi));
    s->isDelta = false;
    // Below the geometric surface (a shading normal that tilts): no light.
    if (glm::dot(s->wi, geometricNormal_) <= 0.0f) s->f = Color(0.0f);
    return s;
  }
  const Vec3 local = lobes_->sampleDiffuseDirection(u);
  const float pdf = lobes_->diffuseDirectionPdf(local);
  if (!(pdf > 0.0f) || !(local.z > 0.0f)) return std::nullopt;
  BsdfSample s;
  s.wi = glm::normalize(frame_.toWorld(local));
  s.pdf = pdf;
  s.f = f(wo, s.wi);
  return s;
}

}  // namespace pathlab
