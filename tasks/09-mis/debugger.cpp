// Task 9's visual debugger (students don't edit this file: it shows what
// their mis.cpp does).
//   compare   the three estimators side by side: light sampling alone, BSDF
//             sampling alone and MIS (power heuristic), at equal samples
//             (top) and at equal time (bottom: each given the time MIS took).
//   weights   direct light at each pixel's first hit, one light sample and
//             one BSDF sample, each with its MIS weight (power heuristic):
//             what the light samples add, what the BSDF samples add, their
//             sum, and the light samples' share of it (red: light sampling
//             carried the pixel, green: BSDF sampling).
//   variance  each estimator's per-pixel variance (one sample), on one
//             logarithmic colour scale: dark where an estimator is good.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/bsdf.h"
#include "debug/debug_views.h"
#include "debug/draw.h"
#include "render/render.h"
#include "tasks/direct_lighting.h"
#include "tasks/mis.h"

namespace pathlab {
namespace {

constexpr MisEstimator kEstimators[] = {MisEstimator::LightSampling, MisEstimator::BsdfSampling, MisEstimator::Power};
constexpr const char* kLabels[] = {"LIGHT", "BSDF", "MIS"};

// The scene at half the requested size (each view shows several tiles).
Scene tileScene(const DebugViewRequest& request) {
  Scene scene = request.scene;
  scene.render.width = std::max(8, request.width / 2);
  scene.render.height = std::max(8, request.height / 2);
  return scene;
}

RenderOptions estimatorOptions(const DebugViewRequest& request, MisEstimator estimator) {
  RenderOptions options;
  options.progress = false;
  options.threads = request.threads;
  options.integrator = estimator == MisEstimator::LightSampling ? Integrator::LightSampling
                       : estimator == MisEstimator::BsdfSampling ? Integrator::BsdfSampling
                                                                  : Integrator::Mis;
  return options;
}

DebugOutput compareView(const DebugViewRequest& request) {
  Scene scene = tileScene(request);
  const int spp = scene.render.samplesPerPixel;
  TileSheet sheet(3, 2, scene.render.width, scene.render.height);
  std::string report = "equal samples (" + std::to_string(spp) + " spp):";
  double misSeconds = 0.0;
  double secondsPerSpp[3] = {};
  for (int i = 0; i < 3; ++i) {
    const RenderResult result = render(scene, estimatorOptions(request, kEstimators[i]));
    secondsPerSpp[i] = result.stats.seconds / double(spp);
    if (kEstimators[i] == MisEstimator::Power) misSeconds = result.stats.seconds;
    sheet.place(result.image, i, kLabels[i] + std::string(", ") + std::to_string(spp) + " SPP");
    char entry[80];
    std::snprintf(entry, sizeof entry, " %s %.3f ms/spp", misEstimatorName(kEstimators[i]), 1e3 * secondsPerSpp[i]);
    report += entry;
  }
  report += "\nequal time (" + std::to_string(int(std::lround(1e3 * misSeconds))) + " ms, MIS's):";
  for (int i = 0; i < 3; ++i) {
    Scene timed = scene;
    timed.render.samplesPerPixel = std::clamp(int(misSeconds / std::max(secondsPerSpp[i], 1e-9)), 1, 16 * spp);
    const RenderResult result = render(timed, estimatorOptions(request, kEstimators[i]));
    sheet.place(result.image, 3 + i, kLabels[i] + std::string(", ") + std::to_string(timed.render.samplesPerPixel) + " SPP");
    char entry[80];
    std::snprintf(entry, sizeof entry, " %s %d spp", misEstimatorName(kEstimators[i]), timed.render.samplesPerPixel);
    report += entry;
  }
  return {sheet.image(), report + "\n"};
}

// Direct light at the first hit from one light sample and one BSDF sample,
// each weighted by the power heuristic (task 9's functions): x the light
// sample's part, y the BSDF sample's (luminance).
Color weightedParts(TraceContext& context, const Ray& ray, Sampler& sampler) {
  const std::optional<Hit> hit = context.intersect(ray, Interval{0.0f, kInfinity});
  if (!hit) return Color(0.0f);
  const Vec3 wo = -ray.direction;
  const Bsdf bsdf = context.bsdf(*hit, wo);
  if (bsdf.isDelta()) return Color(0.0f);
  Color parts(0.0f);
  const Vec2 u2 = sampler.next2D();
  if (const std::optional<LightSample> light = sampleOneLight(context, hit->point, Vec3(sampler.next1D(), u2));
      light && light->pdf > 0.0f) {
    const float cosine = glm::dot(light->wi, bsdf.normal());
    const Point3 origin = offsetRayOrigin(hit->point, hit->geometricNormal, light->wi);
    const float reach = light->distance == kInfinity ? kInfinity : light->distance * (1.0f - 1e-4f);
    if (cosine > 0.0f && !context.occluded(Ray{origin, light->wi}, Interval{0.0f, reach})) {
      const float weight = powerHeuristic(light->pdf, bsdf.pdf(wo, light->wi));
      parts.x = luminance(bsdf.f(wo, light->wi) * light->radiance) * cosine / light->pdf * weight;
    }
  }
  if (const std::optional<BsdfSample> sample = bsdf.sample(wo, sampler.next2D()); sample && sample->pdf > 0.0f) {
    const Ray bounce{offsetRayOrigin(hit->point, hit->geometricNormal, sample->wi), sample->wi};
    const std::optional<Hit> next = context.intersect(bounce, Interval{0.0f, kInfinity});
    const Color arriving = next ? emittedRadiance(context.scene, *next, -sample->wi)
                                : context.lights.environment ? context.lights.environment->pixelRadiance(sample->wi)
                                                             : Color(0.0f);
    if (maxComponent(arriving) > 0.0f) {
      const float weight = powerHeuristic(sample->pdf, oneLightPdf(context, hit->point, sample->wi, next));
      parts.y = luminance(sample->f * arriving) * std::abs(glm::dot(sample->wi, bsdf.normal())) / sample->pdf * weight;
    }
  }
  return parts;
}

DebugOutput weightsView(const DebugViewRequest& request) {
  Scene scene = tileScene(request);
  RenderOptions options;
  options.progress = false;
  options.threads = request.threads;
  options.estimator = weightedParts;
  const Image parts = render(scene, options).image;
  const int w = parts.width, h = parts.height;
  Image light(w, h), bsdf(w, h), share(w, h), sum(w, h);
  double totalLight = 0.0, totalBsdf = 0.0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Color p = parts.at(x, y);
      light.at(x, y) = Color(p.x);
      bsdf.at(x, y) = Color(p.y);
      sum.at(x, y) = Color(p.x + p.y);
      totalLight += double(p.x), totalBsdf += double(p.y);
      const float both = p.x + p.y;
      share.at(x, y) = both > 0.0f ? Color(p.x / both, p.y / both, 0.0f) : Color(0.05f);
    }
  }
  TileSheet sheet(2, 2, w, h);
  sheet.place(light, 0, "LIGHT SAMPLE x W");
  sheet.place(bsdf, 1, "BSDF SAMPLE x W");
  sheet.place(sum, 2, "BOTH: DIRECT LIGHT");
  sheet.place(share, 3, "RED: LIGHT, GREEN: BSDF");
  char report[160];
  const double total = std::max(1e-30, totalLight + totalBsdf);
  std::snprintf(report, sizeof report, "direct light at the first hit: %.1f %% from light samples, %.1f %% from BSDF samples\n",
                100.0 * totalLight / total, 100.0 * totalBsdf / total);
  return {sheet.image(), report};
}

DebugOutput varianceView(const DebugViewRequest& request) {
  constexpr int kBatches = 8;  // the variance of one sample, from the spread of 8 batch means
  Scene scene = tileScene(request);
  const int spp = std::max(1, scene.render.samplesPerPixel / kBatches);
  scene.render.samplesPerPixel = spp;
  const int w = scene.render.width, h = scene.render.height;
  std::vector<Image> variances;
  std::string report = "median per-pixel variance of one sample:";
  for (MisEstimator estimator : kEstimators) {
    std::vector<double> sum(size_t(w) * size_t(h), 0.0), squares(sum.size(), 0.0);
    for (int batch = 0; batch < kBatches; ++batch) {
      scene.render.seed = request.scene.render.seed + uint64_t(batch) + 1;
      const Image image = render(scene, estimatorOptions(request, estimator)).image;
      for (size_t i = 0; i < sum.size(); ++i) {
        const double v = double(luminance(image.pixels[i]));
        sum[i] += v, squares[i] += v * v;
      }
    }
    Image variance(w, h);
    std::vector<double> values;
    for (size_t i = 0; i < sum.size(); ++i) {
      const double mean = sum[i] / kBatches;
      const double ofBatchMean = std::max(0.0, (squares[i] - kBatches * mean * mean) / (kBatches - 1));
      const double ofOneSample = ofBatchMean * spp;
      values.push_back(ofOneSample);
      variance.pixels[i] = Color(float(ofOneSample));  // mapped to colour below, on one scale for all three
    }
    std::nth_element(values.begin(), values.begin() + long(values.size() / 2), values.end());
    char entry[64];
    std::snprintf(entry, sizeof entry, " %s %.3g", misEstimatorName(estimator), values[values.size() / 2]);
    report += entry;
    variances.push_back(std::move(variance));
  }
  // log10 of the variance, from 1e-4 (dark) to 1e2 (bright), on one scale.
  TileSheet sheet(3, 1, w, h);
  for (size_t k = 0; k < variances.size(); ++k) {
    Image& image = variances[k];
    for (Color& c : image.pixels) c = colorMap(std::clamp((std::log10(std::max(c.x, 1e-30f)) + 4.0f) / 6.0f, 0.0f, 1.0f));
    sheet.place(image, int(k), kLabels[k]);
  }
  return {sheet.image(), report + " (colour: log10 from -4 to 2)\n"};
}

}  // namespace

void addMisViews(std::vector<DebugView>& views) {
  views.push_back({9, "compare", "light sampling, BSDF sampling and MIS at equal samples and at equal time", compareView});
  views.push_back({9, "weights", "each pixel's light-sampled and BSDF-sampled direct light, and their MIS weights",
                   weightsView});
  views.push_back({9, "variance", "each estimator's per-pixel variance, on one logarithmic scale", varianceView});
}

}  // namespace pathlab
