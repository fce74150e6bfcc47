// An image shown by Dear ImGui: an OpenGL texture holding the display
// encoding (exposure, then sRGB) of a linear image.
#pragma once

#include <imgui.h>

#include "util/image.h"

namespace pathlab::gui {

class Texture {
 public:
  Texture() = default;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
  ~Texture();

  // Shows `image` times 2^exposureStops.
  void upload(const Image& image, float exposureStops);
  bool empty() const { return id_ == 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  ImTextureID imguiId() const { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(id_)); }

 private:
  unsigned id_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace pathlab::gui
