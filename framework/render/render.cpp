#include "render/render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>

#include "render/task_wiring.h"
#include "tasks/direct_lighting.h"
#include "tasks/media.h"
#include "tasks/mis.h"
#include "tasks/path_tracing.h"
#include "tasks/thin_lens.h"
#include "util/error.h"
#include "util/parallel.h"
#include "util/progress.h"

namespace pathlab {

std::optional<Integrator> integratorFromName(const std::string& name) {
  for (const IntegratorEntry& entry : kIntegrators) {
    if (name == entry.name) return entry.integrator;
  }
  return std::nullopt;
}

const char* integratorName(Integrator integrator) {
  for (const IntegratorEntry& entry : kIntegrators) {
    if (entry.integrator == integrator) return entry.name;
  }
  return "?";
}

std::string integratorNames() {
  std::string names;
  for (const IntegratorEntry& entry : kIntegrators) names += (names.empty() ? "" : ", ") + std::string(entry.name);
  return names;
}

std::optional<MisEstimator> misEstimatorOf(Integrator integrator) {
  switch (integrator) {
    case Integrator::Mis: return MisEstimator::Power;
    case Integrator::MisBalance: return MisEstimator::Balance;
    case Integrator::LightSampling: return MisEstimator::LightSampling;
    case Integrator::BsdfSampling: return MisEstimator::BsdfSampling;
    default: return std::nullopt;
  }
}

std::string tasksLightingRender(const Scene& scene, Integrator integrator) {
  std::vector<int> tasks = {1, 2, 3};
  const bool mis = misEstimatorOf(integrator).has_value();  // task 9, with task 4's ray offsets and light directions
  const bool paths = integrator == Integrator::Path || mis;  // bounces: task 5's diffuse sampling
  const bool lit = paths || integrator == Integrator::Direct;
  if (lit) tasks.push_back(4);
  if (paths) tasks.push_back(5);
  auto has = [&](auto predicate) { return std::any_of(scene.materials.begin(), scene.materials.end(), predicate); };
  if (paths && has([](const Material& m) { return m.isDelta(); })) tasks.push_back(6);
  if (lit && scene.environment && !scene.environment->image.pixels.empty()) tasks.push_back(7);
  if (lit && has([](const Material& m) { return m.isRough(); })) tasks.push_back(8);
  if (mis) tasks.push_back(9);
  if (scene.camera.apertureRadius > 0.0f) tasks.push_back(10);
  if (paths && scene.hasMedia()) tasks.push_back(12);
  // Runs of consecutive tasks as "a-b".
  std::string text;
  for (size_t i = 0; i < tasks.size();) {
    size_t j = i;
    while (j + 1 < tasks.size() && tasks[j + 1] == tasks[j] + 1) ++j;
    if (!text.empty()) text += ", ";
    text += j > i + 1 ? std::to_string(tasks[i]) + "-" + std::to_string(tasks[j])
                      : std::to_string(tasks[i]) + (j == i + 1 ? ", " + std::to_string(tasks[j]) : "");
    i = j + 1;
  }
  return text;
}

std::optional<SampleSequence> sampleSequenceFromName(const std::string& name) {
  if (name == "independent") return SampleSequence::Independent;
  if (name == "stratified") return SampleSequence::Stratified;
  if (name == "sobol") return SampleSequence::Sobol;
  return std::nullopt;
}

const char* sampleSequenceName(SampleSequence sequence) {
  return sequence == SampleSequence::Sobol ? "sobol" : sequence == SampleSequence::Stratified ? "stratified" : "independent";
}

Color estimateRadiance(TraceContext& context, const RenderOptions& options, const Ray& ray, Sampler& sampler) {
  if (options.estimator) return options.estimator(context, ray, sampler);
  const Scene& scene = context.scene;
  switch (options.integrator) {
    case Integrator::Path:
      if (scene.hasMedia()) return tracePathInMedia(context, ray, sampler);  // task 12; checkMedia allows only the recipe
      return options.strategy.isRecipe() ? tracePath(context, ray, sampler)
                                         : traceWithStrategy(context, ray, sampler, options.strategy);
    case Integrator::Direct: {
      const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
      if (!hit) return context.background(ray.direction);
      const Vec3 wo = -ray.direction;
      const Bsdf bsdf = context.bsdf(*hit, wo);
      return emittedRadiance(scene, *hit, wo) + estimateDirectLighting(context, *hit, bsdf, wo, sampler);
    }
    case Integrator::Preview: {
      // An "eye light" at the camera: enough to recognise shapes and colours
      // before any light transport exists.
      const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
      if (!hit) return context.background(ray.direction);
      const Material& material = scene.materials[hit->material];
      const float cosine = std::abs(glm::dot(hit->shadingNormal, ray.direction));
      return material.albedo * cosine + material.emission;
    }
    case Integrator::Normals: {
      const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
      return hit ? 0.5f * (hit->shadingNormal + Vec3(1.0f)) : Color(0.0f);
    }
    case Integrator::Mis:
    case Integrator::MisBalance:
    case Integrator::LightSampling:
    case Integrator::BsdfSampling:
      return tracePathMis(context, ray, sampler, misWeights(*misEstimatorOf(options.integrator)));
  }
  return Color(0.0f);
}

Sampler pixelSampler(const RenderSettings& settings, IVec2 pixel, uint32_t sample, SampleSequence sequence) {
  return Sampler(uint32_t(pixel.y) * uint32_t(settings.width) + uint32_t(pixel.x), sample, settings.seed, sequence,
                 uint32_t(settings.samplesPerPixel));
}

Color estimatePixelSample(TraceContext& context, const RenderOptions& options, const CameraBasis& basis,
                          uint32_t sample) {
  const RenderSettings& settings = context.scene.render;
  const IVec2 pixel = context.pixel;
  Sampler sampler = pixelSampler(settings, pixel, sample, options.sampler);
  const Point2 raster = pixelSamplePosition(pixel, sampler.next2D());
  const Camera& camera = context.scene.camera;
  Ray ray = generateCameraRay(camera, basis, raster, {settings.width, settings.height});
  // A pinhole camera draws no lens sample: its renders are task 1's alone.
  if (camera.apertureRadius > 0.0f) ray = generateThinLensRay(camera, basis, ray, sampler.next2D());
  return estimateRadiance(context, options, ray, sampler);
}

bool RenderCounters::admit(const Color& radiance, uint64_t pixelIndex) {
  if (isFinite(radiance)) return true;
  nonFinite_.fetch_add(1, std::memory_order_relaxed);
  uint64_t seen = firstNonFinite_.load();
  while (pixelIndex < seen && !firstNonFinite_.compare_exchange_weak(seen, pixelIndex)) {
  }
  return false;
}

void RenderCounters::addTile(uint64_t rays, uint64_t samples) {
  rays_.fetch_add(rays, std::memory_order_relaxed);
  samples_.fetch_add(samples, std::memory_order_relaxed);
}

void RenderCounters::report(RenderStats& stats, int width) const {
  stats.samples = samples_.load();
  stats.rays = rays_.load();
  stats.nonFiniteSamples = nonFinite_.load();
  if (stats.nonFiniteSamples > 0) {
    const uint64_t p = firstNonFinite_.load();
    stats.firstNonFinitePixel = IVec2(int(p % uint64_t(width)), int(p / uint64_t(width)));
  }
}

// Media (task 12) need task 12's path tracer: the other estimators know
// nothing of them. The shading previews ignore them, and may look.
std::string mediaProblem(const Scene& scene, const RenderOptions& options) {
  const bool preview = options.integrator == Integrator::Preview || options.integrator == Integrator::Normals;
  if (!scene.hasMedia() || options.estimator || preview ||
      (options.integrator == Integrator::Path && options.strategy.isRecipe())) {
    return "";
  }
  return "a scene with media renders with task 12's path tracer only (the path integrator with its default "
         "sampling strategy), not the " + std::string(integratorName(options.integrator)) + " integrator" +
         (options.strategy.isRecipe() ? "" : " with another sampling strategy");
}

namespace {

const RenderOptions& checkMedia(const Scene& scene, const RenderOptions& options) {
  if (const std::string problem = mediaProblem(scene, options); !problem.empty()) throw Error(scene.source + ": " + problem);
  return options;
}

}  // namespace

ProgressiveRender::ProgressiveRender(const Scene& scene, const RenderOptions& options)
    : scene_(scene),
      options_(checkMedia(scene, options)),
      basis_(cameraBasis(scene.camera)),
      accelerator_(scene, options.traversal),
      lights_(Lights::fromScene(scene, kLinkedTasks.environment, options.environmentSampling)),
      start_(std::chrono::steady_clock::now()),
      sum_(size_t(scene.render.width) * size_t(scene.render.height), Color(0.0f)),
      count_(sum_.size(), 0),
      progress_(std::make_unique<ProgressBar>(uint64_t(sum_.size()) * uint64_t(scene.render.samplesPerPixel),
                                              options.progress)) {}

ProgressiveRender::~ProgressiveRender() = default;

bool ProgressiveRender::step() {
  const int width = scene_.render.width, height = scene_.render.height;
  if (done() || cancelled_) return false;
  if (options_.cancel && options_.cancel->load()) {
    cancelled_ = true;
    return false;
  }
  const int passBegin = passBegin_;
  const int passEnd = std::min(scene_.render.samplesPerPixel, passBegin + passSize_);
  forEachTile(width, height, options_.tileSize, options_.threads, [&](const Tile& tile) {
    TraceContext context(scene_, accelerator_, lights_, kLinkedTasks.lobes);
    uint64_t tileSamples = 0;
    for (int y = tile.begin.y; y < tile.end.y; ++y) {
      for (int x = tile.begin.x; x < tile.end.x; ++x) {
        const uint32_t pixelIndex = uint32_t(y) * uint32_t(width) + uint32_t(x);
        Color& pixelSum = sum_[pixelIndex];
        context.pixel = {x, y};
        for (int s = passBegin; s < passEnd; ++s) {
          const Color radiance = estimatePixelSample(context, options_, basis_, uint32_t(s));
          if (counters_.admit(radiance, pixelIndex)) pixelSum += radiance;
        }
        count_[pixelIndex] = passEnd;
        tileSamples += uint64_t(passEnd - passBegin);
      }
    }
    counters_.addTile(context.rays, tileSamples);
    progress_->add(tileSamples);
  }, options_.cancel);
  if (options_.cancel && options_.cancel->load()) {
    cancelled_ = true;  // some tiles of this pass may be missing
    return false;
  }
  // Passes of 1, 1, 2, 4, ...: the image refines everywhere at once, so an
  // interrupted render is still a whole picture.
  passBegin_ = passEnd;
  if (passes_++ > 0) passSize_ = std::min(passSize_ * 2, std::max(1, options_.maxPassSpp));
  return !done();
}

Image ProgressiveRender::image() const {
  Image image(scene_.render.width, scene_.render.height);
  for (size_t i = 0; i < sum_.size(); ++i) {
    if (count_[i] > 0) image.pixels[i] = sum_[i] / float(count_[i]);
  }
  return image;
}

RenderStats ProgressiveRender::stats() const {
  RenderStats stats;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  counters_.report(stats, scene_.render.width);
  stats.completedSpp = count_.empty() ? 0 : *std::min_element(count_.begin(), count_.end());
  stats.buildSeconds = accelerator_.buildSeconds();
  stats.interrupted = stats.completedSpp < scene_.render.samplesPerPixel;
  return stats;
}

std::string adaptiveSettingsProblem(const AdaptiveSettings& a) {
  if (!(a.tolerance > 0.0 && std::isfinite(a.tolerance))) return "the tolerance must be a positive number";
  if (a.batch < 1) return "the batch must be at least 1 sample";
  if (a.minSpp < a.batch || a.minSpp % a.batch != 0) return "the minimum must be a multiple of the batch";
  if (a.maxSpp < a.minSpp || a.maxSpp % a.batch != 0) return "the maximum must be a multiple of the batch, at least the minimum";
  return "";
}

namespace {

// Task 11's render: each pixel whole, by samplePixelAdaptively. Pixels are
// independent (sample i of a pixel is the stream (seed, pixel, i)), so the
// image is the same for any thread count.
RenderResult renderAdaptive(const Scene& scene, const RenderOptions& options) {
  const AdaptiveSettings settings = *options.adaptive;
  if (const std::string problem = adaptiveSettingsProblem(settings); !problem.empty()) {
    throw Error("adaptive sampling: " + problem);
  }
  checkMedia(scene, options);
  Scene run = scene;  // the Sobol sequence's length: the most a pixel may take
  run.render.samplesPerPixel = int(settings.maxSpp);
  const int width = run.render.width, height = run.render.height;
  const auto start = std::chrono::steady_clock::now();
  const Accelerator accelerator(run, options.traversal);
  const Lights lights = Lights::fromScene(run, kLinkedTasks.environment, options.environmentSampling);
  const CameraBasis basis = cameraBasis(run.camera);
  RenderResult result;
  result.image = Image(width, height);
  SampleMap& map = result.sampleMap;
  map.width = width, map.height = height;
  map.samples.assign(size_t(width) * size_t(height), 0);
  map.confident.assign(map.samples.size(), 0);
  RenderCounters counters;
  ProgressBar progress(uint64_t(map.samples.size()), options.progress);  // counts pixels
  forEachTile(width, height, options.tileSize, options.threads, [&](const Tile& tile) {
    TraceContext context(run, accelerator, lights, kLinkedTasks.lobes);
    uint64_t tileSamples = 0;
    for (int y = tile.begin.y; y < tile.end.y; ++y) {
      for (int x = tile.begin.x; x < tile.end.x; ++x) {
        const uint64_t index = uint64_t(y) * uint64_t(width) + uint64_t(x);
        context.pixel = {x, y};
        uint32_t calls = 0;  // counted here: the map shows what the pixel cost, whatever it reports
        const auto sample = [&](uint32_t i) {
          ++calls;
          const Color radiance = estimatePixelSample(context, options, basis, i);
          return counters.admit(radiance, index) ? radiance : Color(0.0f);
        };
        const AdaptivePixel pixel = samplePixelAdaptively(sample, settings);
        result.image.pixels[index] = pixel.estimate;
        map.samples[index] = calls;
        map.confident[index] = pixel.confident ? 1 : 0;
        tileSamples += calls;
      }
    }
    counters.addTile(context.rays, tileSamples);
    progress.add(uint64_t(tile.end.x - tile.begin.x) * uint64_t(tile.end.y - tile.begin.y));
  }, options.cancel);
  RenderStats& stats = result.stats;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  counters.report(stats, width);
  stats.completedSpp = map.samples.empty() ? 0 : int(*std::min_element(map.samples.begin(), map.samples.end()));
  stats.buildSeconds = accelerator.buildSeconds();
  stats.interrupted = options.cancel && options.cancel->load();
  return result;
}

}  // namespace

RenderResult render(const Scene& scene, const RenderOptions& options) {
  if (options.adaptive) return renderAdaptive(scene, options);
  ProgressiveRender progressive(scene, options);
  while (progressive.step()) {
  }
  return {progressive.image(), progressive.stats()};
}

}  // namespace pathlab
