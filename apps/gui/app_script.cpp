// The window's --script commands (script.h): one per frame, so the
// interface draws what each did.
#include <algorithm>
#include <cstdio>

#include "app.h"
#include "util/error.h"

namespace pathlab::gui {

void App::runScript() {
  // Settled for a few frames: the window shows the finished state.
  settledFrames_ = settled() ? settledFrames_ + 1 : 0;
  panelSettledFrames_ = panelSettled() ? panelSettledFrames_ + 1 : 0;
  while (scriptPosition_ < options_.script.size()) {
    if (!runCommand(options_.script[scriptPosition_])) return;
    ++scriptPosition_;
    return;  // one command per frame, so the interface draws what it did
  }
}

bool App::runCommand(const ScriptCommand& command) {
  const std::string& verb = command.verb;
  if (verb == "wait") return settledFrames_ >= 3;
  if (verb == "wait-spp") return renderStats_.completedSpp >= std::min(spp_, int(command.number(0)));
  if (verb == "wait-panel") return panelSettledFrames_ >= 3;
  std::printf("script: %s", verb.c_str());
  for (const std::string& arg : command.args) std::printf(" %s", arg.c_str());
  if (verb == "panel") {
    const int panel = int(command.number(0));
    if (panel < 1 || panel > kTaskCount) {
      throw Error("script line " + std::to_string(command.line) + ": panel must be 1.." + std::to_string(kTaskCount));
    }
    selectedTab_ = panel;
  } else if (verb == "lab") {
    if (!lab_.select(command.args[0])) {
      throw Error("script line " + std::to_string(command.line) + ": the lab has no warp \"" + command.args[0] + "\"");
    }
    selectedTab_ = kLabPanel;
  } else if (verb == "lab-set") {
    if (!lab_.set(command.args[0], command.number(1))) {
      throw Error("script line " + std::to_string(command.line) + ": the warp has no parameter \"" + command.args[0] + "\"");
    }
  } else if (verb == "lab-map") {
    lab_.setEnvironmentMap(command.args[0]);
  } else if (verb == "panels") {
    std::printf(" -> %zu buttons in %d rows, %d cut:", selectorLabels_.size(), selectorRows_, selectorCut_);
    for (size_t i = 0; i < selectorLabels_.size(); ++i) std::printf("%s%s", i ? " | " : " ", selectorLabels_[i].c_str());
  } else if (verb == "lab-verdict") {
    std::printf(" -> %s", lab_.verdict().c_str());
  } else if (verb == "view") {
    const std::vector<const DebugView*> panelViews = viewsOfTask(selectedTab_);
    auto found = std::find_if(panelViews.begin(), panelViews.end(),
                              [&](const DebugView* v) { return v->name == command.args[0]; });
    if (found == panelViews.end()) {
      throw Error("script line " + std::to_string(command.line) + ": panel " + std::to_string(selectedTab_) +
                  " has no view \"" + command.args[0] + "\"");
    }
    selectedView_[size_t(selectedTab_)] = int(found - panelViews.begin());
  } else if (verb == "click") {
    const IVec2 pixel(int(command.number(0)), int(command.number(1)));
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= width_ || pixel.y >= height_) {
      throw Error("script line " + std::to_string(command.line) + ": click: pixel outside the image");
    }
    inspect(pixel);
    std::printf(" -> pixel %d,%d: %zu samples, mean (%.4f, %.4f, %.4f)", pixel.x, pixel.y, inspection_.samples.size(),
                double(inspection_.mean.x), double(inspection_.mean.y), double(inspection_.mean.z));
  } else if (verb == "orbit") {
    camera_ = orbitCamera(camera_, float(command.number(0)), float(command.number(1)));
    restartRender();
  } else if (verb == "view-orbit") {
    viewCamera_ = orbitCamera(viewCamera_.value_or(camera_), float(command.number(0)), float(command.number(1)));
  } else if (verb == "depth") {
    depth_ = std::clamp(int(command.number(0)), 0, int(kMaxBvhDepth));
  } else if (verb == "exposure") {
    exposure_ = float(command.number(0));
    if (!renderImage_.pixels.empty()) renderTexture_.upload(renderImage_, exposure_);
  } else if (verb == "screenshot") {
    screenshot_ = command.args[0];
  } else if (verb == "quit") {
    quit_ = true;
  }
  std::printf("\n");
  std::fflush(stdout);
  return true;
}

}  // namespace pathlab::gui
