// The task code this binary links — each task the student's or the
// reference, as CMake chose — as the core's table (task_functions.h): every
// task function a core service calls, in one list.
#pragma once

#include "pathlab/task_functions.h"
#include "pathlab/tasks/direct_lighting.h"
#include "pathlab/tasks/environment.h"
#include "pathlab/tasks/intersection.h"
#include "pathlab/tasks/mirror_glass.h"
#include "pathlab/tasks/path_tracing.h"

namespace pathlab {

inline constexpr TaskFunctions kLinkedTasks{
    .primitives = {&intersectTriangle, &intersectSphere},
    .lobes = {&lambertianBrdf, &sampleDiffuseDirection, &diffuseDirectionPdf, &sampleMirror, &sampleGlass},
    .environment = {&directionToEquirect, &lookupEnvironment, &sampleUniformSphere, &buildEnvironmentDistribution,
                    &sampleEnvironment, &environmentPdf},
};

}  // namespace pathlab
