// Task @N@'s remote calls: the judge's view of the student's @STEM@.cpp.
// Each runs in the candidate on a batch the judge sends.
#pragma once

#include <vector>

#include "wire/call.h"
#include "tasks/@STEM@.h"

namespace pathlab::calls {
PATHLAB_REMOTE_CALL(SampleTriangle, 1, shape::OnePer<0>, std::vector<Point2>(std::vector<Vec2>));
}  // namespace pathlab::calls

namespace pathlab::candidate {
// @STEM@::sampleTriangle(u) for each u.
inline std::vector<Point2> sampleTriangle(const std::vector<Vec2>& us) { return remote::call<calls::SampleTriangle>(us); }
}  // namespace pathlab::candidate
