#include "figure_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

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
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(width, height));
  ImDrawList* list = ImGui::GetWindowDrawList();
  const ImU32 text = IM_COL32(220, 220, 220, 255), grid = IM_COL32(70, 70, 70, 255);
  list->AddText(ImVec2(origin.x + 4, origin.y), text, plot.title.c_str());
  const float left = origin.x + 58, right = origin.x + width - 8, top = origin.y + 22, bottom = origin.y + height - 34;

  // Images fill the plot area, keeping their aspect ratio.
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
  const bool onlyImages = std::all_of(plot.series.begin(), plot.series.end(), [](const Series& s) { return s.kind == Series::Kind::Image; });
  if (onlyImages) return;

  Axis x, y;
  x.log = plot.logX, y.log = plot.logY;
  size_t barGroups = 0;
  for (const Series& s : plot.series) {
    switch (s.kind) {
      case Series::Kind::Line:
      case Series::Kind::Scatter:
        for (double v : s.x) x.include(v);
        for (double v : s.y) y.include(v);
        break;
      case Series::Kind::Histogram:
        for (double v : s.x) x.include(v);
        for (double v : s.y) y.include(v);
        if (!y.log) y.include(0.0);
        break;
      case Series::Kind::Bars:
        x.include(-0.5), x.include(double(s.y.size()) - 0.5);
        for (double v : s.y) y.include(v);
        if (!y.log) y.include(0.0);
        ++barGroups;
        break;
      case Series::Kind::Image: break;
    }
  }
  x.finish(), y.finish();
  x.p0 = left, x.p1 = right, y.p0 = bottom, y.p1 = top;
  if (plot.equalAspect) {  // the same data units per pixel on both axes
    const double perPixel = std::max((x.hi - x.lo) / (right - left), (y.hi - y.lo) / (bottom - top));
    const double cx = 0.5 * (x.lo + x.hi), cy = 0.5 * (y.lo + y.hi);
    x.lo = cx - perPixel * (right - left) / 2, x.hi = cx + perPixel * (right - left) / 2;
    y.lo = cy - perPixel * (bottom - top) / 2, y.hi = cy + perPixel * (bottom - top) / 2;
  }
  list->PushClipRect(ImVec2(left, top), ImVec2(right, bottom), true);
  for (double t : x.ticks()) list->AddLine(ImVec2(x.map(t), top), ImVec2(x.map(t), bottom), grid);
  for (double t : y.ticks()) list->AddLine(ImVec2(left, y.map(t)), ImVec2(right, y.map(t)), grid);

  size_t colorIndex = 0, barIndex = 0;
  std::vector<std::pair<std::string, ImU32>> legend;
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
          const float base = y.log ? bottom : y.map(0.0);
          list->AddRectFilled(ImVec2(x.map(s.x[i]), y.map(s.y[i])), ImVec2(x.map(s.x[i + 1]), base), withAlpha(color, 110));
        }
        break;
      case Series::Kind::Bars: {
        const double barWidth = 0.8 / double(std::max<size_t>(1, barGroups));
        for (size_t i = 0; i < s.y.size(); ++i) {
          const double centre = double(i) + (double(barIndex) - double(barGroups - 1) / 2.0) * barWidth;
          const float base = y.log ? bottom : y.map(0.0);
          list->AddRectFilled(ImVec2(x.map(centre - barWidth / 2), y.map(s.y[i])), ImVec2(x.map(centre + barWidth / 2), base), color);
        }
        ++barIndex;
        break;
      }
      case Series::Kind::Image: break;
    }
  }
  list->PopClipRect();
  list->AddRect(ImVec2(left, top), ImVec2(right, bottom), IM_COL32(150, 150, 150, 255));

  // Tick labels, axis labels, categories, legend.
  char label[32];
  for (double t : x.ticks()) {
    if (!plot.categories.empty()) break;
    std::snprintf(label, sizeof label, "%.3g", t);
    list->AddText(ImVec2(x.map(t) - 10, bottom + 2), text, label);
  }
  for (size_t i = 0; i < plot.categories.size(); ++i) {
    list->AddText(ImVec2(x.map(double(i)) - 12, bottom + 2), text, plot.categories[i].c_str());
  }
  for (double t : y.ticks()) {
    std::snprintf(label, sizeof label, "%.3g", t);
    list->AddText(ImVec2(origin.x + 2, y.map(t) - 7), text, label);
  }
  list->AddText(ImVec2((left + right) / 2 - 20, bottom + 17), text, plot.xlabel.c_str());
  list->AddText(ImVec2(left + 4, top + 2), IM_COL32(170, 170, 170, 255), plot.ylabel.c_str());
  float legendY = top + 18;
  for (const auto& [name, color] : legend) {
    const ImVec2 size = ImGui::CalcTextSize(name.c_str());
    const float lx = std::max(left + 4, right - size.x - 20);
    list->AddRectFilled(ImVec2(lx, legendY + 3), ImVec2(lx + 10, legendY + 13), color);
    list->AddText(ImVec2(lx + 14, legendY), text, name.c_str());
    legendY += 16;
  }
}

}  // namespace pathlab::demo
