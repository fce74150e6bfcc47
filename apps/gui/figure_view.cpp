#include "figure_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace pathlab::demo {
namespace {

const ImU32 kPalette[] = {IM_COL32(80, 160, 255, 255), IM_COL32(255, 140, 40, 255), IM_COL32(90, 200, 90, 255),
                          IM_COL32(230, 70, 70, 255),  IM_COL32(170, 120, 230, 255), IM_COL32(200, 200, 80, 255)};

ImU32 withAlpha(ImU32 color, int alpha) { return (color & 0x00FFFFFF) | (ImU32(alpha) << 24); }

// One axis: data range, log or linear, mapped to a pixel interval.
struct Axis {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  bool log = false;
  float p0 = 0, p1 = 1;  // pixels of lo and hi

  void include(double v) {
    if (log && !(v > 0.0)) return;
    const double t = log ? std::log10(v) : v;
    if (std::isfinite(t)) lo = std::min(lo, t), hi = std::max(hi, t);
  }
  void finish() {
    if (!(lo <= hi)) lo = 0.0, hi = 1.0;
    if (hi - lo < 1e-12) lo -= 0.5, hi += 0.5;
    const double pad = log ? 0.3 : 0.04 * (hi - lo);  // log: a third of a decade, so the smallest bar shows
    lo -= pad, hi += pad;
  }
  float map(double v) const {
    const double t = log ? std::log10(std::max(v, 1e-300)) : v;
    return p0 + float((t - lo) / (hi - lo)) * (p1 - p0);
  }
  std::vector<double> ticks() const {
    std::vector<double> result;
    if (log) {
      for (double e = std::ceil(lo); e <= hi + 1e-9; e += std::max(1.0, std::floor((hi - lo) / 5.0))) result.push_back(std::pow(10.0, e));
      return result;
    }
    const double raw = (hi - lo) / 5.0, magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 5.0, 10.0})
      if (raw <= m * magnitude) {
        step = m * magnitude;
        break;
      }
    for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step) result.push_back(std::abs(t) < 1e-12 ? 0.0 : t);
    return result;
  }
};

void dashedLine(ImDrawList* list, ImVec2 a, ImVec2 b, ImU32 color) {
  const float dx = b.x - a.x, dy = b.y - a.y, length = std::sqrt(dx * dx + dy * dy);
  for (float s = 0.0f; s < length; s += 10.0f) {
    const float e = std::min(length, s + 6.0f);
    list->AddLine(ImVec2(a.x + dx * s / length, a.y + dy * s / length), ImVec2(a.x + dx * e / length, a.y + dy * e / length),
                  color, 1.5f);
  }
}

// A plot's rectangle on screen: the title above, tick labels left and below.
struct PlotBox {
  ImVec2 origin;
  float left, right, top, bottom;
  PlotBox(ImVec2 corner, float width, float height)
      : origin(corner),
        left(corner.x + 58),
        right(corner.x + width - 8),
        top(corner.y + 22),
        bottom(corner.y + height - 34) {}
};

using Legend = std::vector<std::pair<std::string, ImU32>>;

const ImU32 kText = IM_COL32(220, 220, 220, 255), kGrid = IM_COL32(70, 70, 70, 255);

size_t barGroupsOf(const Plot& plot) {
  return size_t(std::count_if(plot.series.begin(), plot.series.end(),
                              [](const Series& s) { return s.kind == Series::Kind::Bars; }));
}

// The axes over every series but images (bars span their categories, and
// histograms and bars start at 0 on a linear axis), mapped to the box; an
// equal-aspect plot has the same data units per pixel on both.
std::pair<Axis, Axis> axesFor(const Plot& plot, const PlotBox& box) {
  Axis x, y;
  x.log = plot.logX, y.log = plot.logY;
  for (const Series& s : plot.series) {
    switch (s.kind) {
      case Series::Kind::Line:
      case Series::Kind::Scatter:
      case Series::Kind::Histogram:
        for (double v : s.x) x.include(v);
        for (double v : s.y) y.include(v);
        if (s.kind == Series::Kind::Histogram && !y.log) y.include(0.0);
        break;
      case Series::Kind::Bars:
        x.include(-0.5), x.include(double(s.y.size()) - 0.5);
        for (double v : s.y) y.include(v);
        if (!y.log) y.include(0.0);
        break;
      case Series::Kind::Image: break;
    }
  }
  x.finish(), y.finish();
  x.p0 = box.left, x.p1 = box.right, y.p0 = box.bottom, y.p1 = box.top;
  if (plot.equalAspect) {
    const double width = box.right - box.left, height = box.bottom - box.top;
    const double perPixel = std::max((x.hi - x.lo) / width, (y.hi - y.lo) / height);
    const double cx = 0.5 * (x.lo + x.hi), cy = 0.5 * (y.lo + y.hi);
    x.lo = cx - perPixel * width / 2, x.hi = cx + perPixel * width / 2;
    y.lo = cy - perPixel * height / 2, y.hi = cy + perPixel * height / 2;
  }
  return {x, y};
}

// Every series but images, each in the next colour of the palette, clipped
// to the box; returns the legend (the labelled series).
Legend drawSeries(ImDrawList* list, const Plot& plot, const Axis& x, const Axis& y, const PlotBox& box) {
  list->PushClipRect(ImVec2(box.left, box.top), ImVec2(box.right, box.bottom), true);
  for (double t : x.ticks()) list->AddLine(ImVec2(x.map(t), box.top), ImVec2(x.map(t), box.bottom), kGrid);
  for (double t : y.ticks()) list->AddLine(ImVec2(box.left, y.map(t)), ImVec2(box.right, y.map(t)), kGrid);
  const size_t barGroups = barGroupsOf(plot);
  const float base = y.log ? box.bottom : y.map(0.0);  // where histograms and bars stand
  size_t colorIndex = 0, barIndex = 0;
  Legend legend;
  for (const Series& s : plot.series) {
    if (s.kind == Series::Kind::Image) continue;
    const ImU32 color = kPalette[colorIndex++ % std::size(kPalette)];
    if (!s.label.empty()) legend.push_back({s.label, color});
    switch (s.kind) {
      case Series::Kind::Line:
        for (size_t i = 1; i < s.x.size(); ++i) {
          const ImVec2 a(x.map(s.x[i - 1]), y.map(s.y[i - 1])), b(x.map(s.x[i]), y.map(s.y[i]));
          s.dashed ? dashedLine(list, a, b, color) : list->AddLine(a, b, color, 2.0f);
        }
        break;
      case Series::Kind::Scatter:
        for (size_t i = 0; i < std::min<size_t>(s.x.size(), 5000); ++i) {
          list->AddCircleFilled(ImVec2(x.map(s.x[i]), y.map(s.y[i])), 1.6f, withAlpha(color, 170));
        }
        break;
      case Series::Kind::Histogram:
        for (size_t i = 0; i + 1 < s.x.size() && i < s.y.size(); ++i) {
          list->AddRectFilled(ImVec2(x.map(s.x[i]), y.map(s.y[i])), ImVec2(x.map(s.x[i + 1]), base),
                              withAlpha(color, 110));
        }
        break;
      case Series::Kind::Bars: {
        const double barWidth = 0.8 / double(std::max<size_t>(1, barGroups));
        for (size_t i = 0; i < s.y.size(); ++i) {
          const double centre = double(i) + (double(barIndex) - double(barGroups - 1) / 2.0) * barWidth;
          list->AddRectFilled(ImVec2(x.map(centre - barWidth / 2), y.map(s.y[i])),
                              ImVec2(x.map(centre + barWidth / 2), base), color);
        }
        ++barIndex;
        break;
      }
      case Series::Kind::Image: break;
    }
  }
  list->PopClipRect();
  list->AddRect(ImVec2(box.left, box.top), ImVec2(box.right, box.bottom), IM_COL32(150, 150, 150, 255));
  return legend;
}

// Tick labels (or the categories), the axis labels and the legend.
void drawLabels(ImDrawList* list, const Plot& plot, const Axis& x, const Axis& y, const PlotBox& box,
                const Legend& legend) {
  char label[32];
  if (plot.categories.empty()) {
    for (double t : x.ticks()) {
      std::snprintf(label, sizeof label, "%.3g", t);
      list->AddText(ImVec2(x.map(t) - 10, box.bottom + 2), kText, label);
    }
  }
  for (size_t i = 0; i < plot.categories.size(); ++i) {
    list->AddText(ImVec2(x.map(double(i)) - 12, box.bottom + 2), kText, plot.categories[i].c_str());
  }
  for (double t : y.ticks()) {
    std::snprintf(label, sizeof label, "%.3g", t);
    list->AddText(ImVec2(box.origin.x + 2, y.map(t) - 7), kText, label);
  }
  list->AddText(ImVec2((box.left + box.right) / 2 - 20, box.bottom + 17), kText, plot.xlabel.c_str());
  list->AddText(ImVec2(box.left + 4, box.top + 2), IM_COL32(170, 170, 170, 255), plot.ylabel.c_str());
  float legendY = box.top + 18;
  for (const auto& [name, color] : legend) {
    const ImVec2 size = ImGui::CalcTextSize(name.c_str());
    const float lx = std::max(box.left + 4, box.right - size.x - 20);
    list->AddRectFilled(ImVec2(lx, legendY + 3), ImVec2(lx + 10, legendY + 13), color);
    list->AddText(ImVec2(lx + 14, legendY), kText, name.c_str());
    legendY += 16;
  }
}

}  // namespace

void FigureView::draw(const Figure& figure) {
  ImGui::TextUnformatted(figure.title.c_str());
  const ImVec2 available = ImGui::GetContentRegionAvail();
  const size_t count = std::max<size_t>(1, figure.plots.size());
  const float spacing = 8.0f;
  const float width = (available.x - spacing * float(count - 1)) / float(count);
  const float height = std::min(available.y, width * 1.1f);
  nextTexture_ = 0;
  for (size_t i = 0; i < figure.plots.size(); ++i) {
    if (i > 0) ImGui::SameLine(0.0f, spacing);
    drawPlot(figure.plots[i], width, height);
  }
}

void FigureView::drawRows(const Figure& figure, size_t perRow) {
  ImGui::TextWrapped("%s", figure.title.c_str());
  const float spacing = 8.0f;
  const float width = (ImGui::GetContentRegionAvail().x - spacing * float(perRow - 1)) / float(perRow);
  nextTexture_ = 0;
  for (size_t i = 0; i < figure.plots.size(); ++i) {
    if (i % perRow != 0) ImGui::SameLine(0.0f, spacing);
    drawPlot(figure.plots[i], width, width);
  }
}

void FigureView::drawPlot(const Plot& plot, float width, float height) {
  const PlotBox box(ImGui::GetCursorScreenPos(), width, height);
  ImGui::Dummy(ImVec2(width, height));
  ImDrawList* list = ImGui::GetWindowDrawList();
  list->AddText(ImVec2(box.origin.x + 4, box.origin.y), kText, plot.title.c_str());
  if (drawImages(plot, width, height, box.top)) return;
  const auto [x, y] = axesFor(plot, box);
  const Legend legend = drawSeries(list, plot, x, y, box);
  drawLabels(list, plot, x, y, box, legend);
}

// Images fill the plot area, keeping their aspect ratio; true when the plot
// has nothing else.
bool FigureView::drawImages(const Plot& plot, float width, float height, float top) {
  const ImVec2 origin = ImGui::GetItemRectMin();
  ImDrawList* list = ImGui::GetWindowDrawList();
  for (const Series& s : plot.series) {
    if (s.kind != Series::Kind::Image) continue;
    if (nextTexture_ >= textures_.size()) {
      textures_.push_back(std::make_unique<gui::Texture>());
      textures_.back()->upload(s.image, 0.0f);
    }
    const gui::Texture& texture = *textures_[nextTexture_++];
    const float scale = std::min((width - 8) / float(texture.width()), (height - 30) / float(texture.height()));
    const ImVec2 a(origin.x + 4, top), b(a.x + float(texture.width()) * scale, a.y + float(texture.height()) * scale);
    list->AddImage(texture.imguiId(), a, b);
  }
  return std::all_of(plot.series.begin(), plot.series.end(),
                     [](const Series& s) { return s.kind == Series::Kind::Image; });
}

}  // namespace pathlab::demo
