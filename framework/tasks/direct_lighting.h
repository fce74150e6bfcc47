// Task 4 — direct lighting with shadows. Implemented in
// tasks/04-direct-lighting/direct_lighting.cpp (the student's file; where the
// task is not the student's, the programs link the course's reference in its
// place).
#pragma once

#include <optional>

#include "core/bsdf.h"
#include "core/lights.h"
#include "core/trace.h"
#include "util/random.h"

namespace pathlab {

// T4.1: the Lambertian BRDF, constant over all pairs of directions.
Color lambertianBrdf(const Color& albedo);

// T4.2: a ray origin just off the surface at p, on the side `direction`
// leaves towards, far enough that the new ray cannot hit the surface it
// starts on at any scale, near enough that nothing visible is skipped.
Point3 offsetRayOrigin(const Point3& p, const Vec3& geometricNormal, const Vec3& direction);

// The direction from a shading point to a point sampled on a light.
struct LightDirection {
  Vec3 wi{0.0f};               // unit, from the shading point towards the light point
  float distance = 0.0f;       // to the light point
  float pdfSolidAngle = 0.0f;  // density of wi per unit solid angle
};

// T4.3: turn a light point sampled by area into a direction with a solid-angle
// pdf; nothing if the light faces away from `from` (or `from` is on it).
std::optional<LightDirection> lightDirection(const Point3& from, const AreaSample& sample);

// T4.4: the radiance reflected towards wo at `hit` by light arriving straight
// from the lights (no bounces), with shadows: one sample per point light,
// context.settings.lightSamples samples per area light and of the environment.
// Every random number comes from `sampler`, in any order: the same sampler
// gives the same estimate (the suite compares a scene with its moved, turned
// and resized copy under the same random numbers).
Color estimateDirectLighting(TraceContext& context, const Hit& hit, const Bsdf& bsdf, const Vec3& wo,
                             Sampler& sampler);

}  // namespace pathlab
