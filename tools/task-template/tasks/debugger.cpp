// Task @N@'s visual debugger (students don't edit this file: it shows what
// their @STEM@.cpp does).
//   triangle   sampleTriangle on a grid of u: each cell of u (left) and
//              where your map takes it in the triangle (right), in one colour.
#include <algorithm>
#include <string>
#include <vector>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "tasks/@STEM@.h"

namespace pathlab {
namespace {

DebugOutput triangleView(const DebugViewRequest& request) {
  const int side = std::max(64, std::min(request.width / 2, request.height));
  constexpr int kCells = 8, kPerCell = 24;
  Image image(2 * side, side, Color(0.02f));
  const float margin = 0.08f * float(side), size = float(side) - 2.0f * margin;
  const Point2 square0(margin, margin), triangle0(float(side) + margin, float(side) - margin);
  drawLine(image, triangle0, triangle0 + Point2(size, 0.0f), Color(0.4f));
  drawLine(image, triangle0, triangle0 + Point2(0.0f, -size), Color(0.4f));
  drawLine(image, triangle0 + Point2(size, 0.0f), triangle0 + Point2(0.0f, -size), Color(0.4f));
  int outside = 0;
  for (int cy = 0; cy < kCells; ++cy)
    for (int cx = 0; cx < kCells; ++cx) {
      const Color color = idColor(uint32_t(cy * kCells + cx));
      const float cell = size / kCells;
      fillRect(image, square0 + cell * Point2(float(cx), float(cy)), square0 + cell * Point2(float(cx + 1), float(cy + 1)),
               color);
      for (int j = 0; j < kPerCell; ++j)
        for (int i = 0; i < kPerCell; ++i) {
          const Vec2 u((float(cx) + (float(i) + 0.5f) / kPerCell) / kCells, (float(cy) + (float(j) + 0.5f) / kPerCell) / kCells);
          const Point2 p = @STEM@::sampleTriangle(u);
          if (!(p.x >= -1e-6f && p.y >= -1e-6f && p.x + p.y <= 1.0f + 1e-6f)) ++outside;
          if (isFinite(Vec3(p, 0.0f))) drawDot(image, triangle0 + size * Point2(p.x, -p.y), 0.8f, color);
        }
    }
  const int textScale = 8 + 12 * 17 <= side ? 2 : 1;  // the longer label fits its half
  drawText(image, Point2(4.0f, 4.0f), "U", Color(0.9f), textScale);
  drawText(image, Point2(float(side) + 4.0f, 4.0f), "SAMPLETRIANGLE(U)", Color(0.9f), textScale);
  const std::string report = std::to_string(kCells * kCells * kPerCell * kPerCell) + " points of u on a grid, " +
                             std::to_string(outside) + " outside the triangle; equal areas of u must cover equal " +
                             "areas of the triangle\n";
  return {image, report};
}

}  // namespace

void add@NAME@Views(std::vector<DebugView>& views) {
  views.push_back({@N@, "triangle", "sampleTriangle on a grid of u: each cell of u and where it lands in the triangle",
                   triangleView});
}

}  // namespace pathlab
