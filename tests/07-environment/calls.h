// Task 7's remote calls: the judge's view of the student's environment.cpp.
#pragma once

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "wire/call.h"
#include "tasks/environment.h"

namespace pathlab::calls {
// The distribution of a W x H map: its size, H + 1 marginal CDF entries and
// H rows of W + 1 conditional ones (core/environment_distribution.h).
struct DistributionShape {
  using Args = std::tuple<Image>;
  static uint64_t maxBytes(shape::Of<EnvironmentDistribution>, const Args& args) {
    const uint64_t w = uint64_t(std::max(0, std::get<0>(args).width)), h = uint64_t(std::max(0, std::get<0>(args).height));
    return 8 + 8 + (h + 1) * sizeof(float) + 8 + h * (w + 1) * sizeof(float) + sizeof(double);
  }
  static void read(wire::Reader& r, EnvironmentDistribution& d, const Args& args) {
    const Image& map = std::get<0>(args);
    wire::read(r, d.width);
    wire::read(r, d.height);
    if (d.width != map.width || d.height != map.height) {
      throw wire::WireError("a distribution of " + std::to_string(d.width) + " x " + std::to_string(d.height) +
                            " pixels for a map of " + std::to_string(map.width) + " x " + std::to_string(map.height));
    }
    const size_t w = size_t(std::max(0, map.width)), h = size_t(std::max(0, map.height));
    r.expectCount(h + 1, "the marginal CDF (height + 1 entries)");
    wire::readElements(r, d.marginalCdf, h + 1);
    r.expectCount(h * (w + 1), "the conditional CDFs (height rows of width + 1 entries)");
    wire::readElements(r, d.conditionalCdf, h * (w + 1));
    wire::read(r, d.totalWeight);
  }
};

PATHLAB_REMOTE_CALL(DirectionToEquirect, 1, shape::Fixed, Point2(Vec3));
PATHLAB_REMOTE_CALL(EquirectToDirection, 2, shape::Fixed, Vec3(Point2));
PATHLAB_REMOTE_CALL(LookupEnvironment, 3, shape::Fixed, Color(Image, Vec3));
PATHLAB_REMOTE_CALL(SampleUniformSphere, 4, shape::Fixed, Vec3(Vec2));
PATHLAB_REMOTE_CALL(BuildEnvironmentDistribution, 5, DistributionShape, EnvironmentDistribution(Image));
// One distribution, many draws or directions.
PATHLAB_REMOTE_CALL(SampleEnvironment, 6, shape::OnePer<1>,
                    std::vector<std::optional<EnvironmentSample>>(EnvironmentDistribution, std::vector<Vec2>));
PATHLAB_REMOTE_CALL(EnvironmentPdf, 7, shape::OnePer<1>, std::vector<float>(EnvironmentDistribution, std::vector<Vec3>));
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
