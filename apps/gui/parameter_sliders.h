// A slider per parameter (integer or real, linear or logarithmic spacing,
// its help as the tooltip): the demo window and the debugger's lab tab share
// it, so a parameter looks and behaves the same in both.
#pragma once

#include <imgui.h>

#include <cmath>
#include <vector>

#include "demos.h"

namespace pathlab::demo {

// `perRow` sliders to a row. True when the user moved one.
inline bool drawParameterSliders(const std::vector<Parameter>& parameters, Values& values, int perRow = 1) {
  bool changed = false;
  int shown = 0;
  for (const Parameter& parameter : parameters) {
    double& value = values[parameter.name];
    if (shown++ % perRow != 0) ImGui::SameLine();
    const ImGuiSliderFlags flags = parameter.logarithmic ? ImGuiSliderFlags_Logarithmic : 0;
    if (parameter.integer) {
      int v = int(std::lround(value));
      // A choice shows its name (names have no '%', which ImGui would read as a format).
      const bool named = v >= 0 && size_t(v) < parameter.choices.size();
      if (ImGui::SliderInt(parameter.name.c_str(), &v, int(parameter.min), int(parameter.max),
                           named ? parameter.choices[size_t(v)].c_str() : "%d", flags)) {
        value = v, changed = true;
      }
    } else {
      float v = float(value);
      if (ImGui::SliderFloat(parameter.name.c_str(), &v, float(parameter.min), float(parameter.max), "%.3f", flags)) {
        value = v, changed = true;
      }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", parameter.help.c_str());
  }
  return changed;
}

}  // namespace pathlab::demo
