// What the image tests compare: each pixel's sample mean and the variance
// of that mean, from a render taken exactly as render() takes it (same
// camera samples, same random streams). The candidate computes them with the
// student's task; the reference images were computed the same way with the
// reference (tools/make-reference-images).
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <vector>

#include "render/render.h"
#include "render/task_wiring.h"
#include "util/parallel.h"

namespace pathlab::test {

// The render options an image test may vary (the rest are render()'s defaults).
struct ImageOptions {
  Integrator integrator = Integrator::Path;
  EnvironmentSampling environmentSampling = EnvironmentSampling::Importance;
  // Task 11: each pixel by samplePixelAdaptively, at most scene.render's
  // samples per pixel (the reference image: that many times 16, uniformly).
  std::optional<AdaptiveSettings> adaptive{};
};

struct PixelMoments {
  int width = 0, height = 0, spp = 0;
  std::vector<Color> mean;            // per pixel, over its finite samples
  std::vector<Color> varianceOfMean;  // the sample variance / the number of samples
  uint64_t nonFinite = 0;             // NaN or Inf samples (left out of the moments)
  bool usedBvh = false;               // false: task 3's tree was not usable, brute force ran instead
};

// A render as render() takes it, for the image tests: the scene's BVH,
// lights and camera, and each pixel's sample i from estimatePixelSample
// with independent samples (only for them is the variance of a pixel's mean
// the sample variance over n, which the image tests' z-scores rely on).
class PixelSampler {
 public:
  PixelSampler(const Scene& scene, const ImageOptions& imageOptions)
      : scene_(scene), accelerator_(scene),
        lights_(Lights::fromScene(scene, kLinkedTasks.environment, imageOptions.environmentSampling)),
        basis_(cameraBasis(scene.camera)) {
    options_.integrator = imageOptions.integrator;
    options_.environmentSampling = imageOptions.environmentSampling;
    options_.sampler = SampleSequence::Independent;
    options_.progress = false;
  }
  bool usesBvh() const { return accelerator_.usesBvh(); }
  TraceContext context() const { return TraceContext(scene_, accelerator_, lights_, kLinkedTasks.lobes); }
  Color sample(TraceContext& context, IVec2 pixel, uint32_t i) const {
    context.pixel = pixel;
    return estimatePixelSample(context, options_, basis_, i);
  }

 private:
  const Scene& scene_;
  RenderOptions options_;
  const Accelerator accelerator_;
  const Lights lights_;
  const CameraBasis basis_;
};

// scene.render gives the size, samples per pixel, seed, -m and -l.
inline PixelMoments renderMoments(const Scene& scene, const ImageOptions& imageOptions, int threads = 0) {
  const PixelSampler sampler(scene, imageOptions);
  PixelMoments m;
  m.width = scene.render.width;
  m.height = scene.render.height;
  m.spp = scene.render.samplesPerPixel;
  m.mean.assign(size_t(m.width) * size_t(m.height), Color(0.0f));
  m.varianceOfMean.assign(m.mean.size(), Color(0.0f));
  m.usedBvh = sampler.usesBvh();
  // A tree the framework refused fails the test anyway: no slow brute-force render.
  if (!m.usedBvh && !scene.primitives.empty()) return m;
  std::atomic<uint64_t> nonFinite{0};
  forEachTile(m.width, m.height, 8, threads, [&](const Tile& tile) {
    TraceContext context = sampler.context();
    for (int y = tile.begin.y; y < tile.end.y; ++y) {
      for (int x = tile.begin.x; x < tile.end.x; ++x) {
        glm::dvec3 sum(0.0), sumSquares(0.0);
        int n = 0;
        // One sample, tallied here: the variance of a pixel's mean is this
        // code's, whatever an adaptive pixel says about itself.
        const auto sample = [&](uint32_t i) {
          const glm::dvec3 c(sampler.sample(context, {x, y}, i));
          if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
            ++nonFinite;
            return Color(0.0f);
          }
          sum += c;
          sumSquares += c * c;
          ++n;
          return Color(c);
        };
        std::optional<AdaptivePixel> adaptive;
        if (imageOptions.adaptive) {
          adaptive = samplePixelAdaptively(sample, *imageOptions.adaptive);
        } else {
          for (int i = 0; i < m.spp; ++i) sample(uint32_t(i));
        }
        if (n == 0) continue;
        const size_t index = size_t(y) * size_t(m.width) + size_t(x);
        const glm::dvec3 mean = sum / double(n);
        const glm::dvec3 variance =
            n > 1 ? glm::max(glm::dvec3(0.0), (sumSquares - sum * mean) / double(n - 1)) : glm::dvec3(0.0);
        m.mean[index] = adaptive ? adaptive->estimate : Color(mean);  // adaptive: the student's own estimate
        m.varianceOfMean[index] = Color(variance / double(n));
      }
    }
  });
  m.nonFinite = nonFinite.load();
  return m;
}

// The judge's own: the first `count` samples of every pixel (row by row),
// as renderMoments takes them, with the tasks the judge links (the
// reference): what task 11's judge serves a candidate's pixels.
inline std::vector<std::vector<Color>> pixelSamples(const Scene& scene, const ImageOptions& imageOptions,
                                                    uint32_t count) {
  const PixelSampler sampler(scene, imageOptions);
  const int width = scene.render.width, height = scene.render.height;
  std::vector<std::vector<Color>> samples(size_t(width) * size_t(height), std::vector<Color>(count));
  forEachTile(width, height, 8, 0, [&](const Tile& tile) {
    TraceContext context = sampler.context();
    for (int y = tile.begin.y; y < tile.end.y; ++y)
      for (int x = tile.begin.x; x < tile.end.x; ++x)
        for (uint32_t i = 0; i < count; ++i) samples[size_t(y) * size_t(width) + size_t(x)][i] = sampler.sample(context, {x, y}, i);
  });
  return samples;
}

}  // namespace pathlab::test
