// OpenImageIO behind plain C types (image_codec.h says why). Everything
// here may be compiled against a different C++ standard library than the
// rest of PathLab, so nothing but C types enters or leaves, and every
// exception is caught before it could cross.
#include "util/image_codec.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

struct CodecReader {
  std::unique_ptr<OIIO::ImageInput> input;
};

namespace {

void setError(char error[kCodecErrorBytes], const std::string& text) {
  const size_t n = std::min(text.size(), size_t(kCodecErrorBytes) - 1);
  std::memcpy(error, text.data(), n);
  error[n] = '\0';
}

// OpenImageIO's own limits on what a header may claim: a truncated EXR
// claiming a huge image made OpenEXR allocate 1.8 GB before failing
// (found by fuzzing). 1 GB covers an 8192 x 4096 map of 4 float channels.
void setLimitsOnce() {
  static std::once_flag limitsSet;
  std::call_once(limitsSet, [] {
    OIIO::attribute("limits:channels", 16);
    OIIO::attribute("limits:imagesize_MB", 1024);
    OIIO::attribute("openexr:core", 1);
  });
}

}  // namespace

extern "C" {

int codecEncode(const char* extension, int width, int height, int linear, const void* pixels,
                const char* const* keys, const char* const* values, int count, CodecByteSink sink,
                void* context, char error[kCodecErrorBytes]) {
  try {
    auto out = OIIO::ImageOutput::create(extension);
    if (!out || !out->supports("ioproxy")) {
      setError(error, "cannot create an in-memory ." + std::string(extension) + " writer: " + OIIO::geterror());
      return 0;
    }
    const OIIO::TypeDesc type = linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(width, height, 3, type);
    spec.attribute("oiio:ColorSpace", linear ? "Linear" : "sRGB");
    spec.attribute("Software", "PathLab");
    if (linear) spec.attribute("compression", "zip");
    for (int i = 0; i < count; ++i) spec.attribute(keys[i], values[i]);

    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    const std::string name = std::string("image.") + extension;  // names the format; nothing is written to it
    if (!out->set_ioproxy(&memory) || !out->open(name, spec) || !out->write_image(type, pixels) || !out->close()) {
      setError(error, "cannot encode image: " + out->geterror());
      return 0;
    }
    sink(context, bytes.data(), bytes.size());
    return 1;
  } catch (const std::exception& e) {
    setError(error, std::string("cannot encode image: ") + e.what());
  } catch (...) {
    setError(error, "cannot encode image");
  }
  return 0;
}

CodecReader* codecOpen(const char* path, const char* format, CodecHeader* header, char error[kCodecErrorBytes]) {
  try {
    setLimitsOnce();
    auto reader = std::make_unique<CodecReader>();
    reader->input = OIIO::ImageInput::create(format);
    if (!reader->input) {
      setError(error, "cannot read image: " + OIIO::geterror());
      return nullptr;
    }
    OIIO::ImageSpec openedSpec, config;
    // Colours as the file stores them: OpenImageIO would multiply a PNG's
    // or TIFF's colours by alpha, and alpha 0 would turn them black.
    config.attribute("oiio:UnassociatedAlpha", 1);
    if (!reader->input->open(path, openedSpec, config)) {
      setError(error, "cannot read image as a ." + std::string(format) + " file: " + reader->input->geterror());
      return nullptr;
    }
    const OIIO::ImageSpec& spec = reader->input->spec();
    header->width = spec.width;
    header->height = spec.height;
    header->channels = spec.nchannels;
    header->hasAlpha = spec.alpha_channel >= 0 ? 1 : 0;
    header->bytesPerChannel = int(spec.format.size());
    header->isInteger8or16 = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                             spec.format.basetype == OIIO::TypeDesc::UINT16;
    return reader.release();
  } catch (const std::exception& e) {
    setError(error, std::string("cannot read image: ") + e.what());
  } catch (...) {
    setError(error, "cannot read image");
  }
  return nullptr;
}

int codecRead(CodecReader* reader, int channels, float* destination, size_t strideBytes,
              char error[kCodecErrorBytes]) {
  try {
    if (reader->input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, destination, OIIO::stride_t(strideBytes))) {
      return 1;
    }
    setError(error, "cannot read image: " + reader->input->geterror());
  } catch (const std::exception& e) {
    setError(error, std::string("cannot read image: ") + e.what());
  } catch (...) {
    setError(error, "cannot read image");
  }
  return 0;
}

void codecClose(CodecReader* reader) { delete reader; }

}  // extern "C"
