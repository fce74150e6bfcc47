// Task 7's data: core, so the environment light (lights.h) can hold a
// distribution without depending on the task that builds it.
#pragma once

#include <vector>

#include "util/math.h"

namespace pathlab {

// The 2D distribution for importance sampling a map: the weight of pixel
// (i, j) is luminance(i, j) * sin(theta_j), theta_j at the row's centre.
struct EnvironmentDistribution {
  int width = 0;
  int height = 0;
  std::vector<float> marginalCdf;     // height + 1 entries: 0, ..., 1 over rows
  std::vector<float> conditionalCdf;  // height rows of width + 1 entries: 0, ..., 1 within the row
  double totalWeight = 0.0;           // sum of all weights; 0 for a black map
};

struct EnvironmentSample {
  Vec3 direction{0.0f};
  float pdfSolidAngle = 0.0f;
};

}  // namespace pathlab
