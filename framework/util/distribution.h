// A discrete distribution sampled by inverting its CDF with binary search
// (used to pick a light's triangle in proportion to its area).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace pathlab {

class Distribution1D {
 public:
  Distribution1D() = default;
  // Weights need not be normalised; they must be >= 0 with a positive sum.
  explicit Distribution1D(const std::vector<float>& weights) : cdf_(weights.size() + 1, 0.0) {
    for (size_t i = 0; i < weights.size(); ++i) cdf_[i + 1] = cdf_[i] + double(weights[i]);
    total_ = cdf_.back();
    for (double& c : cdf_) c /= total_;
  }

  size_t size() const { return cdf_.empty() ? 0 : cdf_.size() - 1; }
  double total() const { return total_; }

  // The index i with cdf[i] <= u < cdf[i+1], and u re-scaled to [0, 1)
  // inside that interval so it can be used again.
  size_t sample(float u, float* remapped = nullptr) const {
    size_t i = 0;
    if (size() <= kCountUpTo) {
      // A few entries (a light's triangles): count the CDF steps at or below
      // u, the same index as the search below, with a loop of fixed length
      // instead of a search whose branches are coin flips.
      // (A zero-weight entry's step is counted with the one before it, so it is never chosen.)
      for (size_t k = 1; k < size(); ++k) i += cdf_[k] <= double(u);
    } else {
      auto it = std::upper_bound(cdf_.begin(), cdf_.end(), double(u));
      i = size_t(std::clamp<std::ptrdiff_t>(it - cdf_.begin() - 1, 0, std::ptrdiff_t(size()) - 1));
      while (i + 1 < size() && cdf_[i + 1] == cdf_[i]) ++i;  // skip zero-weight entries
    }
    if (remapped) {
      const double width = cdf_[i + 1] - cdf_[i];
      *remapped = width > 0 ? std::min(float((double(u) - cdf_[i]) / width), 0x1.fffffep-1f) : 0.0f;
    }
    return i;
  }

 private:
  static constexpr size_t kCountUpTo = 16;
  std::vector<double> cdf_;
  double total_ = 0.0;
};

}  // namespace pathlab
