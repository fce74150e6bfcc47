// Task 5 — path tracing. Implemented in tasks/05-path-tracing/path_tracing.cpp
// (the student's file; where the task is not the student's, the programs
// link the course's reference in its place).
#pragma once

#include "core/trace.h"
#include "util/random.h"
#include "util/ray.h"

namespace pathlab {

// T5.1: a direction for a diffuse bounce, in the local frame (normal = +z),
// from u uniform in [0,1)^2; and the solid-angle pdf of choosing wi that way.
Vec3 sampleDiffuseDirection(Vec2 u);
float diffuseDirectionPdf(const Vec3& wi);

// T5.2: the radiance arriving along `ray` (a camera ray): emission, direct
// lighting at every vertex, bounces up to context.settings.maxDepth.
// Every random number comes from `sampler`, in any order: the same sampler
// gives the same path (the suite compares a scene with its copy 1024 times
// larger under the same random numbers).
Color tracePath(TraceContext& context, Ray ray, Sampler& sampler);

}  // namespace pathlab
