// The one place PathLab calls OpenImageIO: encoding and decoding image
// files, behind an interface of plain C types only (no std::string, no
// std::vector, no exception crosses it).
//
// Why C types: a library built against one C++ standard library cannot
// take another's types. Debian's OpenImageIO is built against libstdc++,
// so the Clang + libc++ build (the macOS toolchain, docs/setup.md) compiles
// this file alone with libstdc++ and everything else with libc++; the two
// halves meet only here. image.cpp holds every check and every message.
#pragma once

#include <cstddef>

extern "C" {

// Room for one line of error text from the codec (truncated to fit).
enum { kCodecErrorBytes = 512 };

// Receives the encoded file's bytes, once.
typedef void (*CodecByteSink)(void* context, const unsigned char* bytes, size_t size);

// Encodes width x height RGB pixels in the format `extension` names
// ("png", "exr", ...). `linear` true: `pixels` are 3 floats per pixel,
// stored as float; false: 3 bytes per pixel (sRGB), stored as 8 bit.
// `keys`/`values` are `count` metadata strings. Returns 1 on success,
// else 0 with the codec's message in `error`.
int codecEncode(const char* extension, int width, int height, int linear, const void* pixels,
                const char* const* keys, const char* const* values, int count, CodecByteSink sink,
                void* context, char error[kCodecErrorBytes]);

// What a file's header claims, read before any pixel is.
struct CodecHeader {
  int width, height, channels;
  int bytesPerChannel;  // as stored in the file
  int isInteger8or16;   // 8- or 16-bit integer channels: sRGB-encoded
  int hasAlpha;         // an alpha channel (colours are read as stored, never multiplied by it)
};

typedef struct CodecReader CodecReader;

// Opens `path` with the reader for `format` (an extension without the dot,
// or the whole path when it has none) and fills `header`. Returns the
// reader, or null with the message in `error`. The first call also sets
// OpenImageIO's own size limits.
CodecReader* codecOpen(const char* path, const char* format, CodecHeader* header,
                       char error[kCodecErrorBytes]);

// Reads the first `channels` channels as floats, `strideBytes` apart per
// pixel, into `destination`. Returns 1 on success, else 0 with `error`.
int codecRead(CodecReader* reader, int channels, float* destination, size_t strideBytes,
              char error[kCodecErrorBytes]);

void codecClose(CodecReader* reader);

}  // extern "C"
