// Task 10's remote calls: the judge's view of the student's thin_lens.cpp.
// Both functions run in the candidate on batches the judge sends.
#pragma once

#include <tuple>
#include <vector>

#include "wire/call.h"
#include "tasks/thin_lens.h"

namespace pathlab::calls {
// One lens ray's question: the pinhole ray through a film point, and the lens's random numbers.
using LensQuery = std::tuple<Ray /*pinhole*/, Vec2 /*uLens*/>;

PATHLAB_REMOTE_CALL(SampleUnitDisk, 1, shape::OnePer<0>, std::vector<Point2>(std::vector<Vec2>));
PATHLAB_REMOTE_CALL(GenerateThinLensRays, 2, shape::OnePer<2>, std::vector<Ray>(Camera, CameraBasis, std::vector<LensQuery>));
}  // namespace pathlab::calls

namespace pathlab::candidate {
// sampleUnitDisk(u) for each u.
inline std::vector<Point2> sampleUnitDisk(const std::vector<Vec2>& us) { return remote::call<calls::SampleUnitDisk>(us); }
// generateThinLensRay(camera, basis, pinhole, uLens) for each query.
inline std::vector<Ray> generateThinLensRays(const Camera& camera, const CameraBasis& basis,
                                             const std::vector<calls::LensQuery>& queries) {
  return remote::call<calls::GenerateThinLensRays>(camera, basis, queries);
}
}  // namespace pathlab::candidate
