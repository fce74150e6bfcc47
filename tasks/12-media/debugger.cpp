// Task 12's visual debugger (students don't edit this file: it shows what
// their media.cpp does).
//   paths          the inspected pixel's first 8 paths in the scene: each
//                  segment up to where the path scattered in a medium (an
//                  orange dot) or met a surface; shadow rays green where
//                  light got through, red where a surface blocked them.
//                  The report counts the scattering events.
//   transmittance  your transmittance along the inspected pixel's camera
//                  ray, on a log scale against the distance: a straight
//                  stretch of slope -sigmaT in each medium (the dashed
//                  guides), level in a vacuum, 0 past a surface. Vertical
//                  lines: the surfaces the ray meets.
//   phase          the Henyey-Greenstein lobe for g = -0.9 to 0.9 (and the
//                  scene's media): your henyeyGreenstein as a polar curve
//                  (white) and a histogram of your sampleHenyeyGreenstein's
//                  directions (orange), which must lie on it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "debug/inspect.h"
#include "render/accelerator.h"
#include "render/render.h"
#include "render/task_wiring.h"
#include "tasks/media.h"

namespace pathlab {
namespace {

DebugOutput pathsView(const DebugViewRequest& request) {
  Scene scene = request.scene;
  scene.render.width = request.width;
  scene.render.height = request.height;
  const Accelerator accelerator(scene);
  const Lights lights = Lights::fromScene(scene, kLinkedTasks.environment);
  Image image = scenePreview(request, accelerator, 0.3f);
  const int samples = std::min(scene.render.samplesPerPixel, 8);
  const PixelInspection inspection =
      inspectPixel(scene, accelerator, lights, RenderOptions{}, request.inspectedPixel(), samples);

  const CameraProjection projection(request.drawingCamera(), {request.width, request.height});
  const Aabb bounds = accelerator.usesBvh() ? accelerator.bvh().nodes[0].bounds : Aabb{};
  const float escape = std::max(1.0f, glm::length(bounds.max - bounds.min));  // how far to draw a miss
  const Color camera(1.0f), reached(0.1f, 0.9f, 0.1f), blocked(0.9f, 0.05f, 0.05f), scatter(1.0f, 0.55f, 0.1f);
  int scatterings = 0, surfaces = 0;
  for (const InspectedSample& sample : inspection.samples) {
    // The path's own rays, in order: each one ends where the next begins.
    std::vector<const TracedRay*> path;
    for (const TracedRay& traced : sample.rays) {
      if (!traced.shadow) path.push_back(&traced);
    }
    for (size_t k = 0; k < path.size(); ++k) {
      const TracedRay& traced = *path[k];
      Point3 end = traced.hit ? traced.record.point : traced.ray.at(escape);
      bool scattered = false;
      if (k + 1 < path.size()) {  // the next ray starts before the surface: a scattering event on the way
        const Point3 next = path[k + 1]->ray.origin;
        const float along = glm::dot(next - traced.ray.origin, traced.ray.direction);
        const float surface = traced.hit ? traced.record.t : kInfinity;
        if (along < surface * (1.0f - 1e-3f) && glm::length(next - traced.ray.at(along)) < 1e-3f * (1.0f + along)) {
          end = next;
          scattered = true;
        }
      }
      const float shade = 0.15f + 0.85f * float(std::min<size_t>(k, 8)) / 8.0f;
      projection.drawSegment(image, traced.ray.origin, end, k == 0 ? camera : colorMap(shade));
      if (scattered) {
        projection.drawDot(image, end, 2.5f, scatter);
        ++scatterings;
      } else if (traced.hit) {
        ++surfaces;
      }
    }
    for (const TracedRay& traced : sample.rays) {
      if (!traced.shadow) continue;
      const float endT = traced.hit ? traced.record.t : (std::isfinite(traced.range.max) ? traced.range.max : escape);
      const bool passes = !traced.hit || scene.materials[traced.record.material].type == MaterialType::Interface;
      projection.drawSegment(image, traced.ray.origin, traced.ray.at(endT), passes ? reached : blocked);
    }
  }
  markInspectedPixel(image, request);
  drawText(image, Point2(6, 6), std::to_string(samples) + " PATHS, -M " + std::to_string(scene.render.maxDepth),
           Color(0.95f), 2);
  char summary[160];
  std::snprintf(summary, sizeof summary,
                "%d paths: %d scattering events in media (orange dots), %d surface hits (interfaces included)\n",
                samples, scatterings, surfaces);
  return {image, summary + formatInspection(inspection)};
}

// A surface along the camera ray, and the medium after it as the scene says:
// where the curve may bend (an interface) or drop (a surface).
struct Crossing {
  float t;
  MediumIndex after;
  bool interface;
};

// The surfaces along the ray, through every one of them (at most 16).
std::vector<Crossing> crossingsAlong(const Scene& scene, const Accelerator& accelerator, const Ray& ray) {
  std::vector<Crossing> crossings;
  MediumIndex medium = scene.medium;
  float start = 0.0f;
  for (int k = 0; k < 16; ++k) {
    const std::optional<Hit> hit = accelerator.intersect(ray, Interval{start, kInfinity});
    if (!hit) break;
    medium = scene.mediumAcross(*hit, ray.direction, medium);
    crossings.push_back({hit->t, medium, scene.materials[hit->material].type == MaterialType::Interface});
    start = hit->t * (1.0f + 1e-4f) + 1e-4f;
  }
  return crossings;
}

// The plot's frame: distance 0..far across, log10 T from 0 down to -6.
struct TransmittancePlot {
  static constexpr double kDecades = 6.0;
  float far, left, right, top, bottom;
  TransmittancePlot(float farthest, int width, int height)
      : far(farthest), left(60.0f), right(float(width) - 20.0f), top(30.0f), bottom(float(height) - 40.0f) {}
  float x(float d) const { return left + (right - left) * d / far; }
  float y(double t) const {
    const double l = std::clamp(std::log10(std::max(t, 1e-30)), -kDecades, 0.0);
    return float(top + (bottom - top) * (-l / kDecades));
  }
};

void drawDecadesAndCrossings(Image& image, const TransmittancePlot& plot, const std::vector<Crossing>& crossings) {
  for (int decade = 0; decade <= int(TransmittancePlot::kDecades); ++decade) {
    const float yy = plot.y(std::pow(10.0, -decade));
    drawLine(image, Point2(plot.left, yy), Point2(plot.right, yy), Color(0.12f));
    drawText(image, Point2(6.0f, yy - 6.0f), "1E-" + std::to_string(decade), Color(0.6f), 1);
  }
  for (const Crossing& c : crossings) {
    drawLine(image, Point2(plot.x(c.t), plot.top), Point2(plot.x(c.t), plot.bottom),
             c.interface ? Color(0.2f, 0.4f, 0.9f) : Color(0.6f));
  }
}

// Guides, dashed: from the curve's value at the start of each stretch, slope
// -sigmaT of the medium there; none past a surface (nothing gets through).
void drawGuides(Image& image, const TransmittancePlot& plot, const Scene& scene, const std::vector<Crossing>& crossings,
                const std::vector<double>& value) {
  const int steps = int(value.size()) - 1;
  const float far = plot.far;
  float from = 0.0f;
  MediumIndex in = scene.medium;
  for (size_t k = 0; k <= crossings.size(); ++k) {
    const float to = k < crossings.size() ? crossings[k].t : far;
    if (in != kVacuum) {
      const double sigmaT = double(scene.media[size_t(in)].sigmaT);
      const int i0 = std::min(steps, int(std::ceil(from / far * float(steps))));
      const double t0 = value[size_t(i0)], d0 = far * double(i0) / steps;
      for (float d = float(d0); d < to; d += far / 100.0f) {
        if (int(d / far * 100.0f) % 2 == 0) {
          const float d1 = std::min(to, d + far / 100.0f);
          drawLine(image, Point2(plot.x(d), plot.y(t0 * std::exp(-sigmaT * (d - d0)))),
                   Point2(plot.x(d1), plot.y(t0 * std::exp(-sigmaT * (d1 - d0)))), Color(0.9f, 0.6f, 0.1f));
        }
      }
    }
    if (k < crossings.size()) {
      in = crossings[k].after;
      if (!crossings[k].interface) break;
      from = to;
    }
  }
}

void drawCurve(Image& image, const TransmittancePlot& plot, const std::vector<double>& value) {
  const int steps = int(value.size()) - 1;
  for (int i = 0; i < steps; ++i) {
    drawLine(image, Point2(plot.x(plot.far * float(i) / float(steps)), plot.y(value[size_t(i)])),
             Point2(plot.x(plot.far * float(i + 1) / float(steps)), plot.y(value[size_t(i + 1)])), Color(0.95f));
  }
  drawText(image, Point2(plot.left, 8.0f), "TRANSMITTANCE (LOG) AGAINST DISTANCE", Color(0.9f), 1);
}

DebugOutput transmittanceView(const DebugViewRequest& request) {
  const Scene& scene = request.scene;
  const Accelerator accelerator(scene);
  const Lights lights = Lights::fromScene(scene, kLinkedTasks.environment);
  TraceContext context(scene, accelerator, lights, kLinkedTasks.lobes);
  const IVec2 pixel = request.inspectedPixel();
  const CameraBasis basis = cameraBasis(scene.camera);
  const Ray ray =
      generateCameraRay(scene.camera, basis, Point2(pixel) + Point2(0.5f), {scene.render.width, scene.render.height});
  const std::vector<Crossing> crossings = crossingsAlong(scene, accelerator, ray);
  const float far = crossings.empty() ? 10.0f : crossings.back().t * 1.25f;

  // Your transmittance at kSteps distances, each the mean of kCalls calls
  // (an estimator that draws random numbers shows its mean).
  constexpr int kSteps = 200, kCalls = 16;
  auto meanTransmittance = [&](float d, uint32_t stream) {
    double sum = 0.0;
    for (int c = 0; c < kCalls; ++c) {
      Sampler sampler(stream, uint32_t(c), scene.render.seed);
      sum += transmittance(context, ray, d, scene.medium, sampler);
    }
    return sum / kCalls;
  };
  std::vector<double> value(kSteps + 1);
  for (int i = 0; i <= kSteps; ++i) value[size_t(i)] = meanTransmittance(far * float(i) / kSteps, uint32_t(i));

  const int width = std::max(320, request.width), height = std::max(200, request.height);
  Image image(width, height, Color(0.02f));
  const TransmittancePlot plot(far, width, height);
  drawDecadesAndCrossings(image, plot, crossings);
  drawGuides(image, plot, scene, crossings, value);
  drawCurve(image, plot, value);

  std::string report =
      "camera ray of pixel (" + std::to_string(pixel.x) + ", " + std::to_string(pixel.y) + "), starting in " +
      (scene.medium == kVacuum ? std::string("a vacuum") : "medium " + scene.media[size_t(scene.medium)].name) + "\n";
  for (const Crossing& c : crossings) {
    char line[160];
    const double before = meanTransmittance(c.t * (1.0f - 1e-4f), uint32_t(kSteps + 1));
    std::snprintf(line, sizeof line, "  t = %.4g: %s, then %s; your transmittance just before: %.4g\n", c.t,
                  c.interface ? "interface" : "surface",
                  c.after == kVacuum ? "vacuum" : scene.media[size_t(c.after)].name.c_str(), before);
    report += line;
  }
  return {image, report};
}

DebugOutput phaseView(const DebugViewRequest& request) {
  std::vector<float> gs = {-0.9f, -0.5f, 0.0f, 0.5f, 0.9f};
  for (const Medium& m : request.scene.media) {
    if (std::find(gs.begin(), gs.end(), m.g) == gs.end()) gs.push_back(m.g);
  }
  const int columns = 3, rows = int(gs.size() + 2) / 3;
  const int tile = std::max(160, std::min(request.width / columns, 360));
  TileSheet sheet(columns, rows, tile, tile);
  std::string report = "g      mean cosine of your samples   your p integrated over the sphere\n";
  constexpr int kBins = 90, kSamples = 200000;
  const Vec3 travel(1.0f, 0.0f, 0.0f);  // the ray travelled to the right
  for (size_t k = 0; k < gs.size(); ++k) {
    const float g = gs[k];
    // The density of theta (the angle from the direction of travel), from your samples and from your p.
    std::vector<double> histogram(kBins, 0.0);
    double meanCosine = 0.0;
    for (int i = 0; i < kSamples; ++i) {
      const Vec2 u((float(i) + 0.5f) / kSamples, std::fmod(float(i) * 0.6180339887f, 1.0f));
      const Vec3 wi = sampleHenyeyGreenstein(travel, g, u);
      const float c = std::clamp(glm::dot(wi, travel), -1.0f, 1.0f);
      meanCosine += c;
      histogram[size_t(std::min(kBins - 1, int(std::acos(c) / kPi * kBins)))] += 1.0;
    }
    meanCosine /= kSamples;
    double integral = 0.0;  // of p over the sphere: 2 pi sin(theta) dtheta per ring
    std::vector<double> curve(kBins), sampled(kBins);
    for (int b = 0; b < kBins; ++b) {
      const double theta = (b + 0.5) * kPi / kBins, dTheta = kPi / kBins;
      const double ring = 2.0 * kPi * std::sin(theta) * dTheta;
      curve[size_t(b)] = henyeyGreenstein(float(std::cos(theta)), g);
      integral += curve[size_t(b)] * ring;
      sampled[size_t(b)] = histogram[size_t(b)] / kSamples / ring;  // samples per steradian
    }
    // Polar plot of the lobe, r = p(theta)^(1/3) so that g = 0.9 and 0 both fit.
    Image plot(tile, tile, Color(0.02f));
    const Point2 centre(0.5f * float(tile), 0.55f * float(tile));
    double largest = 1e-12;
    for (int b = 0; b < kBins; ++b) largest = std::max({largest, curve[size_t(b)], sampled[size_t(b)]});
    const float scale = 0.42f * float(tile) / float(std::cbrt(largest));
    auto at = [&](double theta, double p, double side) {
      const float r = scale * float(std::cbrt(std::max(0.0, p)));
      return centre + r * Point2(float(std::cos(theta)), float(-side * std::sin(theta)));
    };
    drawLine(plot, Point2(4.0f, centre.y), Point2(float(tile) - 4.0f, centre.y), Color(0.15f));
    drawText(plot, Point2(float(tile) - 60.0f, centre.y + 4.0f), "TRAVEL", Color(0.4f), 1);
    for (double side : {1.0, -1.0}) {
      for (int b = 0; b + 1 < kBins; ++b) {
        const double t0 = (b + 0.5) * kPi / kBins, t1 = (b + 1.5) * kPi / kBins;
        drawLine(plot, at(t0, curve[size_t(b)], side), at(t1, curve[size_t(b + 1)], side), Color(0.95f));
      }
      for (int b = 0; b < kBins; ++b) {
        drawDot(plot, at((b + 0.5) * kPi / kBins, sampled[size_t(b)], side), 1.5f, Color(1.0f, 0.55f, 0.1f));
      }
    }
    char label[48];
    std::snprintf(label, sizeof label, "G = %.2f", double(g));
    sheet.place(plot, int(k), label);
    char line[120];
    std::snprintf(line, sizeof line, "%5.2f  %+.4f (should be %+.2f)        %.4f (should be 1)\n", double(g), meanCosine,
                  double(g), integral);
    report += line;
  }
  return {sheet.image(), report};
}

}  // namespace

void addMediaViews(std::vector<DebugView>& views) {
  views.push_back({12, "paths", "the pixel's paths: where they scatter in media, and their shadow rays", pathsView,
                   kCameraImage | kUsesPixel | kUsesViewCamera});
  views.push_back({12, "transmittance", "your transmittance along the pixel's camera ray, against the media it crosses",
                   transmittanceView, kUsesPixel});
  views.push_back({12, "phase", "the Henyey-Greenstein lobe for several g: your p, and your samples' histogram",
                   phaseView});
}

}  // namespace pathlab
