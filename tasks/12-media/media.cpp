// Task 12 — light in fog and jade: homogeneous participating media
//
// Goal: light that scatters between the surfaces. Until now every ray flew
// through a vacuum from one surface to the next. In a medium (fog, smoke,
// milk, jade) light is scattered or absorbed along the way: a ray carries a
// visibility that fades with distance, and paths bend in mid-air. Here you
// sample where a ray scatters, in which direction it leaves, how much light
// a shadow ray lets through, and put them in task 5's loop. Handout:
// tasks/12-media/README.md
//
// Functions to write (declared in framework/tasks/media.h):
//   T12.1 sampleFreeFlight                 where a ray scatters, or that it reaches the surface
//   T12.2 henyeyGreenstein,                the phase function, and a direction drawn from it
//         sampleHenyeyGreenstein
//   T12.3 transmittance,                   shadow rays through media, and direct lighting with them
//         estimateDirectLightingInMedia
//   T12.4 tracePathInMedia                 task 5's path tracer through media
//
// Check your work:
//   ./build/pathlab media/scenes/fog-shafts.json -o fog.png
//   ./build/pathlab debug --task 12 --view phase media/scenes/fog-shafts.json -o phase.png
//   ctest --test-dir build -R 12-media --output-on-failure
#include "tasks/media.h"

#include <algorithm>
#include <cmath>

#include "tasks/direct_lighting.h"
#include "util/frame.h"
#include "util/todo.h"

namespace pathlab {

// T12.1 — The free flight.
//
// In a medium of extinction sigmaT a ray that has come t without an event
// meets one in the next dt with probability sigmaT dt, whatever t is: the
// distance to the first event has density
//   p(t) = sigmaT exp(-sigmaT t),   CDF  P(t) = 1 - exp(-sigmaT t).
// Inverting the CDF: t = -ln(1 - u) / sigmaT (or -ln(u) / sigmaT: 1 - u is
// as uniform as u; mind ln(0)). A flight longer than tMax, the distance to
// the surface the ray would hit, never happens in the medium: the ray
// reaches the surface instead, with probability
//   P(t >= tMax) = exp(-sigmaT tMax),
// the transmittance to the surface. Return the event, or the surface with
// that probability as its pdf.
//
// PITFALL: sigmaS in place of sigmaT samples too few events: absorption is
// an event too (the weight below accounts for it), and fog then looks thin.
FreeFlight sampleFreeFlight(float sigmaT, float tMax, float u) {
  // TODO(T12.1): t from the exponential distribution, or the surface at tMax.
  PATHLAB_TODO("T12.1");
  (void)sigmaT, (void)u;
  return {tMax, false, 1.0f};
}

// T12.2 — The Henyey-Greenstein phase function.
//
// Where light scatters, the phase function p says where it goes: a density
// over directions (it integrates to 1 over the sphere). Henyey and
// Greenstein's has one parameter, the mean cosine g:
//   p(cos) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^(3/2)),
// cos the cosine between the direction the ray travelled and the one it
// leaves in. With g = 0 it is 1 / (4 pi), every way alike; g > 0 sends
// light mostly onwards (fog, g ~ 0.8), g < 0 back. (The formula is
// symmetric in the two directions' roles: light and camera paths use it
// alike.)
//
// Sampling it by inverting the CDF of cos (phi is uniform in [0, 2 pi)):
//   g = 0:   cos = 1 - 2 u.x
//   else:    s = (1 - g^2) / (1 - g + 2 g u.x),   cos = (1 + g^2 - s^2) / (2 g)
// then a direction at that cosine around `direction`: Frame::fromNormal
// (util/frame.h) builds the axes. Near g = 0 the second form divides 0 by
// 0: use the first below |g| ~ 1e-3. Clamp cos into [-1, 1]: 1 + g^2 - s^2
// cancels, and rounding can leave it just outside (then sin = sqrt(1 - cos^2)
// is NaN).
//
// PITFALL: pbrt and others write the cosine against the direction back to
// the viewer, which flips the sign of g. Here g > 0 must mean onwards.
float henyeyGreenstein(float cosTheta, float g) {
  // TODO(T12.2): the phase function's value.
  PATHLAB_TODO("T12.2");
  (void)cosTheta, (void)g;
  return 0.0f;
}

Vec3 sampleHenyeyGreenstein(const Vec3& direction, float g, Vec2 u) {
  // TODO(T12.2): a direction with density henyeyGreenstein(dot(direction, wi), g).
  PATHLAB_TODO("T12.2");
  (void)g, (void)u;
  return direction;
}

// T12.3 — Transmittance, and direct lighting through media.
//
// A shadow ray in a medium is no longer a yes or a no: of the light that
// sets off along it, the fraction
//   T(d) = exp(-sigmaT d)
// arrives after a distance d (Beer-Lambert). Through several media,
// multiply their fractions. Walk the ray surface by surface up to
// `distance` with context.shadowHit (the closest hit, counted as a shadow
// ray):
//   - in a medium (medium != kVacuum), each stretch travelled multiplies
//     the fraction by exp(-scene.media[medium].sigmaT * length);
//   - an interface (material type MaterialType::Interface) is no surface:
//     go on past it (offsetRayOrigin, task 4) in the medium
//     scene.mediumAcross(hit, direction, medium) says is beyond;
//   - any other surface blocks the light: 0.
// Homogeneous media allow the exact value; an estimator whose expected
// value is T (the free flight passing the light, 1 or 0) is also right,
// only noisier.
//
// Direct lighting at a vertex is then task 4's, with two changes:
//   - the transmittance of the shadow ray where task 4 had visibility;
//   - on a surface (vertex.bsdf set) light is scattered by f(wo, wi) cos;
//     in a medium (vertex.bsdf null) by the phase function,
//     henyeyGreenstein(dot(-vertex.wo, wi), vertex.g), with no cosine: a
//     point in a medium has no surface to be foreshortened on.
// Shadow rays leave a surface from offsetRayOrigin, a medium point from
// the point itself.
//
// PITFALL: a shadow ray that ignores the medium lights the fog's far side
// as brightly as its near side: no shafts, surfaces too bright.
float transmittance(TraceContext& context, Ray ray, float distance, MediumIndex medium, Sampler& sampler) {
  // TODO(T12.3): the product of exp(-sigmaT length) along the ray, through interfaces; 0 at a surface.
  PATHLAB_TODO("T12.3");
  (void)context, (void)ray, (void)distance, (void)medium, (void)sampler;
  return 1.0f;
}

Color estimateDirectLightingInMedia(TraceContext& context, const ScatteringVertex& vertex, MediumIndex medium,
                                    Sampler& sampler) {
  // TODO(T12.3): task 4's direct lighting, with transmittance and the phase function.
  PATHLAB_TODO("T12.3");
  (void)context, (void)vertex, (void)medium, (void)sampler;
  return Color(0.0f);
}

// T12.4 — The path tracer through media.
//
// Task 5's loop, with a medium to cross before each surface. The path
// starts in scene.medium. At each step, with `hit` the next surface:
//   1. in a medium, draw a free flight up to hit's distance (T12.1).
//      - It scatters at t: the point x = o + t d is a vertex. The path's
//        weight gains sigmaS T(t) / p(t) = sigmaS / sigmaT = albedo (the
//        exponentials cancel: compute the albedo, not the ratio, which is
//        0 / 0 in a dense medium). A medium has no emission. Count the
//        bounce against maxDepth as task 5 does, add direct lighting at x
//        (T12.3), and go on from x along a direction from the phase
//        function (T12.2: weight p / pdf = 1).
//      - It reaches the surface: the weight gains T(tMax) / P(pass) = 1.
//   2. at the surface (or the environment, on a miss), as task 5; except
//      that an interface is no bounce and no vertex: go straight on past
//      it in the medium beyond. After a BSDF sample through glass, the
//      medium is scene.mediumAcross(hit, wi, medium) too.
// Emission and the environment are counted as task 5 counts them: only
// where no direct-lighting estimate already did (the camera ray, and after
// mirror or glass); an interface leaves that as it was before it.
//
// PITFALL: in a medium that absorbs nothing (albedo 1) under a uniform sky
// of radiance 1, every path must return 1 on average, however often it
// scatters. Too dark: the surface weight lacks 1 / P(pass), or scattering
// is treated as absorption (the albedo of 1 lost).
Color tracePathInMedia(TraceContext& context, Ray ray, Sampler& sampler) {
  // TODO(T12.4): task 5's loop through media.
  PATHLAB_TODO("T12.4");
  (void)context, (void)ray, (void)sampler;
  return Color(0.0f);
}

}  // namespace pathlab
