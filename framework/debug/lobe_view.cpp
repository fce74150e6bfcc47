// The BSDF lobe at the inspected pixel, for any material: a histogram of
// 200,000 directions drawn by the BSDF (left) beside what its pdf predicts
// (right), on the same equal-area grid of (phi, cos theta) in the local
// frame; the top row is the normal, the bottom row the opposite side. For
// delta lobes (mirror, glass) the prediction is a point mass at each
// direction with the lobe's probability. Tasks 6 and 8 show it ("lobe").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/bsdf.h"
#include "debug/debug_views.h"
#include "debug/draw.h"
#include "render/accelerator.h"
#include "render/task_wiring.h"
#include "tasks/camera_rays.h"
#include "util/random.h"

namespace pathlab {
namespace {

constexpr int kPhiCells = 100, kCosCells = 50;

int cellOf(const Vec3& local) {
  const float phi = std::atan2(local.y, local.x);
  const int i = std::clamp(int((phi + kPi) / (2.0f * kPi) * kPhiCells), 0, kPhiCells - 1);
  const int j = std::clamp(int((1.0f - local.z) * 0.5f * kCosCells), 0, kCosCells - 1);  // row 0: the normal
  return j * kPhiCells + i;
}

}  // namespace

DebugOutput bsdfLobeView(const DebugViewRequest& request) {
  const Scene& scene = request.scene;
  const int width = scene.render.width, height = scene.render.height;
  const IVec2 pixel = request.inspectedPixel();
  const Accelerator accelerator(scene);
  const CameraBasis basis = cameraBasis(scene.camera);
  const Ray ray = generateCameraRay(scene.camera, basis, Point2(pixel) + Point2(0.5f), {width, height});
  const std::optional<Hit> hit = accelerator.intersect(ray, Interval{0.0f, kInfinity});
  const int panel = std::max(400, request.width);
  Image image(2 * panel + 12, panel / 2 + 24, Color(0.02f));
  if (!hit) return {image, "pixel " + std::to_string(pixel.x) + "," + std::to_string(pixel.y) + " sees no surface\n"};

  const Material& material = scene.materials[hit->material];
  const Vec3 wo = -ray.direction;
  const Bsdf bsdf(material, *hit, wo, kLinkedTasks.lobes);
  constexpr int kSamples = 200000;
  std::vector<double> sampled(kPhiCells * kCosCells, 0.0), predicted(kPhiCells * kCosCells, 0.0);
  std::map<int, double> pointMass;  // delta lobes: cell -> probability
  int failed = 0;
  for (int i = 0; i < kSamples; ++i) {
    Sampler sampler(uint32_t(i), 0, 99);
    std::optional<BsdfSample> s = bsdf.sample(wo, sampler.next2D());
    if (!s) {
      ++failed;
      continue;
    }
    const int cell = cellOf(bsdf.frame().toLocal(s->wi));
    sampled[size_t(cell)] += 1.0;
    if (s->isDelta) pointMass[cell] = s->pdf;
  }
  if (bsdf.isDelta()) {
    for (auto [cell, probability] : pointMass) predicted[size_t(cell)] = probability * kSamples;
  } else {
    // The pdf integrated over each cell (midpoint rule, 4 x 4 per cell);
    // the grid is equal-area in solid angle: dw = dphi dcos.
    const float dPhi = 2.0f * kPi / kPhiCells, dCos = 2.0f / kCosCells;
    for (int j = 0; j < kCosCells; ++j)
      for (int i = 0; i < kPhiCells; ++i)
        for (int sj = 0; sj < 4; ++sj)
          for (int si = 0; si < 4; ++si) {
            const float phi = -kPi + (float(i) + (float(si) + 0.5f) / 4.0f) * dPhi;
            const float z = 1.0f - (float(j) + (float(sj) + 0.5f) / 4.0f) * dCos;
            const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
            const Vec3 local(r * std::cos(phi), r * std::sin(phi), z);
            predicted[size_t(j * kPhiCells + i)] +=
                double(bsdf.pdf(wo, bsdf.frame().toWorld(local))) * dPhi * dCos / 16.0 * kSamples;
          }
  }
  double peak = 1.0;
  for (size_t c = 0; c < sampled.size(); ++c) peak = std::max({peak, sampled[c], predicted[c]});
  auto drawPanel = [&](const std::vector<double>& counts, int x0, const char* label) {
    const float cellW = float(panel) / kPhiCells, cellH = float(panel / 2) / kCosCells;
    for (int j = 0; j < kCosCells; ++j)
      for (int i = 0; i < kPhiCells; ++i) {
        const float v = float(std::sqrt(counts[size_t(j * kPhiCells + i)] / peak));  // sqrt: show the tails
        fillRect(image, Point2(float(x0) + float(i) * cellW, 24.0f + float(j) * cellH),
                 Point2(float(x0) + float(i + 1) * cellW, 24.0f + float(j + 1) * cellH), colorMap(v));
      }
    drawLine(image, Point2(float(x0), 24.0f + float(panel) / 4.0f), Point2(float(x0 + panel), 24.0f + float(panel) / 4.0f),
             Color(0.5f));  // the horizon, cos theta = 0
    drawText(image, Point2(float(x0 + 4), 4.0f), label, Color(0.9f), 2);
    // Delta lobes hit single cells: mark them so they can be seen.
    if (!bsdf.isDelta()) return;
    for (size_t c = 0; c < counts.size(); ++c) {
      if (counts[c] <= 0.0) continue;
      const Point2 center(float(x0) + (float(c % kPhiCells) + 0.5f) * cellW, 24.0f + (float(c / kPhiCells) + 0.5f) * cellH);
      drawDot(image, center, 5.0f, colorMap(float(std::sqrt(counts[c] / peak))));
    }
  };
  drawPanel(sampled, 0, "SAMPLED");
  drawPanel(predicted, panel + 12, bsdf.isDelta() ? "PDF (DELTA)" : "PDF");

  char report[200];
  std::snprintf(report, sizeof report,
                "pixel %d,%d: %s material \"%s\", %d samples, %d failed; histogram sums to %.4f of the samples\n",
                pixel.x, pixel.y, materialTypeName(material.type), material.name.c_str(), kSamples, failed,
                [&] { double s = 0; for (double c : sampled) s += c; return s / kSamples; }());
  return {image, report};
}

}  // namespace pathlab
