// Demos 6-7: the rendering equation at one point (three estimators of the
// same integral) and environment-map importance sampling.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "demo_support.h"
#include "debug/draw.h"
#include "tasks/environment.h"

#ifndef PATHLAB_SOURCE_DIR
#define PATHLAB_SOURCE_DIR "."
#endif

namespace pathlab::demo {
namespace {

struct V3 {
  double x, y, z;
  V3 operator-(const V3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  V3 operator*(double s) const { return {x * s, y * s, z * s}; }
};
double dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(const V3& a, const V3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(const V3& a) { return std::sqrt(dot(a, a)); }

// The integral of cos(theta) over the solid angle of a polygon seen from the
// origin with normal +z (Lambert's formula): 1/2 sum_i angle_i (n . unit normal of edge plane i).
double projectedSolidAngle(const std::vector<V3>& polygon) {
  double sum = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const V3 a = polygon[i] * (1.0 / length(polygon[i]));
    const V3 b = polygon[(i + 1) % polygon.size()] * (1.0 / length(polygon[(i + 1) % polygon.size()]));
    const V3 c = cross(a, b);
    const double angle = std::acos(std::clamp(dot(a, b), -1.0, 1.0));
    sum += angle * c.z / length(c);
  }
  return 0.5 * std::abs(sum);
}

}  // namespace

// ---- 6. the rendering equation at one point -------------------------------------

Demo renderingEquationDemo() {
  Demo demo;
  demo.name = "rendering-equation";
  demo.summary = "L_o at one point under a square light: uniform vs cosine vs light sampling, variance per sample";
  demo.parameters = {{"light size", 0.5, 0.05, 4.0, false, true, "side of the square light"},
                     {"height", 1.0, 0.2, 4.0, false, false, "height of the light above the point"},
                     {"offset", 0.5, 0.0, 3.0, false, false, "sideways offset of the light"},
                     {"samples", 4096, 16, 1e6, true, true, "samples per estimator"},
                     {"seed", 1, 0, 1000, true, false, "random seed"}};
  demo.run = [](const Values& p) {
    const double pi = std::numbers::pi;
    const double size = p.at("light size"), h = p.at("height"), offset = p.at("offset");
    const int n = count(p, "samples");
    const double albedo = 0.8, emitted = 10.0;  // diffuse f = albedo / pi; the light's radiance
    // The point is the origin, normal +z; the light is the square [offset +- size/2] x [+- size/2] at z = h, facing down.
    const double x0 = offset - size / 2, x1 = offset + size / 2, y0 = -size / 2, y1 = size / 2;
    const double exact = albedo / pi * emitted * projectedSolidAngle({{x0, y0, h}, {x1, y0, h}, {x1, y1, h}, {x0, y1, h}});
    auto hitsLight = [&](const V3& d) {
      if (d.z <= 0.0) return false;
      const double t = h / d.z, x = t * d.x, y = t * d.y;
      return x >= x0 && x <= x1 && y >= y0 && y <= y1;
    };
    // One estimate f Li cos / pdf per strategy and sample.
    Uniform uniform(uint64_t(count(p, "seed")));
    auto estimate = [&](int strategy) {
      const double u1 = uniform(), u2 = uniform(), phi = 2.0 * pi * u2;
      if (strategy == 0) {  // uniform hemisphere, pdf 1/(2 pi)
        const double z = u1, r = std::sqrt(1.0 - z * z);
        return hitsLight({r * std::cos(phi), r * std::sin(phi), z}) ? albedo / pi * emitted * z * 2.0 * pi : 0.0;
      }
      if (strategy == 1) {  // cosine-weighted, pdf cos/pi: f Li cos / pdf = albedo Li
        const double r = std::sqrt(u1), z = std::sqrt(1.0 - u1);
        return hitsLight({r * std::cos(phi), r * std::sin(phi), z}) ? albedo * emitted : 0.0;
      }
      // Light sampling: a uniform point on the square, pdf 1/A per area;
      // dw = cos(theta_light) dA / d^2 turns it into a solid-angle pdf.
      const V3 q{x0 + u1 * size, y0 + u2 * size, h};
      const double d2 = dot(q, q), d = std::sqrt(d2);
      const double cosSurface = q.z / d, cosLight = h / d;
      return albedo / pi * emitted * cosSurface * cosLight / d2 * size * size;
    };
    const char* names[] = {"uniform hemisphere", "cosine-weighted", "light (area) sampling"};
    Plot running{"running estimate", "N", "L_o", true, false, false, {}, {}};
    Plot variance{"variance per sample (log)", "", "variance", false, true, false, {names[0], "cosine", "light"}, {}};
    Series varianceBars;
    varianceBars.kind = Series::Kind::Bars;
    varianceBars.label = "sample variance";
    std::string numbers = format("exact L_o = albedo/pi x L_e x (projected solid angle) = %.6f  (albedo %.1f, L_e %.0f)\n",
                                 exact, albedo, emitted);
    for (int strategy = 0; strategy < 3; ++strategy) {
      double sum = 0.0, sumSquares = 0.0;
      std::vector<double> ns, means;
      for (int i = 1; i <= n; ++i) {
        const double e = estimate(strategy);
        sum += e, sumSquares += e * e;
        if ((i & (i - 1)) == 0 || i == n) ns.push_back(i), means.push_back(sum / i);  // powers of two
      }
      const double mean = sum / n, var = std::max(0.0, sumSquares / n - mean * mean);
      running.series.push_back(line(ns, means, names[strategy]));
      varianceBars.y.push_back(std::max(var, 1e-12));
      numbers += format("%-22s mean %.6f +- %.6f (1 sigma), variance per sample %.4g\n", names[strategy], mean,
                        std::sqrt(var / n), var);
    }
    running.series.push_back(line({1.0, double(n)}, {exact, exact}, "exact", true));
    variance.series.push_back(varianceBars);
    numbers += format("light sampling needs %.3gx fewer samples than uniform and %.3gx fewer than cosine for the same error\n",
                      varianceBars.y[0] / varianceBars.y[2], varianceBars.y[1] / varianceBars.y[2]);
    DemoResult result;
    result.figure = {"L_o = integral of f L_i cos(theta) over the hemisphere, at one point", {running, variance}};
    result.numbers = numbers;
    return result;
  };
  return demo;
}

// ---- 7. environment-map importance sampling ---------------------------------------

Demo environmentDemo() {
  Demo demo;
  demo.name = "env-importance";
  demo.summary = "environment-map importance sampling (task 7's code): the map, its per-pixel PMF, samples drawn on it";
  demo.parameters = {{"samples", 2000, 100, 100000, true, true, "directions drawn"},
                     {"seed", 1, 0, 1000, true, false, "random seed"}};
  demo.run = [](const Values& p) {
    static const Image map = [] {
      const std::string path = PATHLAB_SOURCE_DIR "/media/envmaps/sky-sun.exr";
      return readImage(std::filesystem::exists(path) ? path : "media/envmaps/sky-sun.exr");
    }();
    const EnvironmentDistribution distribution = buildEnvironmentDistribution(map);
    const int n = count(p, "samples");
    const int width = map.width, height = map.height;
    // The map, tone-mapped, with the samples on it.
    Image shown(width, height);
    for (size_t i = 0; i < map.pixels.size(); ++i) shown.pixels[i] = map.pixels[i] / (Color(1.0f) + map.pixels[i]);
    Image pmf(width, height);
    double total = 0.0, peak = 0.0;
    std::vector<double> weights(map.pixels.size());
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        // The PMF the sampler follows: luminance x sin(theta) per pixel.
        const double w = double(luminance(map.at(x, y))) * std::sin(std::numbers::pi * (y + 0.5) / height);
        weights[size_t(y * width + x)] = w;
        total += w, peak = std::max(peak, w);
      }
    const double floorWeight = peak * 1e-6;
    for (size_t i = 0; i < weights.size(); ++i) {
      pmf.pixels[i] = colorMap(float(std::log(std::max(weights[i], floorWeight) / floorWeight) / std::log(peak / floorWeight)));
    }
    // The brightest 0.1 % of pixels: their share of the PMF and of the samples.
    std::vector<double> sorted = weights;
    const size_t top = std::max<size_t>(1, sorted.size() / 1000);
    std::nth_element(sorted.begin(), sorted.begin() + long(top - 1), sorted.end(), std::greater<>());
    const double threshold = sorted[top - 1];
    double topShare = 0.0;
    for (double w : weights)
      if (w >= threshold) topShare += w / total;
    // A zoom on the brightest pixel (the sun), 8x enlarged, for the samples that pile up there.
    const size_t brightest = size_t(std::max_element(weights.begin(), weights.end()) - weights.begin());
    constexpr int kZoomW = 40, kZoomH = 24, kZoom = 8;
    const int zx0 = std::clamp(int(brightest % size_t(width)) - kZoomW / 2, 0, width - kZoomW);
    const int zy0 = std::clamp(int(brightest / size_t(width)) - kZoomH / 2, 0, height - kZoomH);
    Image zoom(kZoomW * kZoom, kZoomH * kZoom);
    for (int y = 0; y < zoom.height; ++y)
      for (int x = 0; x < zoom.width; ++x) zoom.at(x, y) = shown.at(zx0 + x / kZoom, zy0 + y / kZoom);
    Uniform uniform(uint64_t(count(p, "seed")));
    int inTop = 0, drawn = 0;
    for (int i = 0; i < n; ++i) {
      const std::optional<EnvironmentSample> s = sampleEnvironment(distribution, Vec2(float(uniform()), float(uniform())));
      if (!s) continue;
      ++drawn;
      const Point2 uv = directionToEquirect(s->direction);
      const int x = std::min(width - 1, int(uv.x * width)), y = std::min(height - 1, int(uv.y * height));
      inTop += weights[size_t(y * width + x)] >= threshold;
      drawDot(shown, Point2(uv.x * width, uv.y * height), 1.2f, Color(1.0f, 0.05f, 0.05f));
      const Point2 inZoom((uv.x * width - zx0) * kZoom, (uv.y * height - zy0) * kZoom);
      if (inZoom.x >= 0 && inZoom.y >= 0 && inZoom.x < zoom.width && inZoom.y < zoom.height) {
        drawDot(zoom, inZoom, 1.5f, Color(1.0f, 0.05f, 0.05f));
      }
    }
    Series mapImage, pmfImage, zoomImage;
    mapImage.kind = pmfImage.kind = zoomImage.kind = Series::Kind::Image;
    mapImage.image = shown;
    pmfImage.image = pmf;
    zoomImage.image = zoom;
    Plot mapPlot{format("the map with %d importance samples", n), "", "", false, false, false, {}, {mapImage}};
    Plot pmfPlot{"PMF per pixel: luminance x sin(theta) (log colour)", "", "", false, false, false, {}, {pmfImage}};
    DemoResult result;
    result.figure = {"Environment-map importance sampling (marginal CDF over rows, conditional CDF in the row)",
                     {mapPlot, pmfPlot,
                      {format("zoom x%d on the sun: where %.0f%% of the samples went", kZoom, 100.0 * inTop / std::max(1, drawn)),
                       "", "", false, false, false, {}, {zoomImage}}}};
    result.numbers = format("map %dx%d (media/envmaps/sky-sun.exr), %d of %d samples drawn\n", width, height, drawn, n) +
                     format("the brightest 0.1%% of pixels (%zu, the sun) hold %.1f%% of the PMF and received %.1f%% of the samples\n",
                            top, 100.0 * topShare, 100.0 * inTop / std::max(1, drawn)) +
                     "sin(theta): rows near the poles cover less solid angle, so they are picked less\n" +
                     "the pdf per steradian is p(u, v) / (2 pi^2 sin theta): the change of variables from the image to directions\n";
    return result;
  };
  return demo;
}

}  // namespace pathlab::demo
