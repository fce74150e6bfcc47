// Task 10's visual debugger (students don't edit this file: it shows what
// their thin_lens.cpp does).
//   confusion  the scene in focus everywhere (a pinhole), and where the
//              inspected pixel's lens rays land in it: each dot is one of
//              your rays' first hits, seen by the pinhole. The circle is the
//              circle of confusion the thin-lens equation predicts for the
//              depth the pixel sees; your dots should fill it evenly
//              (magnified in the top-left corner).
//   sweep      the scene through your lens focused at six distances, from
//              the nearest surface the camera sees to the farthest.
//   disk       sampleUnitDisk on a grid of u: each cell of u (left) and
//              where your map takes it on the disk (right), in one colour.
// A scene whose camera is a pinhole (aperture_radius 0) is shown through a
// lens of radius focal distance / 20.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "render/accelerator.h"
#include "render/render.h"
#include "tasks/thin_lens.h"

namespace pathlab {
namespace {

// The scene's lens, or a demonstration lens when the scene has none.
Camera lensCamera(const Camera& camera) {
  Camera lens = camera;
  if (!(lens.apertureRadius > 0.0f)) lens.apertureRadius = lens.focalDistance / 20.0f;
  return lens;
}

// Depth along the view axis of the first hit through raster point p (0: no hit).
float depthAt(const Accelerator& accelerator, const Camera& camera, const CameraBasis& basis, Point2 p, IVec2 size) {
  const Ray ray = generateCameraRay(camera, basis, p, size);
  const std::optional<Hit> hit = accelerator.intersect(ray, Interval{0.0f, kInfinity});
  return hit ? glm::dot(hit->point - camera.position, basis.forward) : 0.0f;
}

// Raster position of a world point seen by the pinhole at the lens's centre.
std::optional<Point2> project(const Camera& camera, const CameraBasis& basis, Point3 p, IVec2 size) {
  const Vec3 v = p - camera.position;
  const float depth = glm::dot(v, basis.forward);
  if (!(depth > 0.0f)) return std::nullopt;
  const float halfHeight = std::tan(glm::radians(camera.vfovDegrees) * 0.5f);
  const float halfWidth = halfHeight * float(size.x) / float(size.y);
  const float ndcX = glm::dot(v, basis.right) / (depth * halfWidth), ndcY = glm::dot(v, basis.up) / (depth * halfHeight);
  return Point2((ndcX + 1.0f) * 0.5f * float(size.x), (1.0f - ndcY) * 0.5f * float(size.y));
}

void drawCircle(Image& image, Point2 centre, float radius, Color color) {
  const int steps = std::clamp(int(radius * 2.0f), 24, 720);
  for (int i = 0; i < steps; ++i) {
    const float a = 2.0f * kPi * float(i) / float(steps), b = 2.0f * kPi * float(i + 1) / float(steps);
    drawLine(image, centre + radius * Point2(std::cos(a), std::sin(a)), centre + radius * Point2(std::cos(b), std::sin(b)),
             color);
  }
}

DebugOutput confusionView(const DebugViewRequest& request) {
  const Camera camera = lensCamera(request.scene.camera);
  const CameraBasis basis = cameraBasis(camera);
  const IVec2 size{request.width, request.height};
  const Accelerator accelerator(request.scene);
  Image image = scenePreview(request, accelerator, 0.6f);
  const IVec2 pixel = request.inspectedPixel();
  const Point2 centre = Point2(pixel) + Point2(0.5f);
  const Ray pinhole = generateCameraRay(camera, basis, centre, size);
  const float depth = depthAt(accelerator, camera, basis, centre, size);

  // Your rays from the pixel's centre, each to its first hit, and that hit as
  // the pinhole sees it. Random numbers as the renderer draws them per sample.
  constexpr int kRays = 400;
  std::vector<Point2> landed;
  const uint32_t pixelIndex = uint32_t(pixel.y) * uint32_t(request.scene.render.width) + uint32_t(pixel.x);
  for (int s = 0; s < kRays; ++s) {
    Sampler sampler(pixelIndex, uint32_t(s), request.scene.render.seed);
    sampler.next2D();  // the pixel sample's, unused: the rays start at the pixel's centre
    const Ray ray = generateThinLensRay(camera, basis, pinhole, sampler.next2D());
    if (!isFinite(ray.direction) || !isFinite(ray.origin)) continue;
    if (const std::optional<Hit> hit = accelerator.intersect(ray, Interval{0.0f, kInfinity})) {
      if (const std::optional<Point2> p = project(camera, basis, hit->point, size)) landed.push_back(*p);
    }
  }
  double spread = 0.0;
  for (const Point2& p : landed) spread += double(glm::dot(p - centre, p - centre));
  spread = landed.empty() ? 0.0 : std::sqrt(spread / double(landed.size()));
  const Image background = image;
  const Color kDotColor(1.0f, 0.1f, 0.8f);
  for (const Point2& p : landed) drawDot(image, p, 1.2f, kDotColor);

  // The thin-lens prediction: a point at depth z is spread over a disk of
  // radius A |1 - z/F| / z on the image plane at distance 1.
  const float pixelsPerUnit = 0.5f * float(size.y) / std::tan(glm::radians(camera.vfovDegrees) * 0.5f);
  const float radius = depth > 0.0f ? camera.apertureRadius * std::abs(1.0f - depth / camera.focalDistance) / depth *
                                          pixelsPerUnit
                                    : 0.0f;
  const Color circleColor(0.2f, 0.9f, 1.0f);
  if (depth > 0.0f) drawCircle(image, centre, std::max(radius, 0.5f), circleColor);

  // The same, magnified, in the top-left corner: a circle a few pixels wide
  // is hard to judge at 1:1.
  const int half = int(std::ceil(std::max(6.0f, 1.4f * radius + 3.0f)));
  const int factor = std::max(1, 200 / (2 * half));
  const IVec2 corner = IVec2(centre) - IVec2(half);
  Image inset(2 * half * factor, 2 * half * factor);
  for (int y = 0; y < inset.height; ++y)
    for (int x = 0; x < inset.width; ++x) {
      const IVec2 from = corner + IVec2(x, y) / factor;
      if (from.x >= 0 && from.y >= 0 && from.x < image.width && from.y < image.height) inset.at(x, y) = background.at(from.x, from.y);
    }
  const auto magnified = [&](Point2 p) { return (p - Point2(corner)) * float(factor); };
  for (const Point2& p : landed) drawDot(inset, magnified(p), 2.0f, kDotColor);
  if (depth > 0.0f) drawCircle(inset, magnified(centre), std::max(radius, 0.5f) * float(factor), circleColor);
  drawRectOutline(inset, Point2(0.0f), Point2(float(inset.width - 1), float(inset.height - 1)), Color(0.9f));
  char zoom[16];
  std::snprintf(zoom, sizeof zoom, "X%d", factor);
  drawText(inset, Point2(4.0f, 4.0f), zoom, Color(0.9f));
  markInspectedPixel(image, request);
  if (inset.width + 8 < image.width && inset.height + 8 < image.height)
    for (int y = 0; y < inset.height; ++y)
      for (int x = 0; x < inset.width; ++x) image.at(4 + x, 4 + y) = inset.at(x, y);

  char report[512];
  if (depth > 0.0f) {
    std::snprintf(report, sizeof report,
                  "pixel %d,%d sees depth %.4g; lens radius %.4g%s, focal distance %.4g\n"
                  "circle of confusion (thin lens): radius %.2f px\nyour %d rays' hits: RMS distance %.2f px from the "
                  "pixel (a filled circle: radius / sqrt 2 = %.2f px, on a surface facing the camera)\n",
                  pixel.x, pixel.y, double(depth), double(camera.apertureRadius),
                  request.scene.camera.apertureRadius > 0.0f ? "" : " (the scene's is 0: a demonstration lens)",
                  double(camera.focalDistance), double(radius), int(landed.size()), spread,
                  double(radius) / std::sqrt(2.0));
  } else {
    std::snprintf(report, sizeof report, "pixel %d,%d sees nothing: click a surface\n", pixel.x, pixel.y);
  }
  return {image, report};
}

DebugOutput sweepView(const DebugViewRequest& request) {
  const Camera camera = lensCamera(request.scene.camera);
  const CameraBasis basis = cameraBasis(camera);
  const Accelerator accelerator(request.scene);
  // The depths the camera sees, on a coarse grid: focus from the 5th to the 95th percentile.
  std::vector<float> depths;
  const IVec2 size{request.width, request.height};
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) {
      const float z = depthAt(accelerator, camera, basis, Point2((float(x) + 0.5f) * float(size.x) / 32.0f,
                                                                  (float(y) + 0.5f) * float(size.y) / 24.0f), size);
      if (z > 0.0f) depths.push_back(z);
    }
  std::sort(depths.begin(), depths.end());
  const float nearest = depths.empty() ? 0.5f * camera.focalDistance : depths[depths.size() / 20];
  const float farthest = depths.empty() ? 2.0f * camera.focalDistance : depths[depths.size() * 19 / 20];

  Scene scene = request.scene;
  scene.render.width = std::max(8, request.width / 3);
  scene.render.height = std::max(8, request.height / 3);
  scene.render.samplesPerPixel = 32;
  RenderOptions options;
  options.progress = false;
  options.threads = request.threads;
  options.integrator = Integrator::Preview;  // an eye light: quick, and the blur shows as well
  TileSheet sheet(3, 2, scene.render.width, scene.render.height);
  std::string report = "lens radius " + std::to_string(camera.apertureRadius) + "; focused at";
  for (int i = 0; i < 6; ++i) {
    scene.camera = camera;
    scene.camera.focalDistance = nearest * std::pow(farthest / nearest, float(i) / 5.0f);  // even steps in log depth
    char label[32];
    std::snprintf(label, sizeof label, "F = %.3g", double(scene.camera.focalDistance));
    sheet.place(render(scene, options).image, i, label);
    report += std::string(" ") + (label + 4);
  }
  return {sheet.image(), report + "\n"};
}

DebugOutput diskView(const DebugViewRequest& request) {
  const int side = std::max(64, std::min(request.width / 2, request.height));
  constexpr int kCells = 8, kPerCell = 24;
  Image image(2 * side, side, Color(0.02f));
  const float margin = 0.08f * float(side);
  const float scale = 0.5f * (float(side) - 2.0f * margin);
  const Point2 square0(margin, margin), diskCentre(1.5f * float(side), 0.5f * float(side));
  drawCircle(image, diskCentre, scale, Color(0.4f));
  int outside = 0;
  for (int cy = 0; cy < kCells; ++cy)
    for (int cx = 0; cx < kCells; ++cx) {
      const Color color = idColor(uint32_t(cy * kCells + cx));
      const float cell = 2.0f * scale / kCells;
      fillRect(image, square0 + cell * Point2(float(cx), float(cy)), square0 + cell * Point2(float(cx + 1), float(cy + 1)),
               color);
      for (int j = 0; j < kPerCell; ++j)
        for (int i = 0; i < kPerCell; ++i) {
          const Vec2 u((float(cx) + (float(i) + 0.5f) / kPerCell) / kCells, (float(cy) + (float(j) + 0.5f) / kPerCell) / kCells);
          const Point2 p = sampleUnitDisk(u);
          if (!(glm::dot(p, p) <= 1.0f + 1e-5f)) ++outside;
          if (isFinite(Vec3(p, 0.0f))) drawDot(image, diskCentre + scale * Point2(p.x, -p.y), 0.8f, color);
        }
    }
  const int textScale = 8 + 12 * 17 <= side ? 2 : 1;  // the longer label fits its half
  drawText(image, Point2(4.0f, 4.0f), "U", Color(0.9f), textScale);
  drawText(image, Point2(float(side) + 4.0f, 4.0f), "SAMPLEUNITDISK(U)", Color(0.9f), textScale);
  const std::string report = std::to_string(kCells * kCells * kPerCell * kPerCell) + " points of u on a grid, " +
                             std::to_string(outside) + " outside the unit disk; equal areas of u must cover equal " +
                             "areas of the disk\n";
  return {image, report};
}

}  // namespace

void addThinLensViews(std::vector<DebugView>& views) {
  views.push_back({10, "confusion",
                   "where the inspected pixel's lens rays land, against the thin lens's circle of confusion",
                   confusionView, kCameraImage | kUsesPixel});
  views.push_back({10, "sweep", "the scene through your lens focused at six distances, near to far", sweepView});
  views.push_back({10, "disk", "sampleUnitDisk on a grid of u: each cell of u and where it lands on the disk",
                   diskView});
}

}  // namespace pathlab
