// The image tests' remote call: the candidate renders a scene the judge
// sends, with its linked task code, and returns each pixel's sample mean and
// the variance of that mean (../support/render_moments.h).
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <tuple>

#include "render_moments.h"
#include "wire/call.h"

namespace pathlab::calls {
// A render of the size asked for: width x height means and variances, with
// the request's samples per pixel; its count of NaN or Inf samples at most
// the samples it can have taken.
struct MomentsShape {
  using Args = std::tuple<Scene, test::ImageOptions>;
  static size_t pixels(const Args& args) {
    const RenderSettings& r = std::get<0>(args).render;
    return size_t(std::max(0, r.width)) * size_t(std::max(0, r.height));
  }
  static uint64_t maxBytes(shape::Of<test::PixelMoments>, const Args& args) {
    const uint64_t n = pixels(args);
    return 3 * sizeof(int) + 2 * (8 + n * sizeof(Color)) + sizeof(uint64_t) + 1;
  }
  static void read(wire::Reader& r, test::PixelMoments& m, const Args& args) {
    const RenderSettings& asked = std::get<0>(args).render;
    const std::optional<AdaptiveSettings>& adaptive = std::get<1>(args).adaptive;
    wire::read(r, m.width);
    wire::read(r, m.height);
    wire::read(r, m.spp);
    if (m.width != asked.width || m.height != asked.height || m.spp != asked.samplesPerPixel) {
      throw wire::WireError("an image of " + std::to_string(m.width) + " x " + std::to_string(m.height) + " at " +
                            std::to_string(m.spp) + " samples per pixel; the request asked for " +
                            std::to_string(asked.width) + " x " + std::to_string(asked.height) + " at " +
                            std::to_string(asked.samplesPerPixel));
    }
    const size_t n = pixels(args);
    r.expectCount(n, "the pixels' means");
    wire::readElements(r, m.mean, n);
    r.expectCount(n, "the pixels' variances");
    wire::readElements(r, m.varianceOfMean, n);
    wire::read(r, m.nonFinite);
    const uint64_t perPixel = uint64_t(std::max(asked.samplesPerPixel, adaptive ? int(adaptive->maxSpp) : 0));
    if (m.nonFinite > uint64_t(n) * std::max<uint64_t>(perPixel, 1)) {
      throw wire::WireError(std::to_string(m.nonFinite) + " NaN or Inf samples, more than the render took");
    }
    wire::read(r, m.usedBvh);
  }
};

PATHLAB_REMOTE_CALL(RenderMoments, 110, MomentsShape, test::PixelMoments(Scene, test::ImageOptions));
}  // namespace pathlab::calls

namespace pathlab::wire {
template <>
struct Fields<test::ImageOptions> {
  static auto tie(test::ImageOptions& s) { return std::tie(s.integrator, s.environmentSampling, s.adaptive); }
};
template <>
struct Fields<test::PixelMoments> {
  static auto tie(test::PixelMoments& s) {
    return std::tie(s.width, s.height, s.spp, s.mean, s.varianceOfMean, s.nonFinite, s.usedBvh);
  }
  static constexpr const char* names = "width, height, spp, mean, varianceOfMean, nonFinite, usedBvh";
};
}  // namespace pathlab::wire

namespace pathlab::candidate {
inline test::PixelMoments renderMoments(const Scene& scene, const test::ImageOptions& options) {
  return remote::call<calls::RenderMoments>(scene, options);
}
}  // namespace pathlab::candidate
