#include "debug/draw.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "render/render.h"
#include "util/random.h"

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
  // Clip to the image (Liang–Barsky) so far-off endpoints cost nothing.
  float t0 = 0.0f, t1 = 1.0f;
  const Vec2 d = b - a;
  const float p[4] = {-d.x, d.x, -d.y, d.y};
  const float q[4] = {a.x, float(image.width) - a.x, a.y, float(image.height) - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0f) {
      if (q[i] < 0.0f) return;
      continue;
    }
    const float r = q[i] / p[i];
    if (p[i] < 0.0f) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
  }
  if (!(t0 <= t1)) return;
  b = a + t1 * d;
  a = a + t0 * d;
  const float length = glm::length(b - a);
  const int steps = std::max(1, int(std::ceil(length * 2.0f)));
  if (!std::isfinite(length) || steps > 1 << 20) return;
  for (int i = 0; i <= steps; ++i) {
    Point2 point = glm::mix(a, b, float(i) / float(steps));
    plot(image, int(std::floor(point.x)), int(std::floor(point.y)), color);
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

namespace {
constexpr int kLabelHeight = 20;
}

TileSheet::TileSheet(int columns, int rows, int tileWidth, int tileHeight)
    : width_(tileWidth), height_(tileHeight), columns_(columns),
      image_(columns * tileWidth, rows * (tileHeight + kLabelHeight), Color(0.02f)) {}

void TileSheet::place(const Image& tile, int index, const std::string& label) {
  const int x0 = (index % columns_) * width_, y0 = (index / columns_) * (height_ + kLabelHeight);
  for (int y = 0; y < std::min(height_, tile.height); ++y)
    for (int x = 0; x < std::min(width_, tile.width); ++x) image_.at(x0 + x, y0 + kLabelHeight + y) = tile.at(x, y);
  const int scale = 8 + 12 * int(label.size()) <= width_ ? 2 : 1;  // 6 pixels a letter at scale 1: fit the tile
  drawText(image_, Point2(float(x0 + 4), float(y0 + 4)), label, Color(0.9f), scale);
}

Image sampleMapImage(const SampleMap& map, uint32_t fewest, uint32_t most) {
  Image image(map.width, map.height);
  const float lo = std::log2(float(std::max(1u, fewest))), hi = std::log2(float(std::max(fewest + 1, most)));
  for (size_t i = 0; i < map.samples.size() && i < image.pixels.size(); ++i) {
    const float t = (std::log2(float(std::max(1u, map.samples[i]))) - lo) / (hi - lo);
    const Color display = colorMap(std::clamp(t, 0.0f, 1.0f));
    image.pixels[i] = {srgbToLinear(display.x), srgbToLinear(display.y), srgbToLinear(display.z)};
  }
  return image;
}

Image enlarge(const Image& image, int factor) {
  Image out(image.width * factor, image.height * factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) out.at(x, y) = image.at(x / factor, y / factor);
  return out;
}

}  // namespace pathlab

namespace pathlab {
namespace {

// 5x7 glyphs, one byte per row, bit 4 = leftmost column.
struct Glyph {
  char c;
  uint8_t rows[7];
};
constexpr Glyph kFont[] = {
    {'0', {14, 17, 19, 21, 25, 17, 14}}, {'1', {4, 12, 4, 4, 4, 4, 14}},     {'2', {14, 17, 1, 2, 4, 8, 31}},
    {'3', {30, 1, 1, 14, 1, 1, 30}},     {'4', {2, 6, 10, 18, 31, 2, 2}},    {'5', {31, 16, 30, 1, 1, 17, 14}},
    {'6', {6, 8, 16, 30, 17, 17, 14}},   {'7', {31, 1, 2, 4, 8, 8, 8}},      {'8', {14, 17, 17, 14, 17, 17, 14}},
    {'9', {14, 17, 17, 15, 1, 2, 12}},   {'A', {14, 17, 17, 31, 17, 17, 17}}, {'B', {30, 17, 17, 30, 17, 17, 30}},
    {'C', {14, 17, 16, 16, 16, 17, 14}}, {'D', {30, 17, 17, 17, 17, 17, 30}}, {'E', {31, 16, 16, 30, 16, 16, 31}},
    {'F', {31, 16, 16, 30, 16, 16, 16}}, {'G', {14, 17, 16, 23, 17, 17, 15}}, {'H', {17, 17, 17, 31, 17, 17, 17}},
    {'I', {14, 4, 4, 4, 4, 4, 14}},      {'J', {7, 2, 2, 2, 2, 18, 12}},     {'K', {17, 18, 20, 24, 20, 18, 17}},
    {'L', {16, 16, 16, 16, 16, 16, 31}}, {'M', {17, 27, 21, 21, 17, 17, 17}}, {'N', {17, 17, 25, 21, 19, 17, 17}},
    {'O', {14, 17, 17, 17, 17, 17, 14}}, {'P', {30, 17, 17, 30, 16, 16, 16}}, {'Q', {14, 17, 17, 17, 21, 18, 13}},
    {'R', {30, 17, 17, 30, 20, 18, 17}}, {'S', {15, 16, 16, 14, 1, 1, 30}},   {'T', {31, 4, 4, 4, 4, 4, 4}},
    {'U', {17, 17, 17, 17, 17, 17, 14}}, {'V', {17, 17, 17, 17, 17, 10, 4}},  {'W', {17, 17, 17, 21, 21, 21, 10}},
    {'X', {17, 17, 10, 4, 10, 17, 17}},  {'Y', {17, 17, 10, 4, 4, 4, 4}},     {'Z', {31, 1, 2, 4, 8, 16, 31}},
    {'.', {0, 0, 0, 0, 0, 12, 12}},      {',', {0, 0, 0, 0, 12, 4, 8}},      {':', {0, 12, 12, 0, 12, 12, 0}},
    {'-', {0, 0, 0, 31, 0, 0, 0}},       {'+', {0, 4, 4, 31, 4, 4, 0}},      {'=', {0, 0, 31, 0, 31, 0, 0}},
    {'/', {1, 1, 2, 4, 8, 16, 16}},      {'(', {2, 4, 8, 8, 8, 4, 2}},       {')', {8, 4, 2, 2, 2, 4, 8}},
    {'%', {24, 25, 2, 4, 8, 19, 3}},     {'<', {2, 4, 8, 16, 8, 4, 2}},      {'>', {8, 4, 2, 1, 2, 4, 8}},
};

}  // namespace

int drawText(Image& image, Point2 topLeft, const std::string& text, Color color, int scale) {
  int x = int(topLeft.x);
  const int y = int(topLeft.y);
  for (char raw : text) {
    const char c = char(std::toupper(static_cast<unsigned char>(raw)));
    for (const Glyph& glyph : kFont) {
      if (glyph.c != c) continue;
      for (int row = 0; row < 7; ++row)
        for (int col = 0; col < 5; ++col)
          if (glyph.rows[row] & (16 >> col)) {
            fillRect(image, Point2(float(x + col * scale), float(y + row * scale)),
                     Point2(float(x + (col + 1) * scale), float(y + (row + 1) * scale)), color);
          }
    }
    x += 6 * scale;  // unknown characters (and spaces) leave a gap
  }
  return x - int(topLeft.x);
}

CameraProjection::CameraProjection(const Camera& camera, IVec2 resolution) : camera_(camera), resolution_(resolution) {
  // The framework's own frame (not task 1's), so drawings stay right even
  // when task 1 is undone.
  forward_ = glm::normalize(camera.lookAt - camera.position);
  Vec3 right = glm::cross(forward_, camera.up);
  if (glm::length(right) < 1e-4f) right = glm::cross(forward_, std::abs(forward_.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
  right_ = glm::normalize(right);
  up_ = glm::cross(right_, forward_);
  halfHeight_ = std::tan(glm::radians(camera.vfovDegrees) * 0.5f);
  halfWidth_ = halfHeight_ * float(resolution.x) / float(resolution.y);
}

Vec3 CameraProjection::toCamera(const Point3& p) const {
  Vec3 d = p - camera_.position;
  return {glm::dot(d, right_), glm::dot(d, up_), glm::dot(d, forward_)};
}

Point2 CameraProjection::toRaster(const Vec3& c) const {
  return {(c.x / (c.z * halfWidth_) + 1.0f) * 0.5f * float(resolution_.x),
          (1.0f - c.y / (c.z * halfHeight_)) * 0.5f * float(resolution_.y)};
}

void CameraProjection::drawSegment(Image& image, Point3 a, Point3 b, Color color) const {
  Vec3 ca = toCamera(a), cb = toCamera(b);
  constexpr float kNear = 1e-4f;
  if (ca.z < kNear && cb.z < kNear) return;
  // Clip the part behind the camera.
  if (ca.z < kNear) ca = glm::mix(ca, cb, (kNear - ca.z) / (cb.z - ca.z));
  if (cb.z < kNear) cb = glm::mix(cb, ca, (kNear - cb.z) / (ca.z - cb.z));
  drawLine(image, toRaster(ca), toRaster(cb), color);
}

void CameraProjection::drawDot(Image& image, Point3 p, float radius, Color color) const {
  const Vec3 c = toCamera(p);
  if (c.z > 1e-4f) pathlab::drawDot(image, toRaster(c), radius, color);
}

void CameraProjection::drawBox(Image& image, const Aabb& box, Color color) const {
  auto corner = [&](int i) {
    return Point3((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z);
  };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) drawSegment(image, corner(i), corner(i | bit), color);
}

}  // namespace pathlab
