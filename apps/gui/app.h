// The debugger window: the progressive render on the left (click a pixel to
// inspect it, drag to orbit, right-drag to pan, wheel to zoom) with the pixel
// inspector below it, and on the right the settings and one panel per task. A panel
// shows its task's debugger views (tasks/NN-name/debugger.cpp), computed in
// the background from the current scene, camera and inspected pixel; the
// last panel is the sampling lab (lab_panel.h).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "background_worker.h"
#include "core/task_list.h"
#include "debug/debug_views.h"
#include "debug/inspect.h"
#include "lab_panel.h"
#include "render/render.h"
#include "script.h"
#include "shell.h"
#include "texture.h"

namespace pathlab::gui {

inline constexpr int kLabPanel = kTaskCount + 1;  // the sampling lab's panel, after the tasks'

// A task's debugger views (tasks/NN-name/debugger.cpp), made once: panels keep the pointers.
std::vector<const DebugView*> viewsOfTask(int task);

struct AppOptions {
  int panel = 1;                   // open on this task's panel (1..kTaskCount)
  std::vector<ScriptCommand> script;
  int threads = 0;                 // render threads; 0: all
  std::string taskSummary;         // "1:reference 2:student ...", as the build configured it
};

class App : public ShellClient {
 public:
  App(Scene scene, AppOptions options);

  void frame() override;
  bool quitRequested() const override { return quit_; }
  // A screenshot the script asked for in this frame.
  std::optional<std::string> takeScreenshotRequest() override { return std::exchange(screenshot_, std::nullopt); }
  // Whether the render and the visible panel are finished.
  bool settled() const;
  bool panelSettled() const;

 private:
  struct RenderJob {
    std::shared_ptr<const Scene> scene;
    RenderOptions options;
    uint64_t generation;
  };
  struct RenderFrame {
    Image image;
    RenderStats stats;
    uint64_t generation;
  };
  struct ViewJob {
    const DebugView* view;
    std::shared_ptr<const Scene> scene;
    IVec2 pixel;
    int depth;
    std::optional<Camera> viewCamera;
    int threads;
    std::string key;
  };
  struct ViewResult {
    DebugOutput output;
    std::string error;  // a view that threw
    std::string key;
  };

  // Scene and render
  void restartRender();
  void takeResults();
  void drawRenderWindow(float width, float height);
  void inspect(IVec2 pixel);
  // Right-hand side
  void drawSidePanel(float x, float width, float height);
  void drawSettings();
  void drawPanelSelector();
  // The panel buttons as last drawn (the script's `panels`): their labels, rows, and any cut by the window's edge.
  std::vector<std::string> selectorLabels_;
  int selectorRows_ = 0, selectorCut_ = 0;
  void drawInspector();
  void drawTaskPanel(int task);
  std::string viewKey(const DebugView& view) const;
  // Script
  void runScript();
  bool runCommand(const ScriptCommand& command);  // false: not finished, try again next frame

  Scene base_;  // as loaded; the controls below override parts of it
  AppOptions options_;
  Camera camera_;
  int width_, height_, spp_, maxDepth_, lightSamples_;
  int integrator_ = 0;  // index into kIntegrators
  float exposure_ = 0.0f;
  std::array<bool, kTaskCount + 1> studentTask_{};  // by task number ([0] unused)

  std::shared_ptr<const Scene> scene_;  // the scene being rendered
  uint64_t generation_ = 0;
  BackgroundWorker<RenderJob, RenderFrame> renderWorker_;
  Texture renderTexture_;
  Image renderImage_;
  RenderStats renderStats_;
  bool renderCurrent_ = false;  // the shown frame belongs to the current generation and is final

  std::optional<IVec2> pixel_;
  PixelInspection inspection_;
  // Built from base_ at the first inspection and kept: the controls change
  // the camera and settings, never the geometry or the lights.
  std::unique_ptr<const Accelerator> inspectionAccelerator_;
  std::unique_ptr<const Lights> inspectionLights_;
  bool inspectionStale_ = false;  // the scene changed since inspection_ was traced

  int selectedTab_ = 1;        // the task whose panel is shown (kLabPanel: the sampling lab)
  std::array<int, kTaskCount + 1> selectedView_{};   // by task number ([0] unused)
  int depth_ = 3;
  std::optional<Camera> viewCamera_;
  BackgroundWorker<ViewJob, ViewResult> viewWorker_;
  std::string submittedKey_, shownKey_;
  Texture viewTexture_;
  DebugOutput viewOutput_;
  std::string viewError_;
  LabPanel lab_;

  size_t scriptPosition_ = 0;
  int settledFrames_ = 0, panelSettledFrames_ = 0;
  bool quit_ = false;
  std::optional<std::string> screenshot_;
};

}  // namespace pathlab::gui
