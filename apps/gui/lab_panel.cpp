#include "lab_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "parameter_sliders.h"
#include "util/error.h"

namespace pathlab::gui {

LabPanel::LabPanel()
    : warp_(&lab::allWarps().front()),
      worker_([](const Job& job, const std::atomic<bool>&, const std::function<void(Computed)>& publish) {
        Computed computed;
        computed.generation = job.generation;
        try {
          computed.result = lab::runWarp(*job.warp, job.values, job.files);
        } catch (const std::exception& e) {
          computed.error = e.what();
        }
        publish(std::move(computed));
      }) {}

bool LabPanel::settled() const {
  return generation_ > 0 && hasResult_ && worker_.idle() && shown_.generation == generation_;
}

bool LabPanel::select(const std::string& name) {
  const lab::Warp* warp = lab::findWarp(name);
  if (!warp) return false;
  warp_ = warp;
  values_.clear();
  recompute();
  return true;
}

std::string LabPanel::verdict() const {
  if (!hasResult_) return warp_->name + ": no result yet";
  if (!shown_.error.empty()) return warp_->name + ": " + shown_.error;
  const lab::LabResult& r = shown_.result;
  std::ostringstream line;
  line << warp_->name << ": " << (r.accepted ? "ACCEPTED" : "REJECTED");
  if (r.test.failure.empty() && r.test.degreesOfFreedom > 0) line << ", p = " << r.test.pValue;
  return line.str();
}

void LabPanel::setEnvironmentMap(const std::string& path) {
  std::snprintf(mapInput_, sizeof mapInput_, "%s", path.c_str());
  files_.environmentMap = path;
  recompute();
}

bool LabPanel::set(const std::string& name, double value) {
  for (const demo::Parameter& p : lab::parametersOf(*warp_)) {
    if (p.name != name) continue;
    values_[name] = std::clamp(value, p.min, p.max);
    recompute();
    return true;
  }
  return false;
}

void LabPanel::recompute() {
  for (const demo::Parameter& p : lab::parametersOf(*warp_)) values_.try_emplace(p.name, p.value);
  worker_.submit({warp_, values_, warp_->takesEnvironmentMap ? files_ : lab::WarpFiles{}, ++generation_});
}

void LabPanel::draw() {
  if (generation_ == 0) recompute();  // the first time the panel is shown
  if (std::optional<Computed> computed = worker_.take(); computed && computed->generation == generation_) {
    shown_ = std::move(*computed);
    view_.invalidate();
    hasResult_ = true;
    if (!shown_.error.empty()) printWarning(shown_.error);  // also on the terminal (and in scripted sessions' logs)
  }
  ImGui::PushItemWidth(220);
  if (ImGui::BeginCombo("warp", (warp_->name + "  (" + warp_->task + ")").c_str())) {
    for (const lab::Warp& warp : lab::allWarps()) {
      if (ImGui::Selectable((warp.name + "  (" + warp.task + ")").c_str(), &warp == warp_)) select(warp.name);
    }
    ImGui::EndCombo();
  }
  ImGui::TextWrapped("%s", warp_->summary.c_str());
  bool changed = demo::drawParameterSliders(lab::parametersOf(*warp_), values_, 2);
  if (warp_->takesEnvironmentMap) {
    // The user's own map instead of the built-in ones (Enter loads it; empty: the built-in maps again).
    ImGui::PushItemWidth(360);
    if (ImGui::InputTextWithHint("map file", "your own map: an .exr, .hdr or .png; Enter loads it", mapInput_,
                                 sizeof mapInput_, ImGuiInputTextFlags_EnterReturnsTrue)) {
      files_.environmentMap = mapInput_;
      changed = true;
    }
    ImGui::PopItemWidth();
  }
  ImGui::PopItemWidth();
  if (changed) recompute();
  ImGui::Separator();
  if (!worker_.idle()) ImGui::TextDisabled("computing...");
  if (!shown_.error.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "%s", shown_.error.c_str());
    return;
  }
  if (!hasResult_) return;
  const ImVec4 verdict = shown_.result.accepted ? ImVec4(0.45f, 0.85f, 0.45f, 1.0f) : ImVec4(1.0f, 0.45f, 0.35f, 1.0f);
  ImGui::PushStyleColor(ImGuiCol_Text, verdict);
  ImGui::TextWrapped("%s", shown_.result.shown.numbers.c_str());
  ImGui::PopStyleColor();
  view_.drawRows(shown_.result.shown.figure, 2);
}

}  // namespace pathlab::gui
