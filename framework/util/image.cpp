#include "util/image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>

#include "util/error.h"
#include "util/image_codec.h"
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
// A sanitizer's report goes to the real stderr meanwhile (silenceStderr);
// fuzz builds keep stderr whole, for libFuzzer's own lines after a crash.
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

// The codec's functions (image_codec.h), from the module pathlab_image_codec,
// loaded the first time the program reads or writes an image: OpenImageIO
// brings some 260 shared libraries, which cost 0.15 s and 100 MB at every
// start of a program that links them, and most starts (a suite's test case,
// a bad-input run, the sampling lab) touch no image file.
struct Codec {
  decltype(&codecEncode) encode = nullptr;
  decltype(&codecOpen) open = nullptr;
  decltype(&codecRead) read = nullptr;
  decltype(&codecClose) close = nullptr;
  std::string error;  // why it could not be loaded ("" when it was)
};

template <typename Function>
void find(void* module, const char* name, Function& function, std::string& error) {
  function = reinterpret_cast<Function>(sharedLibraryFunction(module, name));
  if (!function && error.empty()) error = std::string("it has no function ") + name;
}

#ifdef PATHLAB_IMAGE_CODEC_LINKED
// The web build links its codec in (framework/CMakeLists.txt): there is no module to load.
Codec loadCodec() { return Codec{&codecEncode, &codecOpen, &codecRead, &codecClose, ""}; }
#else
Codec loadCodec() {
  // Where the build put it (PATHLAB_IMAGE_CODEC_PATH, framework/CMakeLists.txt),
  // then beside the program (a program copied elsewhere with the module);
  // or only the file the environment variable PATHLAB_IMAGE_CODEC names.
  std::vector<std::string> places;
  if (const char* chosen = std::getenv("PATHLAB_IMAGE_CODEC"); chosen && *chosen) {
    places.push_back(chosen);
  } else {
    places.push_back(PATHLAB_IMAGE_CODEC_PATH);
    const std::string self = currentExecutablePath();
    if (!self.empty()) {
      places.push_back((std::filesystem::path(self).parent_path() / PATHLAB_IMAGE_CODEC_FILE).string());
    }
  }
  Codec codec;
  std::string tried;
  for (const std::string& place : places) {
    std::string why;
    void* module = loadSharedLibrary(place, why);
    if (module) {
      find(module, "codecEncode", codec.encode, why);
      find(module, "codecOpen", codec.open, why);
      find(module, "codecRead", codec.read, why);
      find(module, "codecClose", codec.close, why);
      if (why.empty()) return codec;
    }
    if (why.rfind(place + ": ", 0) != 0) why = place + ": " + why;  // dlerror names the file, Windows does not
    tried += (tried.empty() ? "" : "; ") + oneLine(why);
  }
  codec.error = "cannot read or write images: the image codec (OpenImageIO, in " PATHLAB_IMAGE_CODEC_FILE
                ") did not load (" + tried + ")";
  return codec;
}
#endif

const Codec& imageCodec() {
  static const Codec loaded = loadCodec();  // once, thread-safe
  if (!loaded.error.empty()) throw Error(loaded.error);
  return loaded;
}

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
  const bool linear = isFloatFormat(ext);
  std::vector<const char*> keys, values;
  for (const auto& [key, value] : metadata) {
    keys.push_back(key.c_str());
    values.push_back(value.c_str());
  }
  const std::vector<uint8_t> srgb = linear ? std::vector<uint8_t>() : encodeSrgb8(image);
  const void* pixels = linear ? static_cast<const void*>(image.pixels.data()) : srgb.data();
  std::string bytes;
  const CodecByteSink sink = [](void* context, const unsigned char* data, size_t size) {
    static_cast<std::string*>(context)->assign(reinterpret_cast<const char*>(data), size);
  };
  char error[kCodecErrorBytes] = "";
  if (!imageCodec().encode(ext.c_str() + 1, image.width, image.height, linear, pixels, keys.data(), values.data(),
                   int(keys.size()), sink, &bytes, error)) {
    throw Error(shown(finalPath, 200) + ": " + oneLine(error));
  }
  writeFileAtomically(finalPath, bytes);
}

Image readImage(const std::string& path, bool* hasAlpha) {
  const size_t fileBytes = requireRegularFile(path, "image file");
  const QuietStderr quiet;  // until the function returns or throws (the message is printed later)
  // Only the reader the extension names: given a whole file name,
  // OpenImageIO tries every reader it has (TIFF, GIF, RAW, video, ...) on a
  // file its extension's reader rejects, which lets any input reach them all.
  std::string format = std::filesystem::path(path).extension().string();
  if (!format.empty()) format.erase(0, 1);
  CodecHeader header{};
  char error[kCodecErrorBytes] = "";
  const Codec& codec = imageCodec();
  const std::unique_ptr<CodecReader, void (*)(CodecReader*)> reader(
      codec.open(path.c_str(), format.empty() ? path.c_str() : format.c_str(), &header, error), codec.close);
  if (!reader) throw Error(shown(path, 200) + ": " + oneLine(error));
  if (hasAlpha) *hasAlpha = header.hasAlpha != 0;
  if (header.width <= 0 || header.height <= 0 || header.channels <= 0) {
    throw Error(shown(path, 200) + ": image has no pixels");
  }
  // At most 2^25 pixels (8192 x 4096): the image is allocated from the
  // header before any pixel is read, so a truncated file claiming a huge
  // size must not cost more than that (400 MB; fuzzing found a 1.8 GB case).
  const int64_t pixels = int64_t(header.width) * header.height;
  if (pixels > (int64_t(1) << 25)) {
    throw Error(shown(path, 200) + ": image is too large (" + std::to_string(header.width) + "x" +
                std::to_string(header.height) + ", at most 33.5 million pixels)");
  }
  // Nor may a small file claim a big image: no codec these formats use packs
  // more than about 1,000 bytes of pixels into one (deflate's limit is 1032:1,
  // run-length codes 64:1), so a header claiming over 4,096 times the file's
  // size is corrupt. Checked above 2^22 pixels only, where the image costs
  // 48 MB. (Fuzzing: a 576-byte EXR claiming 7501926 x 4 cost 2 GB under ASan.)
  const int64_t claimedBytes = pixels * header.channels * int64_t(header.bytesPerChannel);
  if (pixels > (int64_t(1) << 22) && claimedBytes > 4096 * int64_t(fileBytes)) {
    throw Error(shown(path, 200) + ": image is truncated or corrupt: its header claims " + std::to_string(header.width) + "x" +
                std::to_string(header.height) + " pixels but the file has only " + std::to_string(fileBytes) +
                " bytes");
  }
  // Read straight into the image: RGB, or one grey channel copied to all three.
  const int channels = header.channels >= 3 ? 3 : 1;
  Image image(header.width, header.height);
  if (!codec.read(reader.get(), channels, &image.pixels[0].x, sizeof(Color), error)) {
    throw Error(shown(path, 200) + ": " + oneLine(error));
  }
  const bool decodeSrgb = header.isInteger8or16 != 0;
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
