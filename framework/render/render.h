// The multithreaded progressive render loop. Samples are taken in passes
// (1, 1, 2, 4, ... samples per pixel, up to 64 at a time) over 16x16 tiles;
// sample i of a pixel always uses the random stream (seed, pixel, i), so the
// image is bit-identical for any thread count, tile size or pass schedule.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/scene.h"
#include "core/trace.h"
#include "render/accelerator.h"
#include "render/strategies.h"
#include "tasks/adaptive_sampling.h"
#include "tasks/camera_rays.h"
#include "util/image.h"
#include "util/random.h"
#include "util/ray.h"

namespace pathlab {

enum class Integrator {
  Path,     // path tracing (task 5, using task 4 at every vertex)
  Direct,   // emission + direct lighting at the first hit (task 4)
  Preview,  // eye light: albedo * |cos| + emission — needs tasks 1–3 only
  Normals,  // shading normal as colour
  // Task 9's tracePathMis, with one light sample per vertex: combined with
  // the BSDF sample by the power or the balance heuristic, or either alone.
  Mis,
  MisBalance,
  LightSampling,
  BsdfSampling,
};

// The weights an integrator gives task 9's tracePathMis; nothing for the others.
std::optional<MisEstimator> misEstimatorOf(Integrator integrator);

// Every integrator once, in menu order: its name (pathlab --integrator,
// pathlab-bench's strategies, the GUI's menu) and the tasks whose code it
// runs (the GUI's menu says it beside the name).
struct IntegratorEntry {
  Integrator integrator;
  const char* name;
  const char* runs;
};
inline constexpr IntegratorEntry kIntegrators[] = {
    {Integrator::Path, "path", "tasks 4-8"},
    {Integrator::Direct, "direct", "task 4"},
    {Integrator::Preview, "preview", "tasks 1-3"},
    {Integrator::Normals, "normals", "tasks 1-2"},
    {Integrator::Mis, "mis", "task 9, power"},
    {Integrator::MisBalance, "mis-balance", "task 9"},
    {Integrator::LightSampling, "light", "task 9, alone"},
    {Integrator::BsdfSampling, "bsdf", "task 9, alone"},
};

std::optional<Integrator> integratorFromName(const std::string& name);
const char* integratorName(Integrator integrator);
// "path, direct, ...": every name, for a message.
std::string integratorNames();

// The tasks whose code lights a render of `scene` with `integrator`, e.g.
// "1-5, 8": camera rays, hits and the tree always; direct lighting and paths
// by the integrator; mirror and glass (6), an environment map (7) and rough
// materials (8) only where the scene has them.
std::string tasksLightingRender(const Scene& scene, Integrator integrator);
// --sampler: "independent" or "sobol".
std::optional<SampleSequence> sampleSequenceFromName(const std::string& name);
const char* sampleSequenceName(SampleSequence sequence);

// Radiance along a camera ray, the one quantity every integrator estimates.
// The names, one per level: estimatePixelSample (a pixel's sample i: camera
// ray, then) -> estimateRadiance (the integrator the options choose, or
// options.estimator) -> task 5's tracePath, task 4's estimateDirectLighting,
// the framework's traceWithStrategy.
using RadianceEstimator = std::function<Color(TraceContext& context, const Ray& ray, Sampler& sampler)>;

struct RenderOptions {
  Integrator integrator = Integrator::Path;
  // For Integrator::Path: the recipe runs task 5's tracePath; any other
  // strategy runs the framework's traceWithStrategy (render/strategies.h).
  SamplingStrategy strategy;
  EnvironmentSampling environmentSampling = EnvironmentSampling::Importance;
  Traversal traversal = Traversal::Task3;  // --accel: how rays walk task 3's tree
  SampleSequence sampler = SampleSequence::Sobol;  // --sampler: the random numbers (random.h)
  int threads = 0;    // 0: all hardware threads
  int tileSize = 16;
  int maxPassSpp = 64;  // the largest pass; the GUI uses small passes to refresh often
  bool progress = true;
  const std::atomic<bool>* cancel = nullptr;  // set from a signal handler to stop early
  RadianceEstimator estimator;  // when set, replaces the integrator (tests and debugger views render any per-sample quantity)
  // Task 11: each pixel samples until its estimate is known well enough
  // (samplePixelAdaptively), at most scene.render.samplesPerPixel; unset:
  // every pixel takes that many.
  std::optional<AdaptiveSettings> adaptive{};
};

// Why adaptive settings cannot be used (tolerance not positive, a batch of
// 0, minSpp or maxSpp not a multiple of the batch, minSpp > maxSpp), or "".
std::string adaptiveSettingsProblem(const AdaptiveSettings& settings);

// An adaptive render's samples-per-pixel map: each pixel's count (the
// framework's, of the samples the pixel took) and whether the rule stopped it.
struct SampleMap {
  int width = 0, height = 0;
  std::vector<uint32_t> samples;
  std::vector<uint8_t> confident;
};

struct RenderStats {
  double seconds = 0.0;
  uint64_t samples = 0;           // camera samples taken
  uint64_t rays = 0;              // every ray traced (camera, shadow, bounce)
  uint64_t nonFiniteSamples = 0;  // NaN or Inf samples, left out of the image
  std::optional<IVec2> firstNonFinitePixel;  // in scanline order
  int completedSpp = 0;           // every pixel has at least this many samples
  double buildSeconds = 0.0;      // acceleration structure build
  bool interrupted = false;
};

struct RenderResult {
  Image image;
  RenderStats stats;
  SampleMap sampleMap{};  // adaptive renders only
};

// Radiance arriving along one camera ray: options.estimator when set, else
// the chosen integrator (and, for paths, strategy).
Color estimateRadiance(TraceContext& context, const RenderOptions& options, const Ray& ray, Sampler& sampler);

// Every pixel at scene.render.samplesPerPixel, or adaptively (options.adaptive).
// Throws an Error for options the scene cannot render with (mediaProblem).
RenderResult render(const Scene& scene, const RenderOptions& options);

// Why `options` cannot render `scene`, or "": a scene with media (task 12)
// renders with task 12's path tracer only (the path integrator, its default
// sampling strategy), or with a shading preview. Said in the framework's
// words, not a program's flags: each program checks first and names its own.
std::string mediaProblem(const Scene& scene, const RenderOptions& options);

class ProgressBar;

// What a render counts while its threads run: rays, samples, and the NaN or
// Inf samples it leaves out (never clamped: counted as 0 and reported, with
// the first such pixel in scanline order, whichever thread met it first).
class RenderCounters {
 public:
  // True when `radiance` is finite; otherwise counts it against the pixel.
  bool admit(const Color& radiance, uint64_t pixelIndex);
  void addTile(uint64_t rays, uint64_t samples);
  // Fills stats.samples, rays, nonFiniteSamples and firstNonFinitePixel.
  void report(RenderStats& stats, int width) const;

 private:
  std::atomic<uint64_t> rays_{0}, samples_{0}, nonFinite_{0}, firstNonFinite_{UINT64_MAX};
};

// render(), one pass at a time: the GUI shows the image between passes.
// Passes take 1, 1, 2, 4, ... samples per pixel (at most options.maxPassSpp);
// the image after k samples per pixel is the same whatever the passes were.
// `scene` must outlive this object.
class ProgressiveRender {
 public:
  ProgressiveRender(const Scene& scene, const RenderOptions& options);
  ~ProgressiveRender();

  // Takes the next pass; false once every pixel has scene.render.samplesPerPixel
  // samples or options.cancel was set (a cancelled pass leaves some pixels
  // with fewer samples, which completedSpp() reports).
  bool step();
  bool done() const { return passBegin_ >= scene_.render.samplesPerPixel; }

  Image image() const;       // the mean of each pixel's samples so far
  RenderStats stats() const;  // so far

 private:
  const Scene& scene_;
  RenderOptions options_;
  CameraBasis basis_;
  Accelerator accelerator_;
  Lights lights_;
  std::chrono::steady_clock::time_point start_;
  std::vector<Color> sum_;
  std::vector<int> count_;
  int passBegin_ = 0, passSize_ = 1, passes_ = 0;
  bool cancelled_ = false;
  RenderCounters counters_;
  std::unique_ptr<ProgressBar> progress_;
};


// The random numbers of sample `sample` of `pixel`, as render() draws them.
Sampler pixelSampler(const RenderSettings& settings, IVec2 pixel, uint32_t sample, SampleSequence sequence);

// Sample `sample` of pixel context.pixel, exactly as render() takes it (same
// random numbers): the debugger re-traces single pixels with it.
Color estimatePixelSample(TraceContext& context, const RenderOptions& options, const CameraBasis& basis,
                          uint32_t sample);

}  // namespace pathlab
