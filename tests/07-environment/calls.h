// Task 7's remote calls: the judge's view of the student's environment.cpp.
#pragma once

#include <vector>

#include "../remote/call.h"
#include "tasks/environment.h"

namespace pathlab::calls {
PATHLAB_REMOTE_CALL(DirectionToEquirect, 1, Point2(Vec3));
PATHLAB_REMOTE_CALL(EquirectToDirection, 2, Vec3(Point2));
PATHLAB_REMOTE_CALL(LookupEnvironment, 3, Color(Image, Vec3));
PATHLAB_REMOTE_CALL(SampleUniformSphere, 4, Vec3(Vec2));
PATHLAB_REMOTE_CALL(BuildEnvironmentDistribution, 5, EnvironmentDistribution(Image));
// One distribution, many draws or directions.
PATHLAB_REMOTE_CALL(SampleEnvironment, 6,
                    std::vector<std::optional<EnvironmentSample>>(EnvironmentDistribution, std::vector<Vec2>));
PATHLAB_REMOTE_CALL(EnvironmentPdf, 7, std::vector<float>(EnvironmentDistribution, std::vector<Vec3>));
}  // namespace pathlab::calls

namespace pathlab::candidate {
inline Point2 directionToEquirect(const Vec3& direction) { return remote::call<calls::DirectionToEquirect>(direction); }
inline Vec3 equirectToDirection(Point2 uv) { return remote::call<calls::EquirectToDirection>(uv); }
inline Color lookupEnvironment(const Image& map, const Vec3& direction) {
  return remote::call<calls::LookupEnvironment>(map, direction);
}
inline std::vector<Vec3> sampleUniformSphere(const std::vector<Vec2>& us) {
  return remote::callMany<calls::SampleUniformSphere>({us.begin(), us.end()});
}
inline EnvironmentDistribution buildEnvironmentDistribution(const Image& map) {
  return remote::call<calls::BuildEnvironmentDistribution>(map);
}
inline std::vector<std::optional<EnvironmentSample>> sampleEnvironment(const EnvironmentDistribution& distribution,
                                                                       const std::vector<Vec2>& us) {
  return remote::call<calls::SampleEnvironment>(distribution, us);
}
inline std::optional<EnvironmentSample> sampleEnvironment(const EnvironmentDistribution& distribution, Vec2 u) {
  return sampleEnvironment(distribution, std::vector<Vec2>{u}).at(0);
}
inline std::vector<float> environmentPdf(const EnvironmentDistribution& distribution, const std::vector<Vec3>& directions) {
  return remote::call<calls::EnvironmentPdf>(distribution, directions);
}
inline float environmentPdf(const EnvironmentDistribution& distribution, const Vec3& direction) {
  return environmentPdf(distribution, std::vector<Vec3>{direction}).at(0);
}
}  // namespace pathlab::candidate
