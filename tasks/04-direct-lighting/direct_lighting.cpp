// Task 4 — direct lighting with shadows
//
// Goal: the light that reaches a surface straight from the light sources and
// is reflected towards the camera — soft shadows from area lights, hard ones
// from point lights. Handout: tasks/04-direct-lighting/README.md
//
// Functions to write (declared in framework/tasks/direct_lighting.h):
//   T4.1 lambertianBrdf          the diffuse BRDF
//   T4.2 offsetRayOrigin         where a ray leaving a surface starts
//   T4.3 lightDirection          area -> solid angle: the two cosines
//   T4.4 estimateDirectLighting  the estimator, with shadow rays
//
// Check your work:
//   ./build/pathlab --integrator direct -o direct.png
//   ./build/pathlab debug --task 4 --view shadow-rays --pixel 200 250 -o rays.png
//   ctest --test-dir build -R 04-direct-lighting --output-on-failure
#include "tasks/direct_lighting.h"

#include <bit>
#include <cmath>
#include <cstdint>

#include "util/todo.h"

namespace pathlab {

// T4.1 — The Lambertian BRDF.
//
// A diffuse surface scatters equally in all directions: f(wo, wi) = albedo / pi.
// The 1/pi makes it conserve energy: the integral of f cos(theta) over the
// hemisphere is albedo (<= 1).
Color lambertianBrdf(const Color& albedo) {
  // TODO(T4.1): return the BRDF value.
  PATHLAB_TODO("T4.1");
  (void)albedo;
  return Color(0.0f);
}

// T4.2 — Ray origins off the surface.
//
// A hit point computed in float lies a little above or below the true
// surface; a ray started exactly there can hit the surface it leaves
// ("shadow acne"). Move the point to the side `direction` goes to:
//   n = geometricNormal, flipped if dot(n, direction) < 0
// A fixed epsilon (p + 1e-4 n) fails: too small at large coordinates, too
// big for small scenes. Instead (Ray Tracing Gems, chapter 6) move each
// coordinate by int(256 * n[a]) units in the last place of its float bit
// pattern (std::bit_cast<int32_t>), which scales with the coordinate; for
// |p[a]| < 1/32, where ulps are tiny, add n[a] / 65536 instead.
Point3 offsetRayOrigin(const Point3& p, const Vec3& geometricNormal, const Vec3& direction) {
  // TODO(T4.2): offset p along the flipped normal as above.
  PATHLAB_TODO("T4.2");
  (void)geometricNormal, (void)direction;
  return p;
}

// T4.3 — From a light point to a direction.
//
// The light was sampled uniformly by area: pdfArea = 1 / area. The estimator
// integrates over directions, so convert: a patch dA at distance r whose
// normal makes angle theta' with the direction back to the shading point
// covers the solid angle dw = cos(theta') dA / r^2, hence
//   pdfSolidAngle = pdfArea * r^2 / cos(theta'),   cos(theta') = -dot(sample.normal, wi).
// Lights emit on the side their normal points to: if cos(theta') <= 0 the
// light faces away, return nothing. Also return nothing if r = 0.
std::optional<LightDirection> lightDirection(const Point3& from, const AreaSample& sample) {
  // TODO(T4.3): wi, distance and the solid-angle pdf.
  PATHLAB_TODO("T4.3");
  (void)from, (void)sample;
  return std::nullopt;
}

// T4.4 — Direct lighting.
//
//   L_direct(wo) = integral over directions of f(wo, wi) Le(wi) cos(theta) dw
//
// Monte Carlo: draw wi with density p(wi), average f Le cos / p.
// Recipe:
//   1. Delta BSDFs (bsdf.isDelta(): mirror, glass) reflect no light source
//      directly: return black.
//   2. Each point light in context.lights.points (intensity I): one exact
//      sample, wi towards it, radiance f * I * cos(theta) / r^2.
//   3. Each area light in context.lights.areas: context.settings.lightSamples
//      samples light.sample(sampler.next2D()) -> lightDirection(...) -> add
//      f * sample.radiance * cos(theta) / pdfSolidAngle; divide the sum by
//      the number of samples.
//   4. The environment, if any (context.lights.environment): the same with
//      context.settings.lightSamples samples of
//      environment->sample(sampler.next2D()), which already gives wi, the
//      radiance and pdfSolidAngle; its shadow ray has no end (range max =
//      kInfinity).
//   5. For every sample: skip it if cos(theta) = dot(wi, bsdf.normal()) <= 0
//      or f is black; otherwise trace a shadow ray from
//        origin = offsetRayOrigin(hit.point, hit.geometricNormal, wi)
//      aimed at the light point: direction = normalize(lightPoint - origin),
//      context.occluded(ray, Interval{0, d * (1 - 1e-4)}) with
//      d = |lightPoint - origin|, and add the sample only if nothing blocks it.
//
// PITFALL: the shadow ray must stop just short of the light, or it hits the
// light's own surface and everything is in shadow.
// PITFALL: draw the two random numbers for a light sample before any
// `continue`, so every sample uses the same number of random values.
Color estimateDirectLighting(TraceContext& context, const Hit& hit, const Bsdf& bsdf, const Vec3& wo,
                             Sampler& sampler) {
  // TODO(T4.4): sum the point lights and the area lights as above.
  PATHLAB_TODO("T4.4");
  (void)context, (void)hit, (void)bsdf, (void)wo, (void)sampler;
  return Color(0.0f);
}

}  // namespace pathlab
