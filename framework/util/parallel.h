// Tiled parallel loops over an image. Tiles are handed out through an atomic
// counter; each pixel is computed by one thread only, so results never
// depend on the thread count.
#pragma once

#include <atomic>
#include <functional>

#include "util/math.h"

namespace pathlab {

int defaultThreadCount();

struct Tile {
  IVec2 begin;  // inclusive
  IVec2 end;    // exclusive
};

// Calls body(tile) for every tile of a width x height image on `threads`
// threads. Stops handing out tiles once `cancel` (if given) becomes true.
void forEachTile(int width, int height, int tileSize, int threads,
                 const std::function<void(const Tile&)>& body,
                 const std::atomic<bool>* cancel = nullptr);

// Convenience: body(x, y) for every pixel.
void forEachPixel(int width, int height, int threads,
                  const std::function<void(int x, int y)>& body);

}  // namespace pathlab
