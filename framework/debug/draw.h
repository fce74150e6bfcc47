// Small raster drawing helpers for the debugger views: colour maps, lines,
// dots and rectangles in pixel coordinates, clipped to the image.
#pragma once

#include <cstdint>
#include <string>

#include "core/camera.h"
#include "util/aabb.h"
#include "util/image.h"

namespace pathlab {

// Perceptually ordered colour map (viridis-like) for t in [0, 1].
Color colorMap(float t);

// A stable, well-spread colour for an integer id (primitive ids, materials).
Color idColor(uint32_t id);

void drawLine(Image& image, Point2 a, Point2 b, Color color);
void drawDot(Image& image, Point2 center, float radius, Color color);
void drawRectOutline(Image& image, Point2 min, Point2 max, Color color);
void fillRect(Image& image, Point2 min, Point2 max, Color color);

// Text in a 5x7 pixel font (digits, A-Z, a few symbols; lower case is drawn
// as upper case), each font pixel `scale` image pixels. Returns the width drawn.
int drawText(Image& image, Point2 topLeft, const std::string& text, Color color, int scale = 2);

// Projects world-space points through a pinhole camera to raster
// coordinates; segments behind the camera are clipped.
class CameraProjection {
 public:
  CameraProjection(const Camera& camera, IVec2 resolution);
  void drawSegment(Image& image, Point3 a, Point3 b, Color color) const;
  void drawBox(Image& image, const Aabb& box, Color color) const;
  void drawDot(Image& image, Point3 p, float radius, Color color) const;  // nothing behind the camera

 private:
  Vec3 toCamera(const Point3& p) const;
  Point2 toRaster(const Vec3& c) const;
  Camera camera_;
  Vec3 forward_, right_, up_;
  float halfWidth_, halfHeight_;
  IVec2 resolution_;
};

// Tiles of equal size in a grid, each under a one-line label (views that
// compare several renders side by side).
class TileSheet {
 public:
  TileSheet(int columns, int rows, int tileWidth, int tileHeight);
  // Tile `index` (row by row), cropped to the tile size, with its label.
  void place(const Image& tile, int index, const std::string& label);
  Image& image() { return image_; }

 private:
  int width_, height_, columns_;
  Image image_;
};

// An adaptive render's samples-per-pixel map (task 11) as colours: the
// colour map over log2 of the count from `fewest` (dark) to `most` (bright),
// stored so that a PNG shows exactly those colours.
struct SampleMap;
Image sampleMapImage(const SampleMap& map, uint32_t fewest, uint32_t most);

// Nearest-neighbour enlargement by an integer factor.
Image enlarge(const Image& image, int factor);

}  // namespace pathlab
