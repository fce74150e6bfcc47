// A direction drawn from a BSDF: core data, so a task API (task 6's delta
// lobes) can return one without depending on the Bsdf class above it.
#pragma once

#include "pathlab/math.h"

namespace pathlab {

struct BsdfSample {
  Vec3 wi{0.0f};       // unit
  Color f{0.0f};       // BSDF value f(wo, wi); for a delta lobe the whole weight f cos / pdf
  float pdf = 0.0f;    // solid-angle density; for a delta lobe the probability of the lobe chosen
  bool isDelta = false;
};

}  // namespace pathlab
