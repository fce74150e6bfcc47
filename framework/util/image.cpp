#include "util/image.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>

#include "util/error.h"
#include "util/input_file.h"
#include "util/platform.h"

namespace pathlab {
namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

bool isFloatFormat(const std::string& ext) { return ext == ".exr" || ext == ".hdr"; }

// OpenImageIO's error text can span lines (the PNG reader adds its own
// line, found by fuzzing); a bad input must give exactly one line.
std::string oneLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (size_t i = text.find('\n'); i != std::string::npos; i = text.find('\n', i)) text.replace(i, 1, "; ");
  return text;
}

// libpng also prints its own "libpng error: ..." line straight to stderr for
// a corrupt PNG (found by fuzzing). stderr points at /dev/null while
// OpenImageIO reads; reads are serialised because fd 2 is process-wide.
// Fuzz builds keep stderr, so a crash report from inside a read is seen.
class QuietStderr {
 public:
  QuietStderr() : lock_(mutex()) {
#ifdef PATHLAB_KEEP_STDERR_DURING_READS
    return;
#endif
    std::fflush(stderr);
    saved_ = silenceStderr();
  }
  ~QuietStderr() { restoreStderr(saved_); }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
  int saved_ = -1;
};

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
    throw Error(shown(finalPath, 200) + ": unsupported image format (use .png, .exr, .hdr or .jpg)");
  }
  // Encode in memory, then write the bytes through one checked writer: a
  // full disk or an interrupted write never leaves a truncated image (the
  // codecs' own file writes do not report every failure: a full disk gave a
  // truncated PNG and exit 0, libjpeg printed its own line).
  const std::string ext = lowerExtension(finalPath);
  auto out = OIIO::ImageOutput::create(ext.substr(1));
  if (!out || !out->supports("ioproxy")) {
    throw Error(shown(finalPath, 200) + ": cannot create an in-memory " + ext + " writer: " + oneLine(OIIO::geterror()));
  }
  const bool linear = isFloatFormat(ext);
  OIIO::ImageSpec spec(image.width, image.height, 3, linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", linear ? "Linear" : "sRGB");
  spec.attribute("Software", "PathLab");
  if (linear) spec.attribute("compression", "zip");
  for (const auto& [key, value] : metadata) spec.attribute(key, value);

  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  bool ok = out->set_ioproxy(&memory) && out->open(finalPath, spec);
  if (ok && linear) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  } else if (ok) {
    ok = out->write_image(OIIO::TypeDesc::UINT8, encodeSrgb8(image).data());
  }
  if (!ok || !out->close()) throw Error(shown(finalPath, 200) + ": cannot encode image: " + oneLine(out->geterror()));
  writeFileAtomically(finalPath, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

Image readImage(const std::string& path) {
  const size_t fileBytes = requireRegularFile(path, "image file");
  // OpenImageIO's own limits on what a header may claim: a truncated EXR
  // claiming a huge image made OpenEXR allocate 1.8 GB before failing
  // (found by fuzzing). 1 GB covers an 8192 x 4096 map of 4 float channels.
  static std::once_flag limitsSet;
  std::call_once(limitsSet, [] {
    OIIO::attribute("limits:channels", 16);
    OIIO::attribute("limits:imagesize_MB", 1024);
    OIIO::attribute("openexr:core", 1);
  });
  const QuietStderr quiet;  // until the function returns or throws (the message is printed later)
  // Only the reader the extension names: given a whole file name,
  // OpenImageIO tries every reader it has (TIFF, GIF, RAW, video, ...) on a
  // file its extension's reader rejects, which lets any input reach them all.
  std::string format = std::filesystem::path(path).extension().string();
  if (!format.empty()) format.erase(0, 1);
  auto in = OIIO::ImageInput::create(format.empty() ? path : format);
  if (!in) throw Error(shown(path, 200) + ": cannot read image: " + oneLine(OIIO::geterror()));
  OIIO::ImageSpec openedSpec;
  if (!in->open(path, openedSpec)) {
    throw Error(shown(path, 200) + ": cannot read image as a ." + format + " file: " + oneLine(in->geterror()));
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
    throw Error(shown(path, 200) + ": image has no pixels");
  }
  // At most 2^25 pixels (8192 x 4096): the image is allocated from the
  // header before any pixel is read, so a truncated file claiming a huge
  // size must not cost more than that (400 MB; fuzzing found a 1.8 GB case).
  const int64_t pixels = int64_t(spec.width) * spec.height;
  if (pixels > (int64_t(1) << 25)) {
    throw Error(shown(path, 200) + ": image is too large (" + std::to_string(spec.width) + "x" +
                std::to_string(spec.height) + ", at most 33.5 million pixels)");
  }
  // Nor may a small file claim a big image: no codec these formats use packs
  // more than about 1,000 bytes of pixels into one (deflate's limit is 1032:1,
  // run-length codes 64:1), so a header claiming over 4,096 times the file's
  // size is corrupt. Checked above 2^22 pixels only, where the image costs
  // 48 MB. (Fuzzing: a 576-byte EXR claiming 7501926 x 4 cost 2 GB under ASan.)
  const int64_t claimedBytes = pixels * spec.nchannels * int64_t(spec.format.size());
  if (pixels > (int64_t(1) << 22) && claimedBytes > 4096 * int64_t(fileBytes)) {
    throw Error(shown(path, 200) + ": image is truncated or corrupt: its header claims " + std::to_string(spec.width) + "x" +
                std::to_string(spec.height) + " pixels but the file has only " + std::to_string(fileBytes) +
                " bytes");
  }
  // Read straight into the image: RGB, or one grey channel copied to all three.
  const int channels = spec.nchannels >= 3 ? 3 : 1;
  Image image(spec.width, spec.height);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, image.pixels.data(), sizeof(Color))) {
    throw Error(shown(path, 200) + ": cannot read image: " + oneLine(in->geterror()));
  }
  const bool decodeSrgb = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                          spec.format.basetype == OIIO::TypeDesc::UINT16;
  for (Color& pixel : image.pixels) {
    if (channels == 1) pixel = Color(pixel.x);
    if (decodeSrgb) pixel = Color(srgbToLinear(pixel.x), srgbToLinear(pixel.y), srgbToLinear(pixel.z));
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

size_t zeroInvalidRadiance(Image& image) {
  size_t invalid = 0;
  for (Color& pixel : image.pixels) {
    bool bad = false;
    for (int c = 0; c < 3; ++c) {
      if (!(pixel[c] >= 0.0f) || !std::isfinite(pixel[c])) {
        pixel[c] = 0.0f;
        bad = true;
      }
    }
    invalid += bad ? 1 : 0;
  }
  return invalid;
}

}  // namespace pathlab
