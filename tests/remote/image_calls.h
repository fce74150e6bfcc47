// The image tests' remote call: the candidate renders a scene the judge
// sends, with its linked task code, and returns each pixel's sample mean and
// the variance of that mean (../support/render_moments.h).
#pragma once

#include "../support/render_moments.h"
#include "call.h"

namespace pathlab::calls {
PATHLAB_REMOTE_CALL(RenderMoments, 110, test::PixelMoments(Scene, test::ImageOptions));
}  // namespace pathlab::calls

namespace pathlab::wire {
template <>
struct Fields<test::ImageOptions> {
  static auto tie(test::ImageOptions& s) { return std::tie(s.integrator, s.environmentSampling, s.adaptive); }
};
template <>
struct Fields<test::PixelMoments> {
  static auto tie(test::PixelMoments& s) {
    return std::tie(s.width, s.height, s.spp, s.mean, s.varianceOfMean, s.nonFinite, s.usedBvh, s.samples);
  }
};
}  // namespace pathlab::wire

namespace pathlab::candidate {
inline test::PixelMoments renderMoments(const Scene& scene, const test::ImageOptions& options) {
  return remote::call<calls::RenderMoments>(scene, options);
}
}  // namespace pathlab::candidate
