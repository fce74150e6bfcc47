// Task 8's visual debugger (students don't edit this file: it shows what
// their microfacet.cpp does).
//   lobe    for the surface under the inspected pixel: directions drawn by the
//           BSDF beside what its pdf predicts (debug/lobe_view.cpp).
//   curves  in the plane of incidence of the inspected pixel: D(m) cos theta_m,
//           G1 and the pdf against angle, each scaled to its own peak.
//   sweep   the lobe f cos theta_i in the plane of incidence at roughness
//           0.05 ... 1, each scaled to its own peak (the peak in the report).
// A pixel that does not see a rough material shows a rough conductor of
// roughness 0.5 seen at the pixel's angle.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "render/accelerator.h"
#include "render/task_wiring.h"
#include "tasks/camera_rays.h"
#include "tasks/microfacet.h"
#include "util/frame.h"

namespace pathlab {
namespace {

// The material and the local wo under the inspected pixel.
struct Inspected {
  Material material;
  Vec3 wo{0.0f, 0.0f, 1.0f};
  std::string what;
};

Inspected inspect(const DebugViewRequest& request) {
  const Scene& scene = request.scene;
  const IVec2 pixel = request.inspectedPixel();
  const Ray ray = generateCameraRay(scene.camera, cameraBasis(scene.camera), Point2(pixel) + Point2(0.5f),
                                    {scene.render.width, scene.render.height});
  Inspected result;
  result.material.type = MaterialType::RoughConductor;
  result.material.albedo = Color(0.9f);
  result.what = "no rough surface at the pixel: a conductor of roughness 0.5";
  if (const std::optional<Hit> hit = Accelerator(scene).intersect(ray, Interval{0.0f, kInfinity})) {
    Vec3 n = hit->shadingNormal;
    if (glm::dot(n, -ray.direction) < 0.0f) n = -n;
    result.wo = Frame::fromNormal(n).toLocal(-ray.direction);
    const Material& m = scene.materials[hit->material];
    if (m.isRough()) {
      result.material = m;
      result.what = std::string(materialTypeName(m.type)) + " \"" + m.name + "\"";
    }
  }
  result.wo.z = std::max(result.wo.z, 1e-3f);
  result.wo = glm::normalize(result.wo);
  return result;
}

// f and pdf of a rough material in the local frame (task 8's functions).
Color brdf(const Material& m, const Vec3& wo, const Vec3& wi) {
  return m.type == MaterialType::RoughPlastic ? plasticBrdf(wo, wi, m.roughPlastic())
                                              : conductorBrdf(wo, wi, m.roughConductor());
}
float pdf(const Material& m, const Vec3& wo, const Vec3& wi) {
  return m.type == MaterialType::RoughPlastic ? plasticPdf(wo, wi, m.roughPlastic())
                                              : conductorPdf(wo, wi, m.roughConductor());
}

// The direction at signed angle theta (degrees) from the normal in wo's
// plane of incidence: positive on wo's side.
Vec3 inPlane(const Vec3& wo, float degrees) {
  const float phi = std::atan2(wo.y, wo.x), t = glm::radians(degrees);
  const float s = std::sin(t);
  return {s * std::cos(phi), s * std::sin(phi), std::cos(t)};
}

// A chart of curves over theta in [-90, 90] degrees, each scaled to its peak.
struct Curve {
  std::string label;
  Color color;
  std::vector<float> values;
};
constexpr int kSteps = 361;

Image chart(const std::vector<Curve>& curves, int width, int height, const std::string& title) {
  Image image(width, height, Color(0.02f));
  const float x0 = 40.0f, x1 = float(width) - 16.0f, y0 = 40.0f, y1 = float(height) - 30.0f;
  drawRectOutline(image, Point2(x0, y0), Point2(x1, y1), Color(0.35f));
  drawLine(image, Point2(0.5f * (x0 + x1), y0), Point2(0.5f * (x0 + x1), y1), Color(0.25f));  // the normal
  drawText(image, Point2(x0, 12.0f), title, Color(0.9f), 1);
  drawText(image, Point2(x0, y1 + 8.0f), "-90", Color(0.6f), 1);
  drawText(image, Point2(0.5f * (x0 + x1) - 4.0f, y1 + 8.0f), "0", Color(0.6f), 1);
  drawText(image, Point2(x1 - 80.0f, y1 + 8.0f), "90 (WO SIDE)", Color(0.6f), 1);
  float legendX = x0 + 6.0f;
  for (const Curve& c : curves) {
    float peak = 0.0f;
    for (float v : c.values) peak = std::max(peak, std::isfinite(v) ? v : 0.0f);
    if (peak > 0.0f) {
      for (int i = 1; i < kSteps; ++i) {
        auto at = [&](int k) {
          const float v = std::isfinite(c.values[size_t(k)]) ? c.values[size_t(k)] / peak : 0.0f;
          return Point2(x0 + (x1 - x0) * float(k) / float(kSteps - 1), y1 - (y1 - y0) * v);
        };
        drawLine(image, at(i - 1), at(i), c.color);
      }
    }
    legendX += float(drawText(image, Point2(legendX, y0 + 6.0f), c.label, c.color, 1)) + 14.0f;
  }
  return image;
}

DebugOutput curvesView(const DebugViewRequest& request) {
  const Inspected in = inspect(request);
  const float alpha = alphaFromRoughness(in.material.roughness);
  Curve d{"D(M) COS", Color(0.95f, 0.75f, 0.2f), {}}, g1{"G1(W)", Color(0.4f, 0.8f, 1.0f), {}},
      vis{"D_WO(M)", Color(0.9f, 0.4f, 0.9f), {}}, p{"PDF(WO, WI)", Color(0.5f, 0.95f, 0.5f), {}};
  for (int i = 0; i < kSteps; ++i) {
    const float degrees = -90.0f + 180.0f * float(i) / float(kSteps - 1);
    const Vec3 w = inPlane(in.wo, degrees);
    d.values.push_back(ggxD(w, alpha) * std::max(0.0f, w.z));
    g1.values.push_back(smithG1(w, Vec3(0, 0, 1), alpha));
    vis.values.push_back(visibleNormalPdf(in.wo, w, alpha));
    p.values.push_back(pdf(in.material, in.wo, w));
  }
  const int width = std::max(480, request.width), height = std::max(300, request.height);
  char title[160];
  std::snprintf(title, sizeof title, "ROUGHNESS %.2f (ALPHA %.3f), WO AT %.0f DEG", double(in.material.roughness),
                double(alpha), double(glm::degrees(std::acos(in.wo.z))));
  char report[300];
  std::snprintf(report, sizeof report,
                "%s; roughness %.3f, alpha %.4f, wo %.1f degrees from the normal. Curves over the plane of incidence, "
                "each scaled to its own peak.\n",
                in.what.c_str(), double(in.material.roughness), double(alpha), double(glm::degrees(std::acos(in.wo.z))));
  return {chart({d, g1, vis, p}, width, height, title), report};
}

DebugOutput sweepView(const DebugViewRequest& request) {
  const Inspected in = inspect(request);
  const float roughnesses[] = {0.05f, 0.1f, 0.2f, 0.4f, 0.7f, 1.0f};
  std::vector<Curve> curves;
  std::string report = in.what + ": f cos theta_i in the plane of incidence; peaks:";
  int k = 0;
  for (float r : roughnesses) {
    Material m = in.material;
    m.roughness = r;
    Curve c{"R " + std::to_string(r).substr(0, 4), colorMap(0.35f + 0.65f * float(k++) / 5.0f), {}};
    float peak = 0.0f;
    for (int i = 0; i < kSteps; ++i) {
      const Vec3 wi = inPlane(in.wo, -90.0f + 180.0f * float(i) / float(kSteps - 1));
      c.values.push_back(luminance(brdf(m, in.wo, wi)) * std::max(0.0f, wi.z));
      peak = std::max(peak, c.values.back());
    }
    char line[64];
    std::snprintf(line, sizeof line, " %.2f: %.4g", double(r), double(peak));
    report += line;
    curves.push_back(std::move(c));
  }
  const int width = std::max(480, request.width), height = std::max(300, request.height);
  return {chart(curves, width, height, "ROUGHNESS SWEEP: F COS, EACH SCALED TO ITS PEAK"), report + "\n"};
}

}  // namespace

void addMicrofacetViews(std::vector<DebugView>& views) {
  views.push_back({8, "lobe", "BSDF lobe at the inspected pixel: sampled directions beside the pdf", bsdfLobeView,
                   kUsesPixel});
  views.push_back({8, "curves", "D cos, G1, the visible normals and the pdf against angle at the inspected pixel",
                   curvesView, kUsesPixel});
  views.push_back({8, "sweep", "the lobe f cos at roughness 0.05 ... 1, in the inspected pixel's plane of incidence",
                   sweepView, kUsesPixel});
}

}  // namespace pathlab
