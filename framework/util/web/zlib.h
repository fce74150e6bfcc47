// The three zlib calls tinyexr makes (compressBound, compress, uncompress),
// for the web build's image codec, which answers them with stb's deflate
// (util/image_codec_web.cpp): Emscripten offers zlib only as a download,
// and the web build uses Debian's packages alone (docs/web.md).
#pragma once

typedef unsigned long uLong;
typedef unsigned long uLongf;
typedef unsigned char Bytef;

enum { Z_OK = 0, Z_DATA_ERROR = -3, Z_BUF_ERROR = -5 };

uLong compressBound(uLong sourceLen);
int compress(Bytef* dest, uLongf* destLen, const Bytef* source, uLong sourceLen);
int uncompress(Bytef* dest, uLongf* destLen, const Bytef* source, uLong sourceLen);
