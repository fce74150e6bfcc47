// The task code this binary links — each task the student's or the
// reference, as CMake chose — as the core's table (task_functions.h): every
// task function a core service calls, in one list.
#pragma once

#include "core/task_functions.h"
#include "tasks/direct_lighting.h"
#include "tasks/environment.h"
#include "tasks/intersection.h"
#include "tasks/microfacet.h"
#include "tasks/mirror_glass.h"
#include "tasks/path_tracing.h"

namespace pathlab {

inline constexpr TaskFunctions kLinkedTasks{
    .primitives = {&intersectTriangle, &intersectSphere},
    .lobes = {&lambertianBrdf, &sampleDiffuseDirection, &diffuseDirectionPdf, &sampleMirror, &sampleGlass,
              &conductorBrdf, &sampleConductor, &conductorPdf, &plasticBrdf, &samplePlastic, &plasticPdf},
    .environment = {&directionToEquirect, &lookupEnvironment, &sampleUniformSphere, &buildEnvironmentDistribution,
                    &sampleEnvironment, &environmentPdf},
};

}  // namespace pathlab
