// The multithreaded progressive render loop. Samples are taken in passes
// (1, 1, 2, 4, ... samples per pixel, up to 64 at a time) over 16x16 tiles;
// sample i of a pixel always uses the random stream (seed, pixel, i), so the
// image is bit-identical for any thread count, tile size or pass schedule.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "pathlab/trace.h"
#include "pathlab/image.h"
#include "pathlab/random.h"
#include "pathlab/ray.h"
#include "pathlab/scene.h"
#include "pathlab/tasks/camera_rays.h"

namespace pathlab {

enum class Integrator {
  Path,     // path tracing (task 5, using task 4 at every vertex)
  Direct,   // emission + direct lighting at the first hit (task 4)
  Preview,  // eye light: albedo * |cos| + emission — needs tasks 1–3 only
  Normals,  // shading normal as colour
};

std::optional<Integrator> integratorFromName(const std::string& name);
const char* integratorName(Integrator integrator);

// Radiance along a camera ray; replaces the integrator when set (tests and
// debugger views use it to render any per-sample quantity).
using RadianceFunction = std::function<Color(TraceContext& context, const Ray& ray, Sampler& sampler)>;

struct RenderOptions {
  Integrator integrator = Integrator::Path;
  bool russianRoulette = true;
  bool lightSampling = true;
  bool cosineSampling = true;
  MisHeuristic mis = MisHeuristic::None;
  EnvironmentSampling environmentSampling = EnvironmentSampling::Importance;
  int threads = 0;    // 0: all hardware threads
  int tileSize = 16;
  bool progress = true;
  const std::atomic<bool>* cancel = nullptr;  // set from a signal handler to stop early
  RadianceFunction radiance;                  // optional override of the integrator
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
};

// Radiance arriving along one camera ray, by the chosen integrator.
Color traceRadiance(TraceContext& context, Integrator integrator, const Ray& ray, Sampler& sampler);

RenderResult render(const Scene& scene, const RenderOptions& options);

// The trace context render() gives each thread.
TraceContext makeTraceContext(const Scene& scene, const Accelerator& accelerator, const Lights& lights,
                              const RenderOptions& options);

// Sample `sample` of pixel context.pixel, exactly as render() takes it (same
// random numbers): the debugger re-traces single pixels with it.
Color renderSample(TraceContext& context, const RenderOptions& options, const CameraBasis& basis, uint32_t sample);

}  // namespace pathlab
