// Task 6 — mirror and glass. Implemented in tasks/06-mirror-glass/mirror_glass.cpp
// (the student's file; where the task is not the student's, the programs
// link the course's reference in its place).
// Every direction here is in the local shading frame: the surface normal is
// +z, pointing outside (into the medium of index 1); directions are unit and
// point away from the surface.
#pragma once

#include <optional>

#include "core/bsdf_sample.h"
#include "util/math.h"

namespace pathlab {

// T6.1: the mirror direction of wo about the normal +z.
Vec3 reflect(const Vec3& wo);

// T6.2: the direction refracted from wo through a boundary between outside
// (index 1, the +z side) and inside (index `ior`), by Snell's law; nothing on
// total internal reflection. wo may be on either side; wi is on the other.
std::optional<Vec3> refract(const Vec3& wo, float ior);

// T6.3: Schlick's approximation of the Fresnel reflectance for light arriving
// at angle theta (cosTheta = cos of the angle on the outside, index 1, side).
float schlickFresnel(float cosTheta, float ior);

// T6.4: the perfect mirror: a delta lobe. f = reflectance / |cos theta|
// and pdf = 1, so the path weight f |cos theta| / pdf is the reflectance
// (bsdf_sample.h: one convention for every lobe).
BsdfSample sampleMirror(const Vec3& wo, const Color& reflectance);

// T6.5: smooth glass: reflect with the Fresnel probability, else refract.
// `u` in [0, 1) chooses. `pdf` is the probability of the lobe chosen and `f`
// is such that f |cos theta| / pdf is that lobe's path weight.
BsdfSample sampleGlass(const Vec3& wo, const Color& reflectance, const Color& transmittance, float ior, float u);

}  // namespace pathlab
