// A linear-RGB float image and its file I/O through OpenImageIO.
// PNG/JPEG are written display-encoded (sRGB, 8 bit, clamped);
// EXR/HDR are written linear float, exactly as rendered.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "util/math.h"

namespace pathlab {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<Color> pixels;  // row-major, row 0 at the top

  Image() = default;
  Image(int w, int h, Color fill = Color(0.0f))
      : width(w), height(h), pixels(size_t(w) * size_t(h), fill) {}

  Color& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const Color& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

// Extra string attributes stored in the file's metadata (e.g. "pathlab:spp").
using ImageMetadata = std::map<std::string, std::string>;

// True when the path's extension is one writeImage understands.
bool isWritableImagePath(const std::string& path);

// Throws pathlab::Error naming the path when the file cannot be written.
void writeImage(const Image& image, const std::string& path, const ImageMetadata& metadata = {});

// Reads any format OpenImageIO knows into linear RGB (8-bit files are
// decoded from sRGB). An alpha channel is dropped, the colours kept as
// stored; `hasAlpha` says whether there was one. Throws pathlab::Error
// naming the path on failure.
Image readImage(const std::string& path, bool* hasAlpha = nullptr);

// The image as 8-bit sRGB bytes, 3 (RGB) or 4 (RGBA, alpha 255) per pixel,
// after multiplying by `scale` (exposure) and clamping, as PNGs store it.
std::vector<uint8_t> encodeSrgb8(const Image& image, int channels = 3, float scale = 1.0f);

// Radiance is finite and non-negative: sets every NaN, infinite or negative
// channel to 0 and returns how many pixels had one (environment maps pass
// through it when loaded, so task 7's code never sees such texels).
size_t zeroInvalidRadiance(Image& image);

// sRGB transfer function, one channel.
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

// Error of `image` against `reference` (same size), averaged over pixels and channels.
struct ImageError {
  double rmse = 0.0;
  double relMse = 0.0;  // mean((x - y)^2 / (y^2 + 0.01))
};
ImageError compareImages(const Image& image, const Image& reference);

}  // namespace pathlab
