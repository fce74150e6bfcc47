// The web build's image codec (cmake/PathLabWeb.cmake): util/image_codec.h
// answered by stb (PNG, JPEG, HDR, BMP, TGA, GIF, PSD and PNM read; PNG,
// JPEG and HDR written) and tinyexr (EXR), where the desktop build uses
// OpenImageIO, which is compiled for the host only. image.cpp keeps every
// check and every message; this file only decodes and encodes. What differs
// from OpenImageIO: PNG and JPEG files carry no metadata (EXR files carry it
// as string attributes), and tiled EXR files, PFM and TIFF are not read.
#include "util/image_codec.h"

#define STBI_MAX_DIMENSIONS (1 << 16)
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "util/web/zlib.h"  // tinyexr's <zlib.h> (the same file): its deflate, answered below by stb's
#define TINYEXR_IMPLEMENTATION
#include <tinyexr.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

// ---- tinyexr's zlib calls, on stb's deflate ---------------------------------

uLong compressBound(uLong sourceLen) { return sourceLen + sourceLen / 8 + 64; }  // stb: fixed codes, 9 bits at most

int compress(Bytef* dest, uLongf* destLen, const Bytef* source, uLong sourceLen) {
  int size = 0;
  unsigned char* packed = stbi_zlib_compress(const_cast<Bytef*>(source), int(sourceLen), &size, 8);
  if (!packed) return Z_BUF_ERROR;
  const bool fits = uLong(size) <= *destLen;
  if (fits) {
    std::memcpy(dest, packed, size_t(size));
    *destLen = uLong(size);
  }
  STBIW_FREE(packed);
  return fits ? Z_OK : Z_BUF_ERROR;
}

int uncompress(Bytef* dest, uLongf* destLen, const Bytef* source, uLong sourceLen) {
  const int size = stbi_zlib_decode_buffer(reinterpret_cast<char*>(dest), int(*destLen),
                                           reinterpret_cast<const char*>(source), int(sourceLen));
  if (size < 0) return Z_DATA_ERROR;
  *destLen = uLong(size);
  return Z_OK;
}

// ---- The reader ----------------------------------------------------------------

struct CodecReader {
  std::vector<unsigned char> bytes;  // the whole file
  bool exr = false;
  CodecHeader header{};
  EXRHeader exrHeader{};
};

namespace {

constexpr size_t kMaxFileBytes = size_t(1) << 30;

void setError(char error[kCodecErrorBytes], const std::string& text) {
  const size_t n = std::min(text.size(), size_t(kCodecErrorBytes) - 1);
  std::memcpy(error, text.data(), n);
  error[n] = '\0';
}

std::string lower(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool isStbFormat(const std::string& format) {
  for (const char* known : {"png", "jpg", "jpeg", "hdr", "bmp", "tga", "gif", "psd", "pnm", "ppm", "pgm"}) {
    if (format == known) return true;
  }
  return false;
}

bool readWholeFile(const char* path, std::vector<unsigned char>& bytes, char error[kCodecErrorBytes]) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in ? std::streamoff(in.tellg()) : -1;
  if (size < 0 || size_t(size) > kMaxFileBytes) {
    setError(error, size < 0 ? "cannot read image: cannot open the file" : "cannot read image: the file is over 1 GB");
    return false;
  }
  bytes.resize(size_t(size));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), size)) {
    setError(error, "cannot read image: the file could not be read");
    return false;
  }
  return true;
}

// The channel an EXR name stands for, as OpenImageIO orders them: R, G, B, A (a layer's "diffuse.R" too), then
// the rest as stored; a grey image's Y first.
int exrChannelRank(const char* name) {
  const char* dot = std::strrchr(name, '.');
  const std::string last = dot ? dot + 1 : name;
  if (last == "R" || last == "Y") return 0;
  if (last == "G") return 1;
  if (last == "B") return 2;
  if (last == "A") return 3;
  return 4;
}

std::vector<int> exrChannelOrder(const EXRHeader& header) {
  std::vector<int> order(size_t(header.num_channels));
  for (int c = 0; c < header.num_channels; ++c) order[size_t(c)] = c;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return exrChannelRank(header.channels[a].name) < exrChannelRank(header.channels[b].name);
  });
  return order;
}

bool openExr(CodecReader& reader, char error[kCodecErrorBytes]) {
  EXRVersion version{};
  const char* message = nullptr;
  if (ParseEXRVersionFromMemory(&version, reader.bytes.data(), reader.bytes.size()) != TINYEXR_SUCCESS) {
    setError(error, "cannot read image as a .exr file: not an OpenEXR file");
    return false;
  }
  if (version.multipart || version.non_image || version.tiled) {
    setError(error, "cannot read image as a .exr file: multi-part, deep and tiled EXR files are not read by the web "
                    "build (docs/web.md)");
    return false;
  }
  InitEXRHeader(&reader.exrHeader);
  if (ParseEXRHeaderFromMemory(&reader.exrHeader, &version, reader.bytes.data(), reader.bytes.size(), &message) !=
      TINYEXR_SUCCESS) {
    setError(error, std::string("cannot read image as a .exr file: ") + (message ? message : "a bad header"));
    FreeEXRErrorMessage(message);
    return false;
  }
  const EXRHeader& h = reader.exrHeader;
  reader.header.width = h.data_window.max_x - h.data_window.min_x + 1;
  reader.header.height = h.data_window.max_y - h.data_window.min_y + 1;
  reader.header.channels = h.num_channels;
  reader.header.bytesPerChannel = 4;
  for (int c = 0; c < h.num_channels; ++c) {
    if (h.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) reader.header.bytesPerChannel = 2;
    if (exrChannelRank(h.channels[c].name) == 3) reader.header.hasAlpha = 1;
  }
  return true;
}

bool openStb(CodecReader& reader, char error[kCodecErrorBytes]) {
  const int size = int(reader.bytes.size());
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(reader.bytes.data(), size, &width, &height, &channels)) {
    setError(error, std::string("cannot read image: ") + stbi_failure_reason());
    return false;
  }
  const bool hdr = stbi_is_hdr_from_memory(reader.bytes.data(), size) != 0;
  const bool sixteen = stbi_is_16_bit_from_memory(reader.bytes.data(), size) != 0;
  reader.header = {width, height, channels, hdr ? 4 : sixteen ? 2 : 1, hdr ? 0 : 1, channels == 2 || channels == 4};
  return true;
}

// Copies the first `channels` of `stored` interleaved channels, each scaled by `scale`, into the destination.
template <typename T>
void copyChannels(const T* from, int stored, size_t pixels, int channels, float scale, float* to, size_t stride) {
  for (size_t i = 0; i < pixels; ++i) {
    float* out = reinterpret_cast<float*>(reinterpret_cast<char*>(to) + i * stride);
    for (int c = 0; c < channels; ++c) out[c] = float(from[i * size_t(stored) + size_t(c)]) * scale;
  }
}

bool readStb(CodecReader& reader, int channels, float* destination, size_t stride, char error[kCodecErrorBytes]) {
  const int size = int(reader.bytes.size());
  const unsigned char* data = reader.bytes.data();
  int width = 0, height = 0, stored = 0;
  void* pixels = nullptr;
  if (reader.header.bytesPerChannel == 4) {
    pixels = stbi_loadf_from_memory(data, size, &width, &height, &stored, 0);
  } else if (reader.header.bytesPerChannel == 2) {
    pixels = stbi_load_16_from_memory(data, size, &width, &height, &stored, 0);
  } else {
    pixels = stbi_load_from_memory(data, size, &width, &height, &stored, 0);
  }
  if (!pixels || width != reader.header.width || height != reader.header.height || stored < channels) {
    setError(error, std::string("cannot read image: ") + (pixels ? "its size changed" : stbi_failure_reason()));
    stbi_image_free(pixels);
    return false;
  }
  const size_t count = size_t(width) * size_t(height);
  if (reader.header.bytesPerChannel == 4) {
    copyChannels(static_cast<const float*>(pixels), stored, count, channels, 1.0f, destination, stride);
  } else if (reader.header.bytesPerChannel == 2) {
    copyChannels(static_cast<const stbi_us*>(pixels), stored, count, channels, 1.0f / 65535.0f, destination, stride);
  } else {
    copyChannels(static_cast<const stbi_uc*>(pixels), stored, count, channels, 1.0f / 255.0f, destination, stride);
  }
  stbi_image_free(pixels);
  return true;
}

bool readExr(CodecReader& reader, int channels, float* destination, size_t stride, char error[kCodecErrorBytes]) {
  EXRHeader& h = reader.exrHeader;
  for (int c = 0; c < h.num_channels; ++c) {
    if (h.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) h.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
  }
  EXRImage image;
  InitEXRImage(&image);
  const char* message = nullptr;
  if (LoadEXRImageFromMemory(&image, &h, reader.bytes.data(), reader.bytes.size(), &message) != TINYEXR_SUCCESS) {
    setError(error, std::string("cannot read image as a .exr file: ") + (message ? message : "bad pixels"));
    FreeEXRErrorMessage(message);
    return false;
  }
  const std::vector<int> order = exrChannelOrder(h);
  const size_t count = size_t(reader.header.width) * size_t(reader.header.height);
  bool ok = image.images != nullptr;
  for (int c = 0; ok && c < channels; ++c) {
    const int stored = order[size_t(c)];
    if (h.requested_pixel_types[stored] != TINYEXR_PIXELTYPE_FLOAT) {
      setError(error, "cannot read image as a .exr file: a channel of integers");
      ok = false;
      break;
    }
    const float* plane = reinterpret_cast<const float*>(image.images[stored]);
    for (size_t i = 0; i < count; ++i) {
      reinterpret_cast<float*>(reinterpret_cast<char*>(destination) + i * stride)[c] = plane[i];
    }
  }
  if (!image.images) setError(error, "cannot read image as a .exr file: no pixels");
  FreeEXRImage(&image);
  return ok;
}

// ---- The writers ---------------------------------------------------------------

void appendBytes(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<unsigned char>*>(context);
  bytes->insert(bytes->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
}

bool encodeExr(int width, int height, const float* pixels, const char* const* keys, const char* const* values,
               int count, std::vector<unsigned char>& bytes, char error[kCodecErrorBytes]) {
  const size_t n = size_t(width) * size_t(height);
  std::vector<float> planes[3];  // stored B, G, R: the order OpenEXR's readers expect
  for (int c = 0; c < 3; ++c) {
    planes[c].resize(n);
    for (size_t i = 0; i < n; ++i) planes[c][i] = pixels[3 * i + size_t(2 - c)];
  }
  unsigned char* pointers[3] = {reinterpret_cast<unsigned char*>(planes[0].data()),
                                reinterpret_cast<unsigned char*>(planes[1].data()),
                                reinterpret_cast<unsigned char*>(planes[2].data())};
  EXRImage image;
  InitEXRImage(&image);
  image.images = pointers;
  image.width = width;
  image.height = height;
  image.num_channels = 3;

  EXRHeader header;
  InitEXRHeader(&header);
  EXRChannelInfo channels[3] = {};
  int types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
  for (int c = 0; c < 3; ++c) channels[c].name[0] = "BGR"[c];
  header.num_channels = 3;
  header.channels = channels;
  header.pixel_types = types;
  header.requested_pixel_types = types;
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
  std::vector<EXRAttribute> attributes(size_t(std::max(count, 0)));
  for (int i = 0; i < count; ++i) {
    EXRAttribute& a = attributes[size_t(i)];
    std::strncpy(a.name, keys[i], sizeof(a.name) - 1);
    std::strncpy(a.type, "string", sizeof(a.type) - 1);
    a.value = reinterpret_cast<unsigned char*>(const_cast<char*>(values[i]));
    a.size = int(std::strlen(values[i]));
  }
  header.num_custom_attributes = count;
  header.custom_attributes = attributes.data();

  unsigned char* memory = nullptr;
  const char* message = nullptr;
  const size_t size = SaveEXRImageToMemory(&image, &header, &memory, &message);
  if (size == 0) {
    setError(error, std::string("cannot encode image: ") + (message ? message : "tinyexr failed"));
    FreeEXRErrorMessage(message);
    return false;
  }
  bytes.assign(memory, memory + size);
  std::free(memory);
  return true;
}

}  // namespace

extern "C" {

int codecEncode(const char* extension, int width, int height, int linear, const void* pixels, const char* const* keys,
                const char* const* values, int count, CodecByteSink sink, void* context, char error[kCodecErrorBytes]) {
  const std::string format = lower(extension);
  std::vector<unsigned char> bytes;
  bool ok = false;
  if (format == "exr" && linear) {
    ok = encodeExr(width, height, static_cast<const float*>(pixels), keys, values, count, bytes, error);
  } else if (format == "hdr" && linear) {
    ok = stbi_write_hdr_to_func(appendBytes, &bytes, width, height, 3, static_cast<const float*>(pixels)) != 0;
  } else if (format == "png" && !linear) {
    ok = stbi_write_png_to_func(appendBytes, &bytes, width, height, 3, pixels, width * 3) != 0;
  } else if ((format == "jpg" || format == "jpeg") && !linear) {
    ok = stbi_write_jpg_to_func(appendBytes, &bytes, width, height, 3, pixels, 95) != 0;
  } else {
    setError(error, "cannot create an in-memory ." + format + " writer in the web build");
    return 0;
  }
  if (!ok) {
    if (!error[0]) setError(error, "cannot encode image as ." + format);
    return 0;
  }
  sink(context, bytes.data(), bytes.size());
  return 1;
}

CodecReader* codecOpen(const char* path, const char* format, CodecHeader* header, char error[kCodecErrorBytes]) {
  const std::string name = lower(format);
  if (name != "exr" && !isStbFormat(name)) {
    setError(error, "cannot read image as a ." + name +
                        " file: the web build reads .png, .jpg, .hdr, .exr, .bmp, "
                        ".tga, .gif, .psd and .pnm (docs/web.md)");
    return nullptr;
  }
  auto* reader = new CodecReader;
  reader->exr = name == "exr";
  if (!readWholeFile(path, reader->bytes, error) ||
      !(reader->exr ? openExr(*reader, error) : openStb(*reader, error))) {
    codecClose(reader);
    return nullptr;
  }
  *header = reader->header;
  return reader;
}

int codecRead(CodecReader* reader, int channels, float* destination, size_t strideBytes, char error[kCodecErrorBytes]) {
  if (channels > reader->header.channels) {
    setError(error, "cannot read image: asked for more channels than it has");
    return 0;
  }
  return (reader->exr ? readExr(*reader, channels, destination, strideBytes, error)
                      : readStb(*reader, channels, destination, strideBytes, error))
             ? 1
             : 0;
}

void codecClose(CodecReader* reader) {
  if (reader && reader->exr) FreeEXRHeader(&reader->exrHeader);
  delete reader;
}

}  // extern "C"
