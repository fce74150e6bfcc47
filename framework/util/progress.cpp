#include "util/progress.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "util/platform.h"

namespace pathlab {

std::string formatRate(double perSecond) {
  char buffer[32];
  if (perSecond >= 1e6) std::snprintf(buffer, sizeof buffer, "%.2fM", perSecond / 1e6);
  else if (perSecond >= 1e3) std::snprintf(buffer, sizeof buffer, "%.1fk", perSecond / 1e3);
  else std::snprintf(buffer, sizeof buffer, "%.0f", perSecond);
  return buffer;
}

bool ProgressBar::stderrIsTerminal() { return pathlab::stderrIsTerminal(); }

ProgressBar::ProgressBar(uint64_t totalSamples, bool enabled)
    : total_(std::max<uint64_t>(1, totalSamples)),
      enabled_(enabled && stderrIsTerminal()),
      start_(std::chrono::steady_clock::now()) {
  if (!enabled_) return;
  thread_ = std::thread([this] {
    while (!stop_.load()) {
      draw(false);
      for (int i = 0; i < 20 && !stop_.load(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });
}

ProgressBar::~ProgressBar() {
  if (!enabled_) return;
  stop_ = true;
  thread_.join();
  draw(true);
  std::fputc('\n', stderr);
}

void ProgressBar::draw(bool final) {
  const uint64_t done = std::min(done_.load(), total_);
  const double fraction = double(done) / double(total_);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0.0 ? double(done) / elapsed : 0.0;
  constexpr int kWidth = 30;
  const int filled = int(fraction * kWidth);
  char bar[kWidth + 1];
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '=' : (i == filled ? '>' : ' ');
  bar[kWidth] = '\0';
  if (final) {
    std::fprintf(stderr, "\r[%s] %5.1f%%  %.1fs  %s samples/s   ", bar, 100.0 * fraction, elapsed,
                 formatRate(rate).c_str());
  } else {
    const double eta = rate > 0.0 ? double(total_ - done) / rate : 0.0;
    std::fprintf(stderr, "\r[%s] %5.1f%%  ETA %.0fs  %s samples/s   ", bar, 100.0 * fraction, eta,
                 formatRate(rate).c_str());
  }
  std::fflush(stderr);
}

}  // namespace pathlab
