// Counter-based random numbers. Every value is a hash of
// (seed, pixel, sample index, dimension), so an image does not depend on the
// number of threads or the tile order, and a single pixel can be re-traced
// alone (the debugger does exactly that).
#pragma once

#include <cstdint>

#include "pathlab/math.h"

namespace pathlab {

// SplitMix64's finaliser: a bijective 64-bit mix with full avalanche.
inline uint64_t mix64(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

class Sampler {
 public:
  // pixelIndex = y * width + x. Different seeds give independent images.
  Sampler(uint32_t pixelIndex, uint32_t sampleIndex, uint64_t seed)
      : key_(mix64(mix64(seed + 0x9e3779b97f4a7c15ULL) ^
                   ((uint64_t(pixelIndex) << 32) | sampleIndex))) {}

  // Uniform in [0, 1): 24 random bits, so the result is never 1.0f.
  float next1D() {
    uint64_t bits = mix64(key_ + 0x9e3779b97f4a7c15ULL * ++dimension_);
    return float(bits >> 40) * 0x1.0p-24f;
  }

  Vec2 next2D() {
    float u = next1D();
    return {u, next1D()};
  }


 private:
  uint64_t key_;
  uint32_t dimension_ = 0;
};

}  // namespace pathlab
