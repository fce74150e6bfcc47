#include "pathlab/render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>

#include "pathlab/parallel.h"
#include "pathlab/progress.h"
#include "pathlab/tasks/direct_lighting.h"
#include "pathlab/tasks/path_tracing.h"

namespace pathlab {

std::optional<Integrator> integratorFromName(const std::string& name) {
  if (name == "path") return Integrator::Path;
  if (name == "direct") return Integrator::Direct;
  if (name == "preview") return Integrator::Preview;
  if (name == "normals") return Integrator::Normals;
  return std::nullopt;
}

const char* integratorName(Integrator integrator) {
  switch (integrator) {
    case Integrator::Path: return "path";
    case Integrator::Direct: return "direct";
    case Integrator::Preview: return "preview";
    case Integrator::Normals: return "normals";
  }
  return "?";
}

Color traceRadiance(TraceContext& context, Integrator integrator, const Ray& ray, Sampler& sampler) {
  if (integrator == Integrator::Path) return tracePath(context, ray, sampler);
  const Scene& scene = context.scene;
  std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
  switch (integrator) {
    case Integrator::Path: break;
    case Integrator::Direct: {
      if (!hit) return context.background(ray.direction);
      const Vec3 wo = -ray.direction;
      const Bsdf bsdf(scene.materials[hit->material], *hit, wo);
      return emittedRadiance(scene, *hit, wo) + estimateDirectLighting(context, *hit, bsdf, wo, sampler);
    }
    case Integrator::Preview: {
      // An "eye light" at the camera: enough to recognise shapes and colours
      // before any light transport exists.
      if (!hit) return context.background(ray.direction);
      const Material& material = scene.materials[hit->material];
      float cosine = std::abs(glm::dot(hit->shadingNormal, ray.direction));
      return material.albedo * cosine + material.emission;
    }
    case Integrator::Normals:
      if (!hit) return Color(0.0f);
      return 0.5f * (hit->shadingNormal + Vec3(1.0f));
  }
  return Color(0.0f);
}

TraceContext makeTraceContext(const Scene& scene, const Accelerator& accelerator, const Lights& lights,
                              const RenderOptions& options) {
  TraceContext context(scene, accelerator, lights);
  context.lightSamples = scene.render.lightSamples;
  context.maxDepth = scene.render.maxDepth;
  context.russianRoulette = options.russianRoulette;
  context.lightSampling = options.lightSampling;
  context.cosineSampling = options.cosineSampling;
  context.mis = options.mis;
  return context;
}

Color renderSample(TraceContext& context, const RenderOptions& options, const CameraBasis& basis, uint32_t sample) {
  const RenderSettings& settings = context.scene.render;
  const IVec2 pixel = context.pixel;
  Sampler sampler(uint32_t(pixel.y) * uint32_t(settings.width) + uint32_t(pixel.x), sample, settings.seed);
  const Point2 raster = pixelSamplePosition(pixel, sampler.next2D());
  const Ray ray = generateCameraRay(context.scene.camera, basis, raster, {settings.width, settings.height});
  return options.radiance ? options.radiance(context, ray, sampler)
                          : traceRadiance(context, options.integrator, ray, sampler);
}

RenderResult render(const Scene& scene, const RenderOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const RenderSettings& settings = scene.render;
  const int width = settings.width, height = settings.height;
  const CameraBasis basis = cameraBasis(scene.camera);
  const Accelerator accelerator(scene);
  const Lights lights = Lights::fromScene(scene, options.environmentSampling);

  std::vector<Color> sum(size_t(width) * size_t(height), Color(0.0f));
  std::vector<int> count(sum.size(), 0);
  std::atomic<uint64_t> rays{0}, samples{0}, nonFinite{0};
  std::atomic<uint64_t> firstNonFinite{UINT64_MAX};

  ProgressBar progress(uint64_t(width) * uint64_t(height) * uint64_t(settings.samplesPerPixel),
                       options.progress);

  // Passes of 1, 1, 2, 4, ... 64 samples per pixel: the image refines
  // everywhere at once, so an interrupted render is still a whole picture.
  int passBegin = 0, passSize = 1;
  bool first = true;
  while (passBegin < settings.samplesPerPixel) {
    if (options.cancel && options.cancel->load()) break;
    const int passEnd = std::min(settings.samplesPerPixel, passBegin + passSize);
    forEachTile(width, height, options.tileSize, options.threads, [&](const Tile& tile) {
      TraceContext context = makeTraceContext(scene, accelerator, lights, options);
      uint64_t tileSamples = 0;
      for (int y = tile.begin.y; y < tile.end.y; ++y) {
        for (int x = tile.begin.x; x < tile.end.x; ++x) {
          const uint32_t pixelIndex = uint32_t(y) * uint32_t(width) + uint32_t(x);
          Color& pixelSum = sum[pixelIndex];
          context.pixel = {x, y};
          for (int s = passBegin; s < passEnd; ++s) {
            Color radiance = renderSample(context, options, basis, uint32_t(s));
            if (isFinite(radiance)) {
              pixelSum += radiance;
            } else {
              // Never clamp: report. A NaN sample counts as a sample of zero.
              nonFinite.fetch_add(1, std::memory_order_relaxed);
              uint64_t seen = firstNonFinite.load();
              while (pixelIndex < seen && !firstNonFinite.compare_exchange_weak(seen, pixelIndex)) {
              }
            }
          }
          count[pixelIndex] = passEnd;
          tileSamples += uint64_t(passEnd - passBegin);
        }
      }
      rays.fetch_add(context.rays, std::memory_order_relaxed);
      samples.fetch_add(tileSamples, std::memory_order_relaxed);
      progress.add(tileSamples);
    }, options.cancel);
    passBegin = passEnd;
    if (!first) passSize = std::min(passSize * 2, 64);
    first = false;
  }

  RenderResult result;
  result.image = Image(width, height);
  int minCount = settings.samplesPerPixel;
  for (size_t i = 0; i < sum.size(); ++i) {
    if (count[i] > 0) result.image.pixels[i] = sum[i] / float(count[i]);
    minCount = std::min(minCount, count[i]);
  }
  RenderStats& stats = result.stats;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.samples = samples.load();
  stats.rays = rays.load();
  stats.nonFiniteSamples = nonFinite.load();
  if (stats.nonFiniteSamples > 0) {
    uint64_t p = firstNonFinite.load();
    stats.firstNonFinitePixel = IVec2(int(p % uint64_t(width)), int(p / uint64_t(width)));
  }
  stats.completedSpp = minCount;
  stats.buildSeconds = accelerator.buildSeconds();
  stats.interrupted = minCount < settings.samplesPerPixel;
  return result;
}

}  // namespace pathlab
