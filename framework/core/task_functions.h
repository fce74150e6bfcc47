// The task functions the core's services call, as tables of function
// pointers: a BVH leaf tests its primitives with task 2 (leaf_geometry.h), a
// Bsdf evaluates and samples its lobes with tasks 4, 5, 6 and 8 (bsdf.h), the
// environment light looks up and samples its map with task 7 (lights.h).
// The core declares the tables and never names a task; the render layer
// fills them with the task code the binary links (task_wiring.h). So the
// dependencies point one way, core <- tasks <- render, and a test can hand a
// service any function it likes.
#pragma once

#include <optional>

#include "core/bsdf_sample.h"
#include "core/environment_distribution.h"
#include "core/hit.h"
#include "core/microfacet_material.h"
#include "util/image.h"
#include "util/math.h"
#include "util/ray.h"

namespace pathlab {

// Task 2 (tasks/intersection.h).
struct PrimitiveTests {
  std::optional<TriangleHit> (*intersectTriangle)(const Ray&, Interval, const Point3&, const Point3&,
                                                  const Point3&) = nullptr;
  std::optional<float> (*intersectSphere)(const Ray&, Interval, const Point3&, float) = nullptr;
};

// Tasks 4, 5, 6 and 8 (tasks/direct_lighting.h, path_tracing.h, mirror_glass.h, microfacet.h).
struct BsdfLobes {
  Color (*lambertianBrdf)(const Color& albedo) = nullptr;
  Vec3 (*sampleDiffuseDirection)(Vec2 u) = nullptr;
  float (*diffuseDirectionPdf)(const Vec3& wi) = nullptr;
  BsdfSample (*sampleMirror)(const Vec3& wo, const Color& reflectance) = nullptr;
  BsdfSample (*sampleGlass)(const Vec3& wo, const Color& reflectance, const Color& transmittance, float ior,
                            float u) = nullptr;
  Color (*conductorBrdf)(const Vec3& wo, const Vec3& wi, const RoughConductor&) = nullptr;
  std::optional<BsdfSample> (*sampleConductor)(const Vec3& wo, Vec2 u, const RoughConductor&) = nullptr;
  float (*conductorPdf)(const Vec3& wo, const Vec3& wi, const RoughConductor&) = nullptr;
  Color (*plasticBrdf)(const Vec3& wo, const Vec3& wi, const RoughPlastic&) = nullptr;
  std::optional<BsdfSample> (*samplePlastic)(const Vec3& wo, Vec2 u, const RoughPlastic&) = nullptr;
  float (*plasticPdf)(const Vec3& wo, const Vec3& wi, const RoughPlastic&) = nullptr;
};

// Task 7 (tasks/environment.h).
struct EnvironmentMapFunctions {
  Point2 (*directionToEquirect)(const Vec3& direction) = nullptr;
  Color (*lookupEnvironment)(const Image& map, const Vec3& direction) = nullptr;
  Vec3 (*sampleUniformSphere)(Vec2 u) = nullptr;
  EnvironmentDistribution (*buildEnvironmentDistribution)(const Image& map) = nullptr;
  std::optional<EnvironmentSample> (*sampleEnvironment)(const EnvironmentDistribution&, Vec2 u) = nullptr;
  float (*environmentPdf)(const EnvironmentDistribution&, const Vec3& direction) = nullptr;
};

struct TaskFunctions {
  PrimitiveTests primitives;
  BsdfLobes lobes;
  EnvironmentMapFunctions environment;
};

}  // namespace pathlab
