// Task 12 — light in fog and jade: homogeneous participating media.
// Implemented in tasks/12-media/media.cpp (the student's file; where the task
// is not the student's, the programs link the course's reference in its
// place).
#pragma once

#include "core/bsdf.h"
#include "core/trace.h"
#include "util/random.h"
#include "util/ray.h"

namespace pathlab {

// T12.1: how far a ray travels in a homogeneous medium of extinction sigmaT
// before it scatters or is absorbed, drawn from u uniform in [0, 1): t with
// density sigmaT exp(-sigmaT t), up to the surface at tMax (kInfinity: none).
// The flights that would end past the surface stop at it: scattered is false,
// t = tMax, and pdf is the probability of that, exp(-sigmaT tMax).
struct FreeFlight {
  float t = 0.0f;
  bool scattered = false;  // true: the flight ends in the medium, at t < tMax
  float pdf = 0.0f;        // scattered: the density at t; else the probability of passing
};
FreeFlight sampleFreeFlight(float sigmaT, float tMax, float u);

// T12.2: the Henyey-Greenstein phase function, per unit solid angle, of the
// cosine between the direction a ray travelled and the direction it leaves
// in (g > 0: mostly onwards; g < 0: mostly back; 0: every way alike), and a
// direction drawn from it: unit, leaving a ray that travelled along the unit
// `direction`, from u uniform in [0, 1)^2.
float henyeyGreenstein(float cosTheta, float g);
Vec3 sampleHenyeyGreenstein(const Vec3& direction, float g, Vec2 u);

// A vertex where a path scatters: on a surface (hit and bsdf set: f times
// the cosine scatters light there) or at a point in a medium (both null:
// the phase function of g scatters it).
struct ScatteringVertex {
  Point3 point{0.0f};
  Vec3 wo{0.0f};              // unit, back the way the path came
  const Hit* hit = nullptr;   // on a surface
  const Bsdf* bsdf = nullptr;
  float g = 0.0f;             // in a medium

  static ScatteringVertex onSurface(const Hit& hit, const Bsdf& bsdf, const Vec3& wo) {
    return {hit.point, wo, &hit, &bsdf, 0.0f};
  }
  static ScatteringVertex inMedium(const Point3& point, const Vec3& wo, float g) {
    return {point, wo, nullptr, nullptr, g};
  }
};

// T12.3: the fraction of light that crosses the media along `ray` (unit
// direction) from its origin, in `medium`, to `distance`: through each
// interface surface (a medium's index-matched boundary, which changes the
// medium as the ray crosses it; past one, the walk goes on from an origin
// offset beyond it, for the rest of the way), 0 at any other surface. Any estimator whose
// expected value is that fraction will do; the sampler is there for one that
// needs random numbers; it draws them from nothing else (the same sampler
// gives the same answer: the suite compares a scene with its scaled copy).
float transmittance(TraceContext& context, Ray ray, float distance, MediumIndex medium, Sampler& sampler);

// T12.3: task 4's estimateDirectLighting at a vertex in `medium` (a surface
// point or a point in the medium: ScatteringVertex), with transmittance
// where task 4 had visibility.
Color estimateDirectLightingInMedia(TraceContext& context, const ScatteringVertex& vertex, MediumIndex medium,
                                    Sampler& sampler);

// T12.4: task 5's path tracer through media: the radiance arriving along
// `ray` (a camera ray, starting in the scene's medium). In a medium each
// step first draws a free flight: it scatters there (a bounce: direct
// lighting through the phase function, a new direction from it), or it
// reaches the surface and goes on as task 5 does; an interface surface only
// changes the medium.
Color tracePathInMedia(TraceContext& context, Ray ray, Sampler& sampler);

}  // namespace pathlab
