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
  std::vector<uint32_t> samples{};    // adaptive: the samples each pixel took (counted here, not reported)
};

// scene.render gives the size, samples per pixel, seed, -m and -l.
inline PixelMoments renderMoments(const Scene& scene, const ImageOptions& imageOptions, int threads = 0) {
  RenderOptions options;
  options.integrator = imageOptions.integrator;
  options.environmentSampling = imageOptions.environmentSampling;
  // Independent samples: only for them is the variance of a pixel's mean the
  // sample variance over n, which the image tests' z-scores rely on.
  options.sampler = SampleSequence::Independent;
  options.progress = false;
  const Accelerator accelerator(scene);
  const Lights lights = Lights::fromScene(scene, kLinkedTasks.environment, options.environmentSampling);
  const CameraBasis basis = cameraBasis(scene.camera);

  PixelMoments m;
  m.width = scene.render.width;
  m.height = scene.render.height;
  m.spp = scene.render.samplesPerPixel;
  m.mean.assign(size_t(m.width) * size_t(m.height), Color(0.0f));
  m.varianceOfMean.assign(m.mean.size(), Color(0.0f));
  if (imageOptions.adaptive) m.samples.assign(m.mean.size(), 0);
  m.usedBvh = accelerator.usesBvh();
  // A tree the framework refused fails the test anyway: no slow brute-force render.
  if (!m.usedBvh && !scene.primitives.empty()) return m;
  std::atomic<uint64_t> nonFinite{0};
  forEachTile(m.width, m.height, 8, threads, [&](const Tile& tile) {
    TraceContext context(scene, accelerator, lights, kLinkedTasks.lobes);
    for (int y = tile.begin.y; y < tile.end.y; ++y) {
      for (int x = tile.begin.x; x < tile.end.x; ++x) {
        context.pixel = {x, y};
        glm::dvec3 sum(0.0), sumSquares(0.0);
        int n = 0;
        uint32_t calls = 0;
        // One sample, tallied here: the variance of a pixel's mean is this
        // code's, whatever an adaptive pixel says about itself.
        const auto sample = [&](uint32_t i) {
          ++calls;
          const glm::dvec3 c(estimatePixelSample(context, options, basis, i));
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
        const size_t index = size_t(y) * size_t(m.width) + size_t(x);
        if (adaptive) m.samples[index] = calls;
        if (n == 0) continue;
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

}  // namespace pathlab::test
