#include "pathlab/draw.h"

#include <algorithm>
#include <cmath>

#include "pathlab/random.h"

namespace pathlab {

Color colorMap(float t) {
  // Piecewise-linear fit of matplotlib's viridis through five stops.
  static const Color stops[] = {{0.267f, 0.005f, 0.329f}, {0.229f, 0.322f, 0.546f}, {0.128f, 0.567f, 0.551f},
                                {0.369f, 0.789f, 0.383f}, {0.993f, 0.906f, 0.144f}};
  t = std::isfinite(t) ? std::clamp(t, 0.0f, 1.0f) : 0.0f;
  float x = t * 4.0f;
  int i = std::min(int(x), 3);
  Color c = glm::mix(stops[i], stops[i + 1], x - float(i));
  // Stops are display values; the image stores linear radiance.
  return {srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z)};
}

Color idColor(uint32_t id) {
  uint64_t h = mix64(uint64_t(id) + 1);
  auto channel = [&](int shift) { return 0.15f + 0.85f * float((h >> shift) & 0xff) / 255.0f; };
  return {channel(0), channel(8), channel(16)};
}

namespace {

void plot(Image& image, int x, int y, Color color) {
  if (x >= 0 && y >= 0 && x < image.width && y < image.height) image.at(x, y) = color;
}

}  // namespace

void drawLine(Image& image, Point2 a, Point2 b, Color color) {
  const float length = glm::length(b - a);
  const int steps = std::max(1, int(std::ceil(length * 2.0f)));
  if (!std::isfinite(length) || steps > 1 << 20) return;
  for (int i = 0; i <= steps; ++i) {
    Point2 p = glm::mix(a, b, float(i) / float(steps));
    plot(image, int(std::floor(p.x)), int(std::floor(p.y)), color);
  }
}

void drawDot(Image& image, Point2 center, float radius, Color color) {
  if (!std::isfinite(center.x) || !std::isfinite(center.y)) return;
  const int x0 = int(std::floor(center.x - radius)), x1 = int(std::ceil(center.x + radius));
  const int y0 = int(std::floor(center.y - radius)), y1 = int(std::ceil(center.y + radius));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      Point2 d = Point2(float(x) + 0.5f, float(y) + 0.5f) - center;
      if (glm::dot(d, d) <= radius * radius) plot(image, x, y, color);
    }
}

void drawRectOutline(Image& image, Point2 min, Point2 max, Color color) {
  drawLine(image, min, {max.x, min.y}, color);
  drawLine(image, {max.x, min.y}, max, color);
  drawLine(image, max, {min.x, max.y}, color);
  drawLine(image, {min.x, max.y}, min, color);
}

void fillRect(Image& image, Point2 min, Point2 max, Color color) {
  for (int y = std::max(0, int(min.y)); y < std::min(image.height, int(std::ceil(max.y))); ++y)
    for (int x = std::max(0, int(min.x)); x < std::min(image.width, int(std::ceil(max.x))); ++x)
      image.at(x, y) = color;
}

Image enlarge(const Image& image, int factor) {
  Image out(image.width * factor, image.height * factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) out.at(x, y) = image.at(x / factor, y / factor);
  return out;
}

}  // namespace pathlab
