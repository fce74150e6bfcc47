#include "pathlab/image.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include "pathlab/error.h"

namespace pathlab {
namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

bool isFloatFormat(const std::string& ext) { return ext == ".exr" || ext == ".hdr"; }

}  // namespace

float linearToSrgb(float linear) {
  if (!(linear > 0.0f)) return 0.0f;  // also maps NaN to 0
  if (linear <= 0.0031308f) return 12.92f * linear;
  return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float encoded) {
  if (encoded <= 0.04045f) return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

std::vector<uint8_t> encodeSrgb8(const Image& image, int channels, float scale) {
  std::vector<uint8_t> bytes(image.pixels.size() * size_t(channels), 255);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const float v = std::clamp(linearToSrgb(scale * image.pixels[i][c]), 0.0f, 1.0f);
      bytes[size_t(channels) * i + size_t(c)] = uint8_t(std::lround(v * 255.0f));
    }
  }
  return bytes;
}

bool isWritableImagePath(const std::string& path) {
  std::string ext = lowerExtension(path);
  return ext == ".png" || ext == ".exr" || ext == ".hdr" || ext == ".jpg" || ext == ".jpeg";
}

void writeImage(const Image& image, const std::string& finalPath, const ImageMetadata& metadata) {
  if (!isWritableImagePath(finalPath)) {
    throw Error(finalPath + ": unsupported image format (use .png, .exr, .hdr or .jpg)");
  }
  // Write a temporary file beside the target and rename it: an interrupted
  // write never leaves a truncated image behind.
  const std::filesystem::path target(finalPath);
  std::string partialName = ".";
  partialName.append(target.stem().string()).append(".partial").append(target.extension().string());
  const std::string path = (target.parent_path() / partialName).string();
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw Error(finalPath + ": cannot create image writer: " + OIIO::geterror());

  const std::string ext = lowerExtension(path);
  const bool linear = isFloatFormat(ext);
  OIIO::ImageSpec spec(image.width, image.height, 3, linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", linear ? "Linear" : "sRGB");
  spec.attribute("Software", "PathLab");
  if (linear) spec.attribute("compression", "zip");
  for (const auto& [key, value] : metadata) spec.attribute(key, value);

  if (!out->open(path, spec)) throw Error(finalPath + ": cannot write: " + out->geterror());
  bool ok;
  if (linear) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  } else {
    ok = out->write_image(OIIO::TypeDesc::UINT8, encodeSrgb8(image).data());
  }
  if (!ok || !out->close()) {
    std::string why = out->geterror();
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    throw Error(finalPath + ": cannot write: " + why);
  }
  std::error_code renamed;
  std::filesystem::rename(path, finalPath, renamed);
  if (renamed) throw Error(finalPath + ": cannot write: " + renamed.message());
}

Image readImage(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw Error(path + ": no such image file");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw Error(path + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
    throw Error(path + ": image has no pixels");
  }
  if (int64_t(spec.width) * spec.height > (int64_t(1) << 28)) {
    throw Error(path + ": image is too large (" + std::to_string(spec.width) + "x" +
                std::to_string(spec.height) + ")");
  }
  const int channels = spec.nchannels;
  std::vector<float> data(size_t(spec.width) * size_t(spec.height) * size_t(channels));
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data())) {
    throw Error(path + ": cannot read image: " + in->geterror());
  }
  const bool decodeSrgb = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                          spec.format.basetype == OIIO::TypeDesc::UINT16;
  Image image(spec.width, spec.height);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      float v = data[i * size_t(channels) + size_t(std::min(c, channels - 1))];
      image.pixels[i][c] = decodeSrgb ? srgbToLinear(v) : v;
    }
  }
  return image;
}

ImageError compareImages(const Image& image, const Image& reference) {
  if (image.width != reference.width || image.height != reference.height) {
    throw Error("reference image is " + std::to_string(reference.width) + "x" +
                std::to_string(reference.height) + " but the render is " +
                std::to_string(image.width) + "x" + std::to_string(image.height));
  }
  double squared = 0.0, relative = 0.0;
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      double x = image.pixels[i][c], y = reference.pixels[i][c];
      squared += (x - y) * (x - y);
      relative += (x - y) * (x - y) / (y * y + 0.01);
    }
  }
  const double n = 3.0 * double(image.pixels.size());
  return {std::sqrt(squared / n), relative / n};
}

}  // namespace pathlab
