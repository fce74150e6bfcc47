// A one-line progress bar on stderr: percentage, ETA and samples per second.
// Silent when stderr is not a terminal or when the user asked for quiet.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>

namespace pathlab {

// A rate with a k/M suffix, e.g. "8.45M".
std::string formatRate(double perSecond);

class ProgressBar {
 public:
  ProgressBar(uint64_t totalSamples, bool enabled);
  ~ProgressBar();  // prints the final state and a newline

  void add(uint64_t samples) { done_.fetch_add(samples, std::memory_order_relaxed); }

  static bool stderrIsTerminal();

 private:
  void draw(bool final);

  uint64_t total_;
  bool enabled_;
  std::atomic<uint64_t> done_{0};
  std::atomic<bool> stop_{false};
  std::chrono::steady_clock::time_point start_;
  std::thread thread_;
};

}  // namespace pathlab
