// Small raster drawing helpers for the debugger views: colour maps, lines,
// dots and rectangles in pixel coordinates, clipped to the image.
#pragma once

#include <cstdint>

#include "pathlab/image.h"

namespace pathlab {

// Perceptually ordered colour map (viridis-like) for t in [0, 1].
Color colorMap(float t);

// A stable, well-spread colour for an integer id (primitive ids, materials).
Color idColor(uint32_t id);

void drawLine(Image& image, Point2 a, Point2 b, Color color);
void drawDot(Image& image, Point2 center, float radius, Color color);
void drawRectOutline(Image& image, Point2 min, Point2 max, Color color);
void fillRect(Image& image, Point2 min, Point2 max, Color color);

// Nearest-neighbour enlargement by an integer factor.
Image enlarge(const Image& image, int factor);

}  // namespace pathlab
