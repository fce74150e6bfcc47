#include "texture.h"

#include <GLFW/glfw3.h>  // the OpenGL 1.1 entry points textures need

#include <cmath>

namespace pathlab::gui {

Texture::~Texture() {
  if (id_ != 0) glDeleteTextures(1, &id_);
}

void Texture::upload(const Image& image, float exposureStops) {
  if (id_ == 0) glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  // Nearest: magnified pixels stay crisp, so a clicked pixel is a visible square.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::vector<uint8_t> bytes = encodeSrgb8(image, 4, std::exp2(exposureStops));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
  width_ = image.width;
  height_ = image.height;
}

}  // namespace pathlab::gui
