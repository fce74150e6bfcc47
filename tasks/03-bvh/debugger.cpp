// Task 3's visual debugger (students don't edit this file: it shows what
// their bvh.cpp does). One camera ray per pixel centre.
//   heatmap  box tests per ray as colour, with a legend and the image mean
//   boxes      the boxes of the tree at --depth N drawn over the scene
//   traversal  the inspected pixel's ray and the leaves your intersectClosest
//              tested, in the order it tested them (1 = first), each with
//              the distance at which the ray enters its box
// All print the build statistics (nodes, depth, leaf sizes, SAH cost); the
// heat map also the tree's cost per ray as the framework walks it (its score)
// and the speed of your traversal beside the render path's walk of your tree.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "render/accelerator.h"
#include "render/task_wiring.h"
#include "tasks/camera_rays.h"
#include "util/parallel.h"

namespace pathlab {
namespace {

std::string buildReport(const Accelerator& accelerator) {
  if (!accelerator.usesBvh()) return "no usable BVH (task 3 not done?): brute-force intersection\n";
  char line[96];
  std::snprintf(line, sizeof line, "built in %.1f ms\n", accelerator.buildSeconds() * 1e3);
  return formatBvhStatistics(bvhStatistics(accelerator.bvh())) + line;
}

Color display(float r, float g, float b) { return {srgbToLinear(r), srgbToLinear(g), srgbToLinear(b)}; }

// Closest-hit queries per microsecond (= Mrays/s) of `accelerator` on `rays`:
// the best of three passes, each repeated until it lasts 20 ms.
double closestHitsPerMicrosecond(const Accelerator& accelerator, const std::vector<Ray>& rays) {
  double best = 0.0;
  for (int pass = 0; pass < 3; ++pass) {
    size_t traced = 0, found = 0;
    const auto start = std::chrono::steady_clock::now();
    double seconds = 0.0;
    do {
      for (const Ray& ray : rays) found += accelerator.intersect(ray, Interval{0.0f, kInfinity}).has_value();
      traced += rays.size();
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } while (seconds < 0.02 && !rays.empty());
    if (found > traced) return 0.0;  // (keeps the loop's work from being optimised away)
    best = std::max(best, seconds > 0.0 ? double(traced) / seconds * 1e-6 : 0.0);
  }
  return best;
}

DebugOutput heatmapView(const DebugViewRequest& request) {
  const Accelerator accelerator(request.scene);
  const Camera& camera = request.scene.camera;
  const CameraBasis basis = cameraBasis(camera);
  const int width = request.width, height = request.height;
  std::vector<TraversalStats> stats(size_t(width) * size_t(height));
  std::vector<Ray> rays(stats.size());
  forEachPixel(width, height, request.threads, [&](int x, int y) {
    const size_t i = size_t(y) * size_t(width) + size_t(x);
    rays[i] = generateCameraRay(camera, basis, Point2(float(x) + 0.5f, float(y) + 0.5f), {width, height});
    accelerator.intersect(rays[i], Interval{0.0f, kInfinity}, &stats[i]);
  });
  double boxSum = 0.0, nodeSum = 0.0, primitiveSum = 0.0;
  uint32_t maxBoxes = 1;
  for (const TraversalStats& s : stats) {
    boxSum += s.boxTests, nodeSum += s.nodesVisited, primitiveSum += s.primitiveTests;
    maxBoxes = std::max(maxBoxes, s.boxTests);
  }
  const double n = double(stats.size());

  constexpr int kLegend = 44;
  Image image(width, height + kLegend, display(0.08f, 0.08f, 0.08f));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.at(x, y) = colorMap(float(stats[size_t(y) * size_t(width) + size_t(x)].boxTests) / float(maxBoxes));
  // Legend: the colour bar from 0 to the maximum, and the mean.
  const int barLeft = 8, barRight = width - 8, barTop = height + 6;
  for (int x = barLeft; x < barRight; ++x) {
    fillRect(image, Point2(float(x), float(barTop)), Point2(float(x + 1), float(barTop + 10)),
             colorMap(float(x - barLeft) / float(barRight - barLeft - 1)));
  }
  const Color text = display(0.95f, 0.95f, 0.95f);
  drawText(image, Point2(float(barLeft), float(barTop + 15)), "0", text, 2);
  std::string maxLabel = std::to_string(maxBoxes);
  drawText(image, Point2(float(barRight - 12 * int(maxLabel.size())), float(barTop + 15)), maxLabel, text, 2);
  char caption[64];
  std::snprintf(caption, sizeof caption, "BOX TESTS/RAY MEAN %.1f", boxSum / n);
  drawText(image, Point2(float(width / 2 - 6 * int(std::string(caption).size())), float(barTop + 15)), caption, text, 2);

  char report[256];
  std::snprintf(report, sizeof report,
                "per ray: %.1f box tests (max %u), %.1f nodes visited, %.1f primitive tests\n", boxSum / n,
                maxBoxes, nodeSum / n, primitiveSum / n);
  // The tree alone, walked by the framework (what the grader's leaderboard ranks).
  std::string score;
  if (accelerator.usesBvh()) {
    score = "your tree's score, walked by the framework (lower is better):\n  " +
            formatTreeCost(treeCost(accelerator.bvh(), accelerator.geometry(), rays)) + "\n";
    // Speed on the same rays: your traversal, and the render path's 8-wide
    // walk of the same tree (Traversal::Fast), one thread, closest hits.
    const Accelerator fast(request.scene, Traversal::Fast);
    char speed[200];
    std::snprintf(speed, sizeof speed,
                  "speed on these rays, 1 thread:\n  your intersectClosest %.2f Mrays/s\n"
                  "  the render path's 8-wide walk of your tree %.2f Mrays/s\n",
                  closestHitsPerMicrosecond(accelerator, rays), closestHitsPerMicrosecond(fast, rays));
    score += speed;
  }
  return {image, buildReport(accelerator) + report + score};
}

DebugOutput boxesView(const DebugViewRequest& request) {
  const Accelerator accelerator(request.scene);
  Image image = scenePreview(request, accelerator, 0.35f);
  const Bvh& bvh = accelerator.bvh();
  const CameraProjection projection(request.drawingCamera(), {request.width, request.height});
  size_t drawn = 0;
  if (!bvh.nodes.empty()) {
    // Nodes at the chosen depth in colour; leaves that end above it in grey.
    std::vector<std::pair<uint32_t, int>> stack = {{0, 0}};
    while (!stack.empty()) {
      auto [i, depth] = stack.back();
      stack.pop_back();
      const BvhNode& node = bvh.nodes[i];
      if (depth == request.depth || node.isLeaf()) {
        projection.drawBox(image, node.bounds, depth == request.depth ? idColor(i) : Color(0.3f));
        ++drawn;
        continue;
      }
      stack.push_back({node.leftOrFirst, depth + 1});
      stack.push_back({node.leftOrFirst + 1, depth + 1});
    }
  }
  drawText(image, Point2(6, 6), "DEPTH " + std::to_string(request.depth), display(0.95f, 0.95f, 0.95f), 2);
  return {image, buildReport(accelerator) + "drew " + std::to_string(drawn) + " boxes at depth " +
                     std::to_string(request.depth) + "\n"};
}

DebugOutput traversalView(const DebugViewRequest& request) {
  const Accelerator accelerator(request.scene);
  const Scene& scene = request.scene;
  Image image = scenePreview(request, accelerator, 0.3f);
  const IVec2 pixel = request.inspectedPixel();
  const Ray ray = generateCameraRay(scene.camera, cameraBasis(scene.camera), Point2(pixel) + Point2(0.5f),
                                    {scene.render.width, scene.render.height});
  if (!accelerator.usesBvh()) return {image, buildReport(accelerator)};
  const Bvh& bvh = accelerator.bvh();

  // Trace the pixel's ray through your intersectClosest, recording the
  // primitives it tests; each belongs to one leaf.
  std::vector<uint32_t> leafOfSlot(bvh.primitives.size(), 0);
  for (uint32_t i = 0; i < bvh.nodes.size(); ++i) {
    const BvhNode& node = bvh.nodes[i];
    if (node.isLeaf())
      for (uint32_t k = 0; k < node.count; ++k) leafOfSlot[node.leftOrFirst + k] = i;
  }
  LeafGeometry geometry(scene, bvh.primitives, kLinkedTasks.primitives);
  std::vector<uint32_t> tested;
  geometry.recordTests(&tested);
  TraversalStats stats;
  const std::optional<PrimitiveHit> hit = intersectClosest(bvh, geometry, ray, Interval{0.0f, kInfinity}, &stats);
  std::vector<uint32_t> leaves;  // in the order first tested
  for (uint32_t slot : tested)
    if (std::find(leaves.begin(), leaves.end(), leafOfSlot[slot]) == leaves.end()) leaves.push_back(leafOfSlot[slot]);

  const CameraProjection projection(request.drawingCamera(), {request.width, request.height});
  const float rayEnd = hit ? hit->t : glm::length(bvh.nodes[0].bounds.max - bvh.nodes[0].bounds.min) * 2.0f;
  projection.drawSegment(image, ray.origin, ray.at(rayEnd), Color(1.0f, 1.0f, 0.2f));
  char line[160];
  std::snprintf(line, sizeof line, "pixel %d,%d: %u nodes visited, %u box tests, %u primitive tests, %s\n", pixel.x,
                pixel.y, stats.nodesVisited, stats.boxTests, stats.primitiveTests,
                hit ? ("closest hit t = " + std::to_string(hit->t)).c_str() : "no hit");
  std::string report = buildReport(accelerator) + line;
  report += "leaves in the order tested (entry distance; front to back is ascending):\n";
  const Vec3 inverse = 1.0f / ray.direction;
  for (size_t k = 0; k < leaves.size(); ++k) {
    const BvhNode& leaf = bvh.nodes[leaves[k]];
    const Color color = colorMap(leaves.size() > 1 ? float(k) / float(leaves.size() - 1) : 0.0f);
    projection.drawBox(image, leaf.bounds, color);
    const std::optional<float> entry = intersectBox(leaf.bounds, ray, inverse, Interval{0.0f, kInfinity});
    const bool holdsHit = hit && std::find(bvh.primitives.begin() + leaf.leftOrFirst,
                                           bvh.primitives.begin() + leaf.leftOrFirst + leaf.count,
                                           hit->primitive) != bvh.primitives.begin() + leaf.leftOrFirst + leaf.count;
    std::snprintf(line, sizeof line, "  %zu. node %u (%u primitives) enters at t = %.4g%s\n", k + 1, leaves[k],
                  leaf.count, entry ? double(*entry) : -1.0, holdsHit ? "  <- the closest hit" : "");
    report += line;
  }
  drawText(image, Point2(6, 6), "LEAVES TESTED: " + std::to_string(leaves.size()) + ", DARK FIRST", Color(0.95f), 2);
  markInspectedPixel(image, request);
  return {image, report};
}

}  // namespace

void addBvhViews(std::vector<DebugView>& views) {
  views.push_back({3, "heatmap", "box tests per camera ray as colour, legend and mean", heatmapView, kCameraImage});
  views.push_back({3, "boxes", "BVH boxes at --depth N over the scene, build statistics", boxesView,
                   kCameraImage | kUsesDepth | kUsesViewCamera});
  views.push_back({3, "traversal", "the pixel's ray and the leaves your traversal tested, in order", traversalView,
                   kCameraImage | kUsesPixel | kUsesViewCamera});
}

}  // namespace pathlab
