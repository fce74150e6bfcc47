// COLLADA materials: the common profile's diffuse colour and the course's
// extensions (emission, mirror, glass), with CS184's <microfacet> and
// <refraction> approximated by the closest PathLab material.
#include <cstdio>

#include "scene/collada_document.h"
#include "util/error.h"

namespace pathlab::collada {
namespace {

// CS184's <microfacet> (alpha, eta, k): a rough conductor. PathLab has no
// glossy material, so it becomes the closest of its own: a mirror when
// nearly smooth (alpha <= 0.1, where the lobe is a blurred reflection),
// otherwise diffuse (the lobe spreads over the hemisphere). Either way in
// the metal's colour, its Fresnel reflectance at normal incidence
// ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2) per channel: the effect's
// Blender diffuse colour says nothing about the metal. Without eta and k,
// the effect's diffuse colour is kept.
void approximateMicrofacet(const Document& doc, Material& m, pugi::xml_node microfacet, const std::string& effectWhere,
                           const std::string& profile, const ApproximationNote& noteApproximation) {
  const std::string here = effectWhere + "/microfacet";
  std::string what = "has a " + profile + " <microfacet> material";
  float alpha = 0.5f;
  if (pugi::xml_node a = microfacet.child("alpha")) {
    alpha = doc.numbers(a, here + "/alpha", 1)[0];
    if (!(alpha >= 0.0f)) doc.fail(here + "/alpha", "must not be negative");
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, " (alpha %g)", double(alpha));
    what += buffer;
  }
  what += ", which PathLab does not have; it is rendered as ";
  const bool smooth = alpha <= 0.1f;
  m.type = smooth ? MaterialType::Mirror : MaterialType::Diffuse;
  what += smooth ? "a mirror" : "diffuse";
  if (microfacet.child("eta") && microfacet.child("k")) {
    const Color eta = doc.color(microfacet.child("eta"), here + "/eta"), k = doc.color(microfacet.child("k"), here + "/k");
    const Color k2 = k * k;
    m.albedo = glm::clamp(((eta - 1.0f) * (eta - 1.0f) + k2) / ((eta + 1.0f) * (eta + 1.0f) + k2), 0.0f, 1.0f);
    what += " in the metal's colour at normal incidence " + formatted(m.albedo);
  } else {
    what += " in the effect's diffuse colour " + formatted(m.albedo);
  }
  noteApproximation(effectWhere, what);
}

}  // namespace

Material readMaterial(const Document& doc, pugi::xml_node material, const ApproximationNote& noteApproximation) {
  const std::string name = material.attribute("id").value();
  pugi::xml_node effect = doc.resolve(material.child("instance_effect").attribute("url").value(),
                                  "material \"" + name + "\"/instance_effect");
  const std::string effectWhere = std::string("effect \"") + effect.attribute("id").value() + "\"";
  Material m;
  m.name = name;
  // The common profile's diffuse colour (phong, blinn or lambert).
  pugi::xml_node common = effect.child("profile_COMMON").child("technique");
  for (const char* model : {"phong", "blinn", "lambert"}) {
    if (pugi::xml_node c = common.child(model).child("diffuse").child("color")) {
      m.albedo = glm::clamp(doc.color(c, effectWhere + "/diffuse"), 0.0f, 1.0f);
    }
  }
  if (pugi::xml_node technique = collada::Document::courseTechnique(effect)) {
    const std::string profile = technique.attribute("profile").value();
    if (pugi::xml_node emission = technique.child("emission")) {
      m.emission = doc.color(emission.child("radiance"), effectWhere + "/emission/radiance");
      m.albedo = Color(0.0f);  // the course's emitters reflect nothing
    } else if (pugi::xml_node mirror = technique.child("mirror")) {
      m.type = MaterialType::Mirror;
      m.albedo = glm::clamp(doc.color(mirror.child("reflectance"), effectWhere + "/mirror/reflectance"), 0.0f, 1.0f);
    } else if (pugi::xml_node glass = technique.child("glass")) {
      m.type = MaterialType::Glass;
      m.albedo = glm::clamp(doc.color(glass.child("reflectance"), effectWhere + "/glass/reflectance"), 0.0f, 1.0f);
      m.transmittance = glm::clamp(doc.color(glass.child("transmittance"), effectWhere + "/glass/transmittance"), 0.0f, 1.0f);
      m.ior = doc.numbers(glass.child("ior"), effectWhere + "/glass/ior", 1)[0];
      if (!(m.ior > 0.0f)) doc.fail(effectWhere + "/glass/ior", "must be positive");
    } else if (pugi::xml_node microfacet = technique.child("microfacet")) {
      approximateMicrofacet(doc, m, microfacet, effectWhere, profile, noteApproximation);
    } else if (pugi::xml_node refraction = technique.child("refraction")) {
      // CS184's RefractionBSDF: refraction only, no Fresnel reflection.
      // Glass that reflects nothing is the closest; it still loses the
      // Fresnel-reflected share instead of refracting it.
      m.type = MaterialType::Glass;
      m.albedo = Color(0.0f);
      m.transmittance =
          glm::clamp(doc.color(refraction.child("transmittance"), effectWhere + "/refraction/transmittance"), 0.0f, 1.0f);
      m.ior = doc.numbers(refraction.child("ior"), effectWhere + "/refraction/ior", 1)[0];
      if (!(m.ior > 0.0f)) doc.fail(effectWhere + "/refraction/ior", "must be positive");
      noteApproximation(effectWhere, "has a " + profile + " <refraction> material, which PathLab does not have; "
                                     "it is rendered as glass that reflects nothing");
    } else if (pugi::xml_node other = technique.first_child()) {
      doc.fail(effectWhere, std::string("material type <") + other.name() +
                            "> is not supported (diffuse, emission, mirror, glass; microfacet and refraction are "
                            "approximated)");
    }
  }
  return m;
}

}  // namespace pathlab::collada
