// Task 6 — mirror and glass
//
// Goal: surfaces that reflect and refract like a mirror and like glass:
// reflections, refraction, caustics. Handout: tasks/06-mirror-glass/README.md
//
// Functions to write (declared in framework/tasks/mirror_glass.h):
//   T6.1 reflect         the mirror direction
//   T6.2 refract         Snell's law, and total internal reflection
//   T6.3 schlickFresnel  how much light reflects off glass
//   T6.4 sampleMirror    the perfect mirror as a delta BSDF
//   T6.5 sampleGlass     glass: reflect or refract, chosen by Fresnel
//
// All directions are in the local frame: the normal is +z and points to the
// outside (index 1); wo and wi point away from the surface.
//
// Check your work:
//   ./build/pathlab media/scenes/cornell-mirror-glass.json -s 256 -o glass.png
//   ./build/pathlab debug --task 6 --view lobe --pixel 130 200 media/scenes/cornell-mirror-glass.json -o lobe.png
//   ctest --test-dir build -R 06-mirror-glass --output-on-failure
#include "tasks/mirror_glass.h"

#include <cmath>

#include "util/todo.h"

namespace pathlab {

// T6.1 — Reflection about the normal +z: the angle out equals the angle in,
// in the same plane: wi = -wo + 2 (wo . n) n = (-wo.x, -wo.y, wo.z).
Vec3 reflect(const Vec3& wo) {
  // TODO(T6.1): the mirror direction.
  PATHLAB_TODO("T6.1");
  return wo;
}

// T6.2 — Refraction (Snell's law: n_o sin(theta_o) = n_t sin(theta_t)).
//
// If wo.z > 0 the light path enters the glass: eta = n_o / n_t = 1 / ior;
// otherwise it leaves: eta = ior. With cos_i = |wo.z|:
//   sin^2(theta_t) = eta^2 (1 - cos_i^2); if >= 1: total internal reflection, return nothing.
//   cos_t = sqrt(1 - sin^2(theta_t))
//   wi = (-eta wo.x, -eta wo.y, -sign(wo.z) cos_t)    (on the other side)
// PITFALL: the ratio flips when leaving; forgetting it makes glass spheres
// look hollow and breaks the white furnace.
std::optional<Vec3> refract(const Vec3& wo, float ior) {
  // TODO(T6.2): Snell's law with the entering/leaving flip.
  PATHLAB_TODO("T6.2");
  (void)wo, (void)ior;
  return std::nullopt;
}

// T6.3 — Schlick's approximation of Fresnel reflectance:
//   R0 = ((1 - ior) / (1 + ior))^2,   R(theta) = R0 + (1 - R0) (1 - cos(theta))^5
// with theta measured on the outside (index 1) side: at normal incidence
// R = R0 (4 % for ior 1.5), at grazing R -> 1.
float schlickFresnel(float cosTheta, float ior) {
  // TODO(T6.3): Schlick's formula.
  PATHLAB_TODO("T6.3");
  (void)cosTheta, (void)ior;
  return 0.0f;
}

// T6.4 — The perfect mirror reflects all light into one direction: a delta
// distribution. It cannot be evaluated for arbitrary wi (f = 0 there; direct
// lighting skips it), only sampled: wi = reflect(wo). The path tracer weighs
// every sample by f |cos theta| / pdf (task 5), so a delta lobe stores
//   f = reflectance / |cos theta|,  pdf = 1,  isDelta = true,
// with cos theta = wi.z: the weight is then the reflectance.
BsdfSample sampleMirror(const Vec3& wo, const Color& reflectance) {
  // TODO(T6.4): the mirror sample.
  PATHLAB_TODO("T6.4");
  (void)wo, (void)reflectance;
  return BsdfSample{};
}

// T6.5 — Glass reflects a fraction F (Fresnel) and transmits 1 - F.
// Choose one, and store f as in T6.4 (the lobe's value over |cos theta|):
//   u < F:  reflect,  f = reflectance * F / |cos theta|,  pdf = F
//   else:   refract,  f = transmittance * (1 - F) * (n_o / n_t)^2 / |cos theta|,
//           pdf = 1 - F
// so each weight f |cos theta| / pdf is (value * probability) / probability:
// the reflectance, or the transmittance times (n_o / n_t)^2. On total
// internal reflection always reflect (f = reflectance / |cos theta|, pdf = 1).
//
// The cosine for Schlick is the one on the outside side: wo.z when entering,
// |wi.z| of the refracted direction when leaving.
// PITFALL: at ior = 1 there is no interface and F must be 0, but Schlick's
// (1 - cos)^5 term is not: use F = 0 for ior == 1.
// (n_o / n_t)^2: radiance over n^2 is what stays constant across the boundary;
// n_o is the index on wo's side, n_t on wi's side.
// PITFALL: set isDelta = true: the path tracer then counts the emission the
// next ray finds, which direct lighting could not sample.
BsdfSample sampleGlass(const Vec3& wo, const Color& reflectance, const Color& transmittance, float ior, float u) {
  // TODO(T6.5): choose reflection or refraction by Fresnel.
  PATHLAB_TODO("T6.5");
  (void)wo, (void)reflectance, (void)transmittance, (void)ior, (void)u;
  return BsdfSample{};
}

}  // namespace pathlab
