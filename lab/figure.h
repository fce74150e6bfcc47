// What a demo shows: plots (lines, histograms, scatter, bars, images) with
// titles and axis labels. The same figure is drawn by matplotlib to a PNG
// (writeFigure) and by Dear ImGui in the live window (demo_window.cpp).
#pragma once

#include <string>
#include <vector>

#include "util/image.h"

namespace pathlab::demo {

struct Series {
  enum class Kind { Line, Histogram, Scatter, Bars, Image };
  Kind kind = Kind::Line;
  std::string label;
  // Line and Scatter: points (x, y). Histogram: x holds the n + 1 bin
  // edges and y the n bar heights. Bars: y holds one height per category.
  std::vector<double> x, y;
  bool dashed = false;
  Image image;  // Image: linear RGB, drawn over the plot's whole area
};

struct Plot {
  std::string title, xlabel, ylabel;
  bool logX = false, logY = false;
  bool equalAspect = false;             // one unit is as long on both axes (scatter of a disk)
  std::vector<std::string> categories;  // Bars: the category names
  std::vector<Series> series;
};

struct Figure {
  std::string title;
  std::vector<Plot> plots;  // side by side
};

// Draws the figure with matplotlib (tools/plot-demo.py, Debian's
// python3-matplotlib) into `path`. Throws pathlab::Error if it cannot.
void writeFigure(const Figure& figure, const std::string& path);

}  // namespace pathlab::demo
