// Task @N@'s visual debugger (students don't edit this file: it shows what
// their @STEM@.cpp does).
//   cone   left, the side view: a point x, a sphere light and the cone
//          coneCosThetaMax gives, its two edges grazing the sphere; right,
//          sampleCone's directions seen along that cone's axis (projected
//          on the plane across it), one colour per cell of u, the cone's
//          rim the circle.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "debug/debug_views.h"
#include "debug/draw.h"
#include "tasks/@STEM@.h"

namespace pathlab {
namespace {

void drawCircle(Image& image, Point2 center, float radius, Color color) {
  constexpr int kSegments = 96;
  for (int k = 0; k < kSegments; ++k) {
    const float a = 2.0f * kPi * float(k) / kSegments, b = 2.0f * kPi * float(k + 1) / kSegments;
    drawLine(image, center + radius * Point2(std::cos(a), std::sin(a)), center + radius * Point2(std::cos(b), std::sin(b)),
             color);
  }
}

DebugOutput coneView(const DebugViewRequest& request) {
  const int side = std::max(64, std::min(request.width / 2, request.height));
  Image image(2 * side, side, Color(0.02f));
  // The side view: x on the left, the sphere (centre 3 units along +x, radius 1.5) on the right.
  const Point3 x(0.0f), center(3.0f, 0.0f, 0.0f);
  const float radius = 1.5f, scale = float(side) / 5.0f;
  const Point2 origin(0.5f * scale, 0.5f * float(side));
  auto toImage = [&](float px, float py) { return origin + scale * Point2(px, -py); };
  drawCircle(image, toImage(center.x, center.y), radius * scale, Color(0.9f, 0.8f, 0.3f));
  drawDot(image, toImage(0.0f, 0.0f), 3.0f, Color(0.9f));
  const float cosThetaMax = @STEM@::coneCosThetaMax(x, center, radius);
  const float sinThetaMax = std::sqrt(std::max(0.0f, 1.0f - cosThetaMax * cosThetaMax));
  for (float sign : {1.0f, -1.0f}) {
    drawLine(image, toImage(0.0f, 0.0f), toImage(4.4f * cosThetaMax, sign * 4.4f * sinThetaMax), Color(0.4f, 0.7f, 1.0f));
  }
  // Directions around +z (the cone's axis seen from above), in the right half,
  // scaled so that the cone's rim (radius sin(theta_max), or 1 for a cone
  // wider than a hemisphere) is the circle drawn.
  constexpr int kCells = 8, kPerCell = 12;
  const Point2 middle(1.5f * float(side), 0.55f * float(side));
  const float disk = 0.4f * float(side) / std::max(1e-3f, cosThetaMax >= 0.0f ? sinThetaMax : 1.0f);
  drawCircle(image, middle, 0.4f * float(side), Color(0.4f, 0.7f, 1.0f));
  int outside = 0, wrongPdf = 0;
  const float pdf = 1.0f / (2.0f * kPi * (1.0f - cosThetaMax));
  for (int cy = 0; cy < kCells; ++cy)
    for (int cx = 0; cx < kCells; ++cx)
      for (int j = 0; j < kPerCell; ++j)
        for (int i = 0; i < kPerCell; ++i) {
          const Vec2 u((float(cx) + (float(i) + 0.5f) / kPerCell) / kCells, (float(cy) + (float(j) + 0.5f) / kPerCell) / kCells);
          const @STEM@::ConeSample s = @STEM@::sampleCone(Vec3(0.0f, 0.0f, 1.0f), cosThetaMax, u);
          if (!(s.direction.z >= cosThetaMax - 1e-4f)) ++outside;
          if (!(std::abs(s.pdf / pdf - 1.0f) < 1e-3f)) ++wrongPdf;
          if (isFinite(s.direction)) drawDot(image, middle + disk * Point2(s.direction.x, -s.direction.y), 0.8f,
                                             idColor(uint32_t(cy * kCells + cx)));
        }
  const int textScale = 8 + 12 * 14 <= side ? 2 : 1;  // the longer label fits its half
  drawText(image, Point2(4.0f, 4.0f), "CONE FROM X", Color(0.9f), textScale);
  drawText(image, Point2(float(side) + 4.0f, 4.0f), "ALONG THE AXIS", Color(0.9f), textScale);
  const int total = kCells * kCells * kPerCell * kPerCell;
  const std::string report = "cos theta_max " + std::to_string(cosThetaMax) + " (the sphere from x: " +
                             std::to_string(std::sqrt(1.0 - 0.25)) + "); " + std::to_string(total) +
                             " directions on a grid of u, " + std::to_string(outside) + " outside the cone, " +
                             std::to_string(wrongPdf) + " with a pdf other than 1 / (2 pi (1 - cos theta_max))\n";
  return {image, report};
}

}  // namespace

void add@NAME@Views(std::vector<DebugView>& views) {
  views.push_back({@N@, "cone", "the cone a sphere subtends, and sampleCone's directions around its axis", coneView});
}

}  // namespace pathlab
