#include "image_test.h"

#include "suite/doctest_strings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <sstream>

#include "image_calls.h"
#include "statistics.h"
#include "check.h"
#include "failure_pictures.h"
#include "util/error.h"
#include "util/image.h"

namespace pathlab::test {
namespace {

constexpr int kBlock = 4;  // pixels per block side
// Deterministic pixels (no variance in either image) may still differ by
// float rounding between correct methods: this much is never significant.
constexpr double kRelativeFloor = 1e-4, kAbsoluteFloor = 1e-6;
// Noise must never buy a pass: every variance of the candidate's that a
// comparison uses is capped by the judge, from the reference's own (each
// pixel's pixelNoiseBase: the reference's variance there at the candidate's
// samples per pixel, at least its image-wide mean), and a render noisier than
// a correct one fails. Yet a correct render's rare large sample (a firefly)
// must not fail it either. So, per channel:
// - the median over pixels of the render's variance over its base says how
//   noisy the render is where it is typical; above kImageNoiseFactor every
//   pixel's variance is scaled down so that the median is kImageNoiseFactor
//   (noise on every sample, +1e10 and -1e10 in turn, moves a median; a
//   firefly does not). Correct renders: medians of 0.3 to 4;
// - a block's (and the whole image's) variance is capped the same way, at
//   kImageNoiseFactor times its pixels' bases together;
// - a pixel over kPixelNoiseCap times its base is a firefly or a lie: it is
//   left out of its block and the whole image (one pixel's variance would
//   widen its block's tolerance until any mean passed: a black render with a
//   huge variance in one pixel of every block passed every image test) and
//   judged alone by its own variance, and an image may hold at most
//   noisyPixelsAllowed() of them: correct renders show up to 3 (over 200
//   seeds of the reference and 30 of each alternate: docs/test-power.md), so
//   noise can hide at most that many pixels of a wrong render.
// A per-pixel cap that failed every pixel over it was tried first: one
// firefly in a pixel the reference rendered quiet (or never lit) failed
// correct renders (5 of 1900 reference renders, 2 of 60 of an alternate).
constexpr double kImageNoiseFactor = 16;
constexpr double kPixelNoiseCap = 64;
int noisyPixelsAllowed(size_t pixels) { return std::max(8, int(pixels / 256)); }

// z such that P(|Z| > z) = p for a standard normal Z.
double twoSidedQuantile(double p) {
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::string referencePath(const ImageCase& c, const char* suffix) { return referenceImagePath(c.suite, c.name, suffix); }

// z()'s rounding floor from the reference's value alone, where noise is
// measured: a huge mean of yours must not raise the floor its own noise is
// measured against.
double noiseFloor(double reference) { return kRelativeFloor * std::abs(reference) + kAbsoluteFloor; }

// One block (or the whole image) of one channel in both images.
struct Comparison {
  int pixels = 0;  // in the region, excused pixels left out
  double yours = 0, yoursVariance = 0, reference = 0, referenceVariance = 0;
  // The candidate's own variance of the mean, and the reference's scaled to
  // the candidate's samples per pixel: how much noisier the candidate is.
  double yoursOwnVariance = 0, referenceAtYourSpp = 0;
  double noiseRatio() const {
    const double floor = noiseFloor(reference);
    return yoursOwnVariance / std::max(referenceAtYourSpp, floor * floor);
  }
  double z() const {
    const double floor = kRelativeFloor * std::max(std::abs(yours), std::abs(reference)) + kAbsoluteFloor;
    return (yours - reference) / std::sqrt(yoursVariance + referenceVariance + floor * floor);
  }
};

// The reference's variance of a pixel's mean at the candidate's samples per
// pixel, averaged over the image (one channel).
double typicalVariance(const PixelMoments& reference, int channel) {
  double sum = 0;
  for (const Color& v : reference.varianceOfMean) sum += double(v[channel]);
  return reference.varianceOfMean.empty() ? 0.0 : sum / double(reference.varianceOfMean.size()) * kReferenceSppFactor;
}

// What a correct render's variance of pixel i's mean is measured against:
// the reference's there at the candidate's samples per pixel, or the
// reference's image-wide mean where larger, or the rounding floor.
double pixelNoiseBase(const PixelMoments& reference, size_t i, int channel, double typical) {
  const double referenceAtSpp = double(reference.varianceOfMean[i][channel]) * kReferenceSppFactor;
  const double floor = noiseFloor(reference.mean[i][channel]);
  return std::max({referenceAtSpp, typical, floor * floor});
}

// The render's median noise ratio in one channel (the comment on
// kImageNoiseFactor): own variance over pixelNoiseBase.
double medianNoiseRatio(const PixelMoments& yours, const PixelMoments& reference, int channel) {
  const size_t pixels = reference.varianceOfMean.size();
  if (pixels == 0) return 0.0;
  const double typical = typicalVariance(reference, channel);
  std::vector<double> ratios(pixels);
  for (size_t i = 0; i < pixels; ++i) {
    ratios[i] = double(yours.varianceOfMean[i][channel]) / pixelNoiseBase(reference, i, channel, typical);
  }
  std::nth_element(ratios.begin(), ratios.begin() + pixels / 2, ratios.end());
  return ratios[pixels / 2];
}

// The pixels of one region (a block or the whole image) of one channel in
// both images, the candidate's variance capped (the comment on
// kImageNoiseFactor): `scale` is the channel's median cap, `excused` the
// pixels judged alone.
Comparison compareRegion(const PixelMoments& yours, const PixelMoments& reference, int x0, int y0, int x1, int y1,
                         int channel, double scale, double typical, const std::vector<uint8_t>& excused) {
  Comparison c;
  double n = 0, own = 0, base = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const size_t i = size_t(y) * size_t(yours.width) + size_t(x);
      if (excused[i]) continue;
      own += double(yours.varianceOfMean[i][channel]) * scale;
      base += pixelNoiseBase(reference, i, channel, typical);
    }
  }
  const double regionScale = own > kImageNoiseFactor * base ? kImageNoiseFactor * base / own : 1.0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const size_t i = size_t(y) * size_t(yours.width) + size_t(x);
      if (excused[i]) continue;
      c.yours += yours.mean[i][channel];
      // A render's own variance misses what its few samples never drew (a
      // caustic, a firefly): the reference's, from 16x the samples, is the
      // floor of what a correct render's variance can be.
      const double mine = yours.varianceOfMean[i][channel];
      const double referenceAtSpp = double(reference.varianceOfMean[i][channel]) * kReferenceSppFactor;
      c.yoursVariance += std::max(referenceAtSpp, mine * scale * regionScale);
      c.yoursOwnVariance += mine;
      c.referenceAtYourSpp += referenceAtSpp;
      c.reference += reference.mean[i][channel];
      c.referenceVariance += reference.varianceOfMean[i][channel];
      ++n;
    }
  }
  c.pixels = int(n);
  if (n == 0) return c;
  c.yours /= n;
  c.reference /= n;
  c.yoursVariance /= n * n;
  c.referenceVariance /= n * n;
  return c;
}

// One pixel judged alone, by its own variance (an excused pixel).
Comparison comparePixel(const PixelMoments& yours, const PixelMoments& reference, size_t i, int channel) {
  Comparison c;
  c.pixels = 1;
  c.yours = yours.mean[i][channel];
  c.yoursVariance = c.yoursOwnVariance = yours.varianceOfMean[i][channel];
  c.reference = reference.mean[i][channel];
  c.referenceVariance = reference.varianceOfMean[i][channel];
  c.referenceAtYourSpp = c.referenceVariance * kReferenceSppFactor;
  return c;
}

// A pixel noisier than a correct render's can be (over kPixelNoiseCap times its base, after the median's cap).
struct NoisyPixel {
  int x = 0, y = 0, channel = 0;
  double ratio = 0;
};

struct Verdict {
  double limit = 0;          // |z| above this fails
  double worstZ = 0;         // the block with the largest |z|
  Comparison worst;
  int worstX = 0, worstY = 0, worstChannel = 0;
  Comparison whole[3];       // the whole image, per channel
  std::vector<float> blockZ;  // per block, the channel with the largest |z| (signed)
  double worstBlockNoise = 0;  // the largest noiseRatio() of any block and channel
  double medianNoise[3] = {0, 0, 0};  // per channel: medianNoiseRatio()
  std::vector<NoisyPixel> noisy;      // the excused pixels (the channel over the cap the most)
  int noisyAllowed = 0;               // noisyPixelsAllowed(): more fails the image
  double noise() const { return std::max({medianNoise[0], medianNoise[1], medianNoise[2]}); }
  bool tooNoisy() const { return int(noisy.size()) > noisyAllowed; }
  bool pass() const {
    return !tooNoisy() && std::abs(worstZ) <= limit && std::abs(whole[0].z()) <= limit &&
           std::abs(whole[1].z()) <= limit && std::abs(whole[2].z()) <= limit;
  }
};

Verdict compare(const PixelMoments& yours, const PixelMoments& reference) {
  Verdict v;
  const int blocksX = (yours.width + kBlock - 1) / kBlock, blocksY = (yours.height + kBlock - 1) / kBlock;
  double scale[3], typical[3];
  for (int channel = 0; channel < 3; ++channel) {
    typical[channel] = typicalVariance(reference, channel);
    v.medianNoise[channel] = medianNoiseRatio(yours, reference, channel);
    scale[channel] = v.medianNoise[channel] > kImageNoiseFactor ? kImageNoiseFactor / v.medianNoise[channel] : 1.0;
  }
  // The pixels over the cap: judged alone, and at most noisyPixelsAllowed() of them.
  std::vector<uint8_t> excused(yours.mean.size(), 0);
  for (size_t i = 0; i < excused.size(); ++i) {
    NoisyPixel worst{int(i % size_t(yours.width)), int(i / size_t(yours.width)), 0, 0.0};
    for (int channel = 0; channel < 3; ++channel) {
      const double ratio = double(yours.varianceOfMean[i][channel]) * scale[channel] /
                           pixelNoiseBase(reference, i, channel, typical[channel]);
      if (ratio > worst.ratio) worst.channel = channel, worst.ratio = ratio;
    }
    if (worst.ratio > kPixelNoiseCap) {
      excused[i] = 1;
      v.noisy.push_back(worst);
    }
  }
  v.noisyAllowed = noisyPixelsAllowed(excused.size());
  const int tests = 3 * (blocksX * blocksY + 1 + int(v.noisy.size()));
  v.limit = twoSidedQuantile(kImageFalseFailure / tests);
  v.blockZ.assign(size_t(blocksX) * size_t(blocksY), 0.0f);
  const auto consider = [&](const Comparison& c, int x, int y, int channel, float& mark) {
    const double z = c.z();
    if (std::abs(z) > std::abs(mark)) mark = float(z);
    if (std::abs(z) > std::abs(v.worstZ)) {
      v.worstZ = z;
      v.worst = c;
      v.worstX = x;
      v.worstY = y;
      v.worstChannel = channel;
    }
  };
  for (int by = 0; by < blocksY; ++by) {
    for (int bx = 0; bx < blocksX; ++bx) {
      float& mark = v.blockZ[size_t(by) * size_t(blocksX) + size_t(bx)];
      for (int channel = 0; channel < 3; ++channel) {
        const Comparison c = compareRegion(yours, reference, bx * kBlock, by * kBlock,
                                           std::min(yours.width, (bx + 1) * kBlock),
                                           std::min(yours.height, (by + 1) * kBlock), channel, scale[channel],
                                           typical[channel], excused);
        if (c.pixels == 0) continue;
        v.worstBlockNoise = std::max(v.worstBlockNoise, c.noiseRatio());
        consider(c, bx * kBlock, by * kBlock, channel, mark);
      }
    }
  }
  for (const NoisyPixel& p : v.noisy) {
    float& mark = v.blockZ[size_t(p.y / kBlock) * size_t(blocksX) + size_t(p.x / kBlock)];
    for (int channel = 0; channel < 3; ++channel) {
      consider(comparePixel(yours, reference, size_t(p.y) * size_t(yours.width) + size_t(p.x), channel), p.x, p.y,
               channel, mark);
    }
  }
  for (int channel = 0; channel < 3; ++channel) {
    v.whole[channel] = compareRegion(yours, reference, 0, 0, yours.width, yours.height, channel, scale[channel],
                                     typical[channel], excused);
  }
  return v;
}

Image meanImage(const PixelMoments& m) {
  Image image(m.width, m.height);
  image.pixels = m.mean;
  return image;
}

Image varianceImage(const PixelMoments& m) {
  Image image(m.width, m.height);
  image.pixels = m.varianceOfMean;
  return image;
}

// Nearest-neighbour enlargement: the test images are small.
// Both images with one exposure: the reference's 90th percentile maps to 0.8
// (lights and the sun saturate, the rest stays readable).
float exposureOf(const Image& reference) {
  std::vector<float> values;
  for (const Color& c : reference.pixels) values.push_back(maxComponent(c));
  if (values.empty()) return 1.0f;
  std::nth_element(values.begin(), values.begin() + values.size() * 9 / 10, values.end());
  const float p90 = values[values.size() * 9 / 10];
  return p90 > 0.0f && std::isfinite(p90) ? 0.8f / p90 : 1.0f;
}

// Red where yours is brighter, blue where darker. Within noise (|z| up to
// the limit) the colour rises as (|z| / limit)^2 to 40 %, so the usual
// |z| of 1 or 2 stays near black; past the limit it is full.
Image zScoreMap(const Verdict& v, int width, int height) {
  Image map(width, height);
  const int blocksX = (width + kBlock - 1) / kBlock;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float z = v.blockZ[size_t(y / kBlock) * size_t(blocksX) + size_t(x / kBlock)];
      const float ratio = std::abs(z) / float(v.limit);
      const float strength = ratio > 1.0f ? 1.0f : 0.4f * ratio * ratio;
      map.at(x, y) = z > 0 ? Color(strength, 0.0f, 0.0f) : Color(0.0f, 0.0f, strength);
    }
  }
  return map;
}

std::string writeFailureImages(const ImageCase& c, const PixelMoments& yours, const PixelMoments& reference,
                               const Verdict& v) {
  const std::string stem = (std::filesystem::path(failurePicturesDir()) / (c.suite + "-" + c.name)).string();
  const Image referenceImage = meanImage(reference);
  const float exposure = exposureOf(referenceImage);
  auto exposed = [&](Image image) {
    for (Color& p : image.pixels) p *= exposure;
    return enlarged(image, 4);
  };
  try {
    writeImage(exposed(meanImage(yours)), stem + "-yours.png");
    writeImage(exposed(referenceImage), stem + "-reference.png");
    writeImage(enlarged(zScoreMap(v, yours.width, yours.height), 4), stem + "-z.png");
  } catch (const Error& e) {
    return std::string("(could not write the pictures: ") + e.what() + ")";
  }
  return "pictures: " + stem + "-yours.png, " + stem + "-reference.png, " + stem +
         "-z.png (red: yours brighter, blue: darker; black to dim: within noise, full colour: past the limit)";
}

std::string describe(const Comparison& c) {
  std::ostringstream s;
  s.precision(4);
  s << "yours " << c.yours << " (± " << std::sqrt(c.yoursVariance) << "), reference " << c.reference << " (± "
    << std::sqrt(c.referenceVariance) << "), z = " << c.z();
  return s.str();
}

}  // namespace

std::string referenceImagePath(const std::string& suite, const std::string& name, const char* suffix) {
  return std::string(PATHLAB_TESTS_DIR) + "/" + suite + "/images/" + name + suffix;
}

PixelMoments checkImage(ImageCase c) {
  static const char* channels[] = {"red", "green", "blue"};
  const std::hash<std::string> hash;
  c.scene.indexPrimitives();
  c.scene.render.seed = testSeed(hash(c.suite + "/" + c.name));
  const PixelMoments yours = candidate::renderMoments(c.scene, c.options);

  const std::string meanPath = referencePath(c, ".exr"), variancePath = referencePath(c, ".variance.exr");
  if (const char* write = std::getenv("PATHLAB_WRITE_REFERENCE_IMAGES"); write && *write) {
    // tools/make-reference-images: this judge links the reference solutions.
    Scene scene = c.scene;
    scene.render.samplesPerPixel *= kReferenceSppFactor;
    scene.render.seed = 0x5eedf00dull + hash(c.name);
    ImageOptions uniform = c.options;  // an adaptive test's reference: every pixel at 16 x its maximum
    uniform.adaptive.reset();
    const PixelMoments reference = renderMoments(scene, uniform);
    std::filesystem::create_directories(std::filesystem::path(meanPath).parent_path());
    const ImageMetadata metadata{{"pathlab:spp", std::to_string(scene.render.samplesPerPixel)}};
    writeImage(meanImage(reference), meanPath, metadata);
    writeImage(varianceImage(reference), variancePath, metadata);
    MESSAGE("wrote " << meanPath);
  }
  PixelMoments reference;
  try {
    const Image mean = readImage(meanPath), variance = readImage(variancePath);
    reference = {mean.width, mean.height, 0, mean.pixels, variance.pixels, 0, true};
  } catch (const Error& e) {
    FAIL("the reference image is missing (tools/make-reference-images writes it): " << std::string(e.what()));
  }
  REQUIRE_MESSAGE(reference.width == c.scene.render.width, "the reference image " << meanPath << " is stale");
  REQUIRE_MESSAGE(reference.height == c.scene.render.height, "the reference image " << meanPath << " is stale");
  REQUIRE_MESSAGE(reference.varianceOfMean.size() == reference.mean.size(), variancePath << " does not match");
  REQUIRE_MESSAGE(yours.mean.size() == reference.mean.size(), "the candidate returned an image of the wrong size");

  REQUIRE_MESSAGE((yours.usedBvh || c.scene.primitives.empty()),
                  "task 3's BVH failed the framework's validation, so nothing was rendered (the candidate's "
                  "output above says why)");
  noteNoiseCeiling("image: the median pixel's, each block's and the whole image's variance at most 16 x the "
                   "reference's; a pixel over 64 x judged alone, at most 8 such (image_test.cpp)");
  const Verdict v = compare(yours, reference);
  INFO("image '" << c.name << "' (" << c.scene.render.width << "x" << c.scene.render.height << ", "
                 << c.scene.render.samplesPerPixel << " samples per pixel, |z| limit " << v.limit << ")");
  if (const char* statsPath = std::getenv("PATHLAB_IMAGE_STATS"); statsPath && *statsPath) {
    // tools/image-test-seeds: the largest |z| per image under many seeds.
    if (std::FILE* f = std::fopen(statsPath, "a")) {
      double whole = 0, wholeNoise = 0;
      for (const Comparison& w : v.whole) whole = std::max(whole, std::abs(w.z()));
      for (const Comparison& w : v.whole) wholeNoise = std::max(wholeNoise, w.noiseRatio());
      // ... then the verdict (tools/writeup): NaN or Inf samples, and 1 when the image passes.
      // ... then the pixels judged alone (over kPixelNoiseCap), and the largest ratio of a pixel's
      // variance to its base after the median's cap (what kPixelNoiseCap is set from).
      double most = 0;
      for (int channel = 0; channel < 3; ++channel) {
        const double scale = v.medianNoise[channel] > kImageNoiseFactor ? kImageNoiseFactor / v.medianNoise[channel] : 1.0;
        const double typical = typicalVariance(reference, channel);
        for (size_t i = 0; i < yours.mean.size(); ++i) {
          most = std::max(most, double(yours.varianceOfMean[i][channel]) * scale /
                                    pixelNoiseBase(reference, i, channel, typical));
        }
      }
      std::fprintf(f, "%s/%s %.3f %.3f %.3f %.4g %.4g %.4g %llu %d %zu %d %.4g\n", c.suite.c_str(), c.name.c_str(),
                   std::abs(v.worstZ), whole, v.limit, v.worstBlockNoise, wholeNoise, v.noise(),
                   static_cast<unsigned long long>(yours.nonFinite), yours.nonFinite == 0 && v.pass() ? 1 : 0,
                   v.noisy.size(), v.noisyAllowed, most);
      std::fclose(f);
    }
  }
  if (picturesAlways()) {
    MESSAGE(writeFailureImages(c, yours, reference, v));
  }
  if (yours.nonFinite > 0 || !v.pass()) {
    std::ostringstream s;
    if (yours.nonFinite > 0) s << yours.nonFinite << " samples were NaN or Inf.\n";
    if (v.tooNoisy()) {
      s << v.noisy.size() << " pixels are noisier than a correct render's can be (their variance over " << kPixelNoiseCap
        << " times the reference's there; at most " << v.noisyAllowed << " such fireflies are let through):";
      for (size_t k = 0; k < v.noisy.size() && k < 5; ++k) {
        const NoisyPixel& p = v.noisy[k];
        s << (k ? "," : "") << " (" << p.x << ", " << p.y << ") " << channels[p.channel] << " " << p.ratio << " times";
      }
      s << (v.noisy.size() > 5 ? ", ..." : "") << ". Some samples are far too large, or of the wrong sign?\n";
    }
    if (v.noise() > kImageNoiseFactor) {
      s << "your render's variance is " << v.noise() << " times the reference's in a typical pixel, more than a "
        << "correct render has "
        << "(some samples far too large, or of the wrong sign?): it is judged with the variance a correct one "
        << "would have.\n";
    }
    s << "worst 4x4 block: pixels x " << v.worstX << "-" << v.worstX + kBlock - 1 << ", y " << v.worstY << "-"
      << v.worstY + kBlock - 1 << " (row 0 at the top), " << channels[v.worstChannel] << ": " << describe(v.worst)
      << "\nwhole image, red:   " << describe(v.whole[0]) << "\nwhole image, green: " << describe(v.whole[1])
      << "\nwhole image, blue:  " << describe(v.whole[2]) << "\n"
      << writeFailureImages(c, yours, reference, v);
    FAIL_CHECK(s.str());
  }
  return yours;
}

}  // namespace pathlab::test
