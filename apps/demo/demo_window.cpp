#include "demo_window.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "background_worker.h"
#include "shell.h"
#include "figure_view.h"
#include "parameter_sliders.h"

namespace pathlab::demo {
namespace {

struct Job {
  const Demo* demo;
  Values values;
  uint64_t generation;
};
struct Computed {
  DemoResult result;
  std::string error;
  uint64_t generation;
};

class DemoWindow : public gui::ShellClient {
 public:
  DemoWindow(const Demo& demo, Values values, std::string screenshot)
      : demo_(&demo),
        values_(std::move(values)),
        screenshot_(std::move(screenshot)),
        worker_([](const Job& job, const std::atomic<bool>&, const std::function<void(Computed)>& publish) {
          Computed computed{{}, "", job.generation};
          try {
            computed.result = job.demo->run(job.values);
          } catch (const std::exception& e) {
            computed.error = e.what();
          }
          publish(std::move(computed));
        }) {
    recompute();
  }

  void frame() override {
    if (std::optional<Computed> computed = worker_.take(); computed && computed->generation == generation_) {
      shown_ = std::move(*computed);
      view_.invalidate();
      hasResult_ = true;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(340, display.y));
    ImGui::Begin("Demos", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    for (const Demo& demo : allDemos()) {
      if (ImGui::Selectable(demo.name.c_str(), &demo == demo_)) select(demo);
    }
    ImGui::Separator();
    ImGui::TextWrapped("%s", demo_->summary.c_str());
    ImGui::PushItemWidth(180);
    const bool changed = drawParameterSliders(demo_->parameters, values_);
    ImGui::PopItemWidth();
    if (changed) recompute();
    ImGui::Separator();
    if (!worker_.idle()) ImGui::TextDisabled("computing...");
    if (!shown_.error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", shown_.error.c_str());
    ImGui::TextWrapped("%s", shown_.result.numbers.c_str());
    ImGui::End();

    ImGui::SetNextWindowPos(ImVec2(340, 0));
    ImGui::SetNextWindowSize(ImVec2(display.x - 340, display.y));
    ImGui::Begin("Figure", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    if (hasResult_) view_.draw(shown_.result.figure);
    ImGui::End();

    // A screenshot waits for the current result and two frames to lay it out.
    settledFrames_ = hasResult_ && worker_.idle() && shown_.generation == generation_ ? settledFrames_ + 1 : 0;
  }

  bool quitRequested() const override { return quit_; }

  std::optional<std::string> takeScreenshotRequest() override {
    if (screenshot_.empty() || settledFrames_ < 3) return std::nullopt;
    quit_ = true;
    return std::exchange(screenshot_, std::string());
  }

 private:
  void select(const Demo& demo) {
    demo_ = &demo;
    values_.clear();
    recompute();
  }
  void recompute() {
    for (const Parameter& parameter : demo_->parameters) values_.try_emplace(parameter.name, parameter.value);
    worker_.submit({demo_, values_, ++generation_});
  }

  const Demo* demo_;
  Values values_;
  std::string screenshot_;
  gui::BackgroundWorker<Job, Computed> worker_;
  uint64_t generation_ = 0;
  Computed shown_;
  bool hasResult_ = false;
  FigureView view_;
  int settledFrames_ = 0;
  bool quit_ = false;
};

}  // namespace

int runDemoWindow(const Demo& demo, const Values& values, const std::string& screenshot) {
  gui::ShellOptions shell;
  shell.program = "pathlab-demo";
  shell.title = "PathLab demos";
  shell.width = 1500;
  shell.height = 800;
  if (!screenshot.empty()) shell.timeout = 300.0;
  return gui::runShell(shell, [&] { return std::make_unique<DemoWindow>(demo, values, screenshot); });
}

}  // namespace pathlab::demo
