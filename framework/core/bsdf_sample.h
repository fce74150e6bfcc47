// A direction drawn from a BSDF: core data, so a task API (task 6's delta
// lobes) can return one without depending on the Bsdf class above it.
#pragma once

#include "util/math.h"

namespace pathlab {

// One convention for every lobe (pbrt's): the path weight of a sample is
// f |cos theta| / pdf. A delta lobe (mirror, glass) has no density; its pdf
// is the probability of choosing that lobe and its f carries 1 / |cos theta|
// (a mirror of reflectance R: f = R / |cos theta|, pdf = 1, weight R).
struct BsdfSample {
  Vec3 wi{0.0f};       // unit
  Color f{0.0f};       // BSDF value f(wo, wi); for a delta lobe (value x lobe probability) / |cos theta|
  float pdf = 0.0f;    // solid-angle density; for a delta lobe the probability of the lobe chosen
  bool isDelta = false;  // from a delta lobe: next-event estimation could not have found what wi sees
};

}  // namespace pathlab
