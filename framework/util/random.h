// Counter-based random numbers. Every value is a function of
// (seed, pixel, sample index, dimension), so an image does not depend on the
// number of threads or the tile order, and a single pixel can be re-traced
// alone (the debugger does exactly that).
//
// Three sequences. Independent: each value a hash, plain Monte Carlo (error
// falls as 1/sqrt(N)). Stratified: a pixel's N samples split [0,1) (or
// [0,1)^2, an nx x ny grid) into N cells, one jittered sample in each, the
// cells dealt to samples in a different random order in every dimension
// (pbrt-v4's StratifiedSampler, with Kensler's hashed permutation). Sobol: the samples of one pixel, dimension by
// dimension, are points of a randomised low-discrepancy sequence, so they
// cover [0,1)^2 more evenly than random points and the error of a smooth
// integrand falls faster (Burley, "Practical Hash-based Owen Scrambling",
// JCGT 2020: each next2D is the first two Sobol dimensions, Owen-scrambled,
// with the sample order shuffled, by seeds hashed from the pixel and the
// dimension). Code that draws numbers is the same for both.
#pragma once

#include <cstdint>

#include "util/compiler.h"
#include "util/math.h"

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

// x with its 32 bits in the opposite order.
constexpr uint32_t reverseBits(uint32_t x) {
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// A nested uniform (Owen) scramble of a binary fraction stored bit-reversed
// (its first digit in bit 0): each bit is flipped by a hash of the bits below
// it, i.e. of the digits before it. Vegdahl's refinement of Laine and Karras'
// permutation. The fraction itself is reverseBits(result).
inline uint32_t owenScrambleReversed(uint32_t reversed, uint32_t seed) {
  uint32_t x = reversed;
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

// The first two dimensions of the Sobol sequence, bit-reversed (so ready
// for owenScrambleReversed). Dimension 0 is van der Corput: the fraction is
// the index's bits reversed, so reversed it is the index itself. Dimension
// 1 has direction numbers v0 = 1/2, v(k+1) = v(k) xor v(k) / 2: the XOR of
// v(k) over the index's set bits k, looked up a byte at a time.
struct SobolByteTable {
  uint32_t entries[4][256];
};
constexpr SobolByteTable makeSobolDimension1Reversed() {
  uint32_t v[32] = {};
  for (uint32_t k = 0, d = 1u << 31; k < 32; ++k, d ^= d >> 1) v[k] = reverseBits(d);
  SobolByteTable table{};
  for (int byte = 0; byte < 4; ++byte) {
    for (uint32_t bits = 0; bits < 256; ++bits) {
      for (int j = 0; j < 8; ++j) {
        if ((bits >> j) & 1u) table.entries[byte][bits] ^= v[8 * byte + j];
      }
    }
  }
  return table;
}
inline constexpr SobolByteTable kSobolDimension1Reversed = makeSobolDimension1Reversed();

inline uint32_t sobolDimension0Reversed(uint32_t index) { return index; }
inline uint32_t sobolDimension1Reversed(uint32_t index) {
  const auto& t = kSobolDimension1Reversed.entries;
  return t[0][index & 0xffu] ^ t[1][(index >> 8) & 0xffu] ^ t[2][(index >> 16) & 0xffu] ^ t[3][index >> 24];
}

// Element i of a random permutation of 0 .. n-1 chosen by `seed`, without
// storing it: Kensler's hash, re-applied until it lands below n ("Correlated
// Multi-Jittered Sampling", Pixar 2013, as in pbrt-v4).
inline uint32_t permutationElement(uint32_t i, uint32_t n, uint32_t seed) {
  uint32_t w = n - 1;
  w |= w >> 1, w |= w >> 2, w |= w >> 4, w |= w >> 8, w |= w >> 16;
  do {
    i ^= seed, i *= 0xe170893du, i ^= seed >> 16, i ^= (i & w) >> 4, i ^= seed >> 8, i *= 0x0929eb3fu;
    i ^= seed >> 23, i ^= (i & w) >> 1, i *= 1u | seed >> 27, i *= 0x6935fa69u, i ^= (i & w) >> 11;
    i *= 0x74dcb303u, i ^= (i & w) >> 2, i *= 0x9e501cc3u, i ^= (i & w) >> 2, i *= 0xc860a3dfu;
    i &= w, i ^= i >> 5;
  } while (i >= n);
  return (i + seed) % n;
}

// The 2D strata of n samples: an nx x ny grid with nx the largest divisor of
// n not above sqrt(n) (n = 16: 4 x 4; n = 8: 2 x 4; a prime n: 1 x n).
inline uint32_t strataColumns(uint32_t n) {
  uint32_t columns = 1;
  for (uint32_t c = 1; c * c <= n; ++c) {
    if (n % c == 0) columns = c;
  }
  return columns;
}

enum class SampleSequence { Independent, Stratified, Sobol };

class Sampler {
 public:
  // pixelIndex = y * width + x. Different seeds give independent images.
  // Stratified needs the pixel's sample count; a sample at or past it (a
  // render that goes on) is drawn independently.
  Sampler(uint32_t pixelIndex, uint32_t sampleIndex, uint64_t seed,
          SampleSequence sequence = SampleSequence::Independent, uint32_t sampleCount = 0)
      : key_(sequence == SampleSequence::Sobol ||
                     (sequence == SampleSequence::Stratified && sampleIndex < sampleCount)
                 ? mix64(mix64(seed + 0x632be59bd9b4e019ULL) ^ pixelIndex)  // the same for every sample
                 : mix64(mix64(seed + 0x9e3779b97f4a7c15ULL) ^ ((uint64_t(pixelIndex) << 32) | sampleIndex))),
        reversedSampleIndex_(reverseBits(sampleIndex)),
        sampleIndex_(sampleIndex),
        sampleCount_(sampleCount),
        sequence_(sequence == SampleSequence::Stratified && sampleIndex >= sampleCount ? SampleSequence::Independent
                                                                                      : sequence) {}

  // Uniform in [0, 1): 24 bits, so the result is never 1.0f.
  float next1D() {
    const uint64_t bits = mix64(key_ + 0x9e3779b97f4a7c15ULL * ++dimension_);
    if (sequence_ == SampleSequence::Sobol) [[likely]] {
      return toUnit(owenScrambleReversed(sobolDimension0Reversed(shuffledIndex(bits)), uint32_t(bits >> 32)));
    }
    if (sequence_ == SampleSequence::Independent) return float(bits >> 40) * 0x1.0p-24f;
    return jittered(permutationElement(sampleIndex_, sampleCount_, uint32_t(bits)), sampleCount_, bits);
  }

  Vec2 next2D() {
    if (sequence_ == SampleSequence::Sobol) [[likely]] {
      const uint64_t bits = mix64(key_ + 0x9e3779b97f4a7c15ULL * ++dimension_);
      const uint32_t index = shuffledIndex(bits);
      return {toUnit(owenScrambleReversed(sobolDimension0Reversed(index), uint32_t(bits >> 32))),
              toUnit(owenScrambleReversed(sobolDimension1Reversed(index), uint32_t(mix64(bits))))};
    }
    if (sequence_ == SampleSequence::Independent) {
      const float u = next1D();
      return {u, next1D()};
    }
    return nextStratified2D();
  }

 private:
  // One jittered point in each cell of an nx x ny grid, the cells dealt to
  // the samples in an order of this dimension's own. Out of line: not the
  // default, and kept out of the Sobol path's inlined code.
  PATHLAB_NOINLINE Vec2 nextStratified2D() {
    const uint64_t bits = mix64(key_ + 0x9e3779b97f4a7c15ULL * ++dimension_);
    const uint32_t columns = strataColumns(sampleCount_), rows = sampleCount_ / columns;
    const uint32_t stratum = permutationElement(sampleIndex_, sampleCount_, uint32_t(bits));
    return {jittered(stratum % columns, columns, bits), jittered(stratum / columns, rows, mix64(bits))};
  }
  // A uniform point in cell `cell` of n equal cells of [0, 1): the jitter is
  // a hash of the sample and the dimension's bits. Never 1.0f (rounded down).
  float jittered(uint32_t cell, uint32_t n, uint64_t bits) const {
    const double jitter = double(mix64(bits ^ (uint64_t(sampleIndex_) << 32)) >> 11) * 0x1.0p-53;
    const float u = float((double(cell) + jitter) / double(n));
    return u < 1.0f ? u : 0x1.fffffep-1f;
  }
  // A scrambled fraction, stored bit-reversed, as a float in [0, 1).
  static float toUnit(uint32_t reversed) { return float(reverseBits(reversed) >> 8) * 0x1.0p-24f; }
  // The pixel's samples in a random order (the index Owen-scrambled as a
  // fraction) that keeps every power-of-two prefix an aligned block of the
  // sequence, so still evenly spread.
  uint32_t shuffledIndex(uint64_t bits) const {
    return reverseBits(owenScrambleReversed(reversedSampleIndex_, uint32_t(bits)));
  }

  uint64_t key_;
  uint32_t reversedSampleIndex_;
  uint32_t sampleIndex_, sampleCount_;
  uint32_t dimension_ = 0;
  SampleSequence sequence_;
};

}  // namespace pathlab
