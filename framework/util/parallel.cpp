#include "util/parallel.h"

#include <pthread.h>

#include <algorithm>
#include <csignal>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

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
    // Workers start with SIGINT and SIGTERM blocked, so Ctrl-C reaches the
    // calling thread, which only waits: its handler runs at once (under
    // ThreadSanitizer too, which defers a signal that lands in a thread busy
    // computing until that thread calls into the C library).
    sigset_t stop, previous;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop, &previous);
    std::vector<std::thread> pool;
    for (int i = 0; i < threads; ++i) pool.emplace_back(worker);
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
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
