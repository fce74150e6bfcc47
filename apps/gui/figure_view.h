// Draws a demo Figure with Dear ImGui's draw lists: axes with ticks, lines
// (solid or dashed), histograms, scatter points, grouped bars, images and a
// legend — the live counterpart of the matplotlib PNG.
#pragma once

#include <memory>
#include <vector>

#include "texture.h"
#include "figure.h"

namespace pathlab::demo {

class FigureView {
 public:
  // Shows the figure's plots side by side in the space left in the window.
  void draw(const Figure& figure);
  // The plots in rows of `perRow` (a narrow panel), each as tall as it is wide.
  void drawRows(const Figure& figure, size_t perRow);
  // Call when the figure changes: image series are uploaded again.
  void invalidate() { textures_.clear(); }

 private:
  void drawPlot(const Plot& plot, float width, float height);
  bool drawImages(const Plot& plot, float width, float height, float top);
  std::vector<std::unique_ptr<gui::Texture>> textures_;  // one per image series, in order
  size_t nextTexture_ = 0;
};

}  // namespace pathlab::demo
