// The window pathlab-gui and `pathlab-demo --gui` run in: GLFW, an OpenGL
// 3.0 context and Dear ImGui, a frame loop that wakes at least every 50 ms
// (results arrive from background threads) and screenshots of the back
// buffer.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace pathlab::gui {

// What runs inside the window.
class ShellClient {
 public:
  virtual ~ShellClient() = default;
  // Builds one frame's interface (between ImGui::NewFrame and ImGui::Render).
  virtual void frame() = 0;
  virtual bool quitRequested() const = 0;
  // A file to save this frame to, once it is drawn.
  virtual std::optional<std::string> takeScreenshotRequest() = 0;
};

struct ShellOptions {
  std::string program;  // for messages, e.g. "pathlab-gui"
  std::string title;
  int width = 1500, height = 900;
  double timeout = 0.0;  // seconds; > 0: give up (exit 1) if the client has not quit by then
};

// Opens the window, makes the client (after the OpenGL context exists, so
// it can make textures) and runs frames until the client quits or the
// window is closed. Returns 0, or 1 after a timeout. Throws pathlab::Error
// when no window can be opened.
int runShell(const ShellOptions& options, const std::function<std::unique_ptr<ShellClient>()>& makeClient);

}  // namespace pathlab::gui
