// Task @N@'s remote calls: the judge's view of the student's @STEM@.cpp.
// Each runs in the candidate on a batch the judge sends.
#pragma once

#include <vector>

#include "wire/call.h"
#include "tasks/@STEM@.h"

// This task's own value type on the wire (grader/wire/wire.h).
namespace pathlab::wire {
PATHLAB_WIRE_FIELDS(@STEM@::ConeSample, s.direction, s.pdf);
}  // namespace pathlab::wire

namespace pathlab::calls {
// Several arguments, asked in a batch: remote::callMany<ConeCosThetaMax>({{x, center, radius}, ...}).
PATHLAB_REMOTE_CALL(ConeCosThetaMax, 1, shape::Fixed, float(Point3, Point3, float));
// One answer per element of argument 2 (the u's, or the directions).
PATHLAB_REMOTE_CALL(SampleCone, 2, shape::OnePer<2>, std::vector<@STEM@::ConeSample>(Vec3, float, std::vector<Vec2>));
PATHLAB_REMOTE_CALL(ConePdf, 3, shape::OnePer<2>, std::vector<float>(Vec3, float, std::vector<Vec3>));
}  // namespace pathlab::calls

namespace pathlab::candidate {
// @STEM@::coneCosThetaMax for each (x, center, radius).
inline std::vector<float> coneCosThetaMax(const std::vector<calls::ConeCosThetaMax::Args>& spheres) {
  return remote::callMany<calls::ConeCosThetaMax>(spheres);
}
// @STEM@::sampleCone(axis, cosThetaMax, u) for each u.
inline std::vector<@STEM@::ConeSample> sampleCone(Vec3 axis, float cosThetaMax, const std::vector<Vec2>& us) {
  return remote::call<calls::SampleCone>(axis, cosThetaMax, us);
}
// @STEM@::conePdf(axis, cosThetaMax, w) for each w.
inline std::vector<float> conePdf(Vec3 axis, float cosThetaMax, const std::vector<Vec3>& directions) {
  return remote::call<calls::ConePdf>(axis, cosThetaMax, directions);
}
}  // namespace pathlab::candidate
