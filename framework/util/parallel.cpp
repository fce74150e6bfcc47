#include "util/parallel.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "util/platform.h"

namespace pathlab {

int defaultThreadCount() { return std::max(1u, std::thread::hardware_concurrency()); }

void forEachTile(int width, int height, int tileSize, int threads,
                 const std::function<void(const Tile&)>& body, const std::atomic<bool>* cancel) {
  tileSize = std::max(1, tileSize);
  const int tilesX = (width + tileSize - 1) / tileSize;
  const int tilesY = (height + tileSize - 1) / tileSize;
  const int tileCount = tilesX * tilesY;
  if (tileCount == 0) return;
  threads = std::clamp(threads <= 0 ? defaultThreadCount() : threads, 1, tileCount);

  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto worker = [&] {
    try {
      for (int t = next++; t < tileCount; t = next++) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return;
        Tile tile;
        tile.begin = {(t % tilesX) * tileSize, (t / tilesX) * tileSize};
        tile.end = {std::min(tile.begin.x + tileSize, width), std::min(tile.begin.y + tileSize, height)};
        body(tile);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure) failure = std::current_exception();
      next = tileCount;  // stop the other workers soon
    }
  };
  if (threads == 1) {
    worker();
  } else {
    // Workers start with Ctrl-C kept from them, so it reaches the calling
    // thread, which only waits: its handler runs at once.
    std::vector<std::thread> pool;
    withStopSignalsBlockedInNewThreads([&] {
      for (int i = 0; i < threads; ++i) pool.emplace_back(worker);
    });
    for (std::thread& thread : pool) thread.join();
  }
  if (failure) std::rethrow_exception(failure);
}

void forEachPixel(int width, int height, int threads, const std::function<void(int x, int y)>& body) {
  forEachTile(width, height, 16, threads, [&](const Tile& tile) {
    for (int y = tile.begin.y; y < tile.end.y; ++y)
      for (int x = tile.begin.x; x < tile.end.x; ++x) body(x, y);
  });
}

}  // namespace pathlab
