// Debugger views: each task contributes named views that turn the scene and
// the task's code into an image. A task's views make its panel in
// `pathlab-gui`; `pathlab debug` writes the same images to PNG.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/scene.h"
#include "util/image.h"

namespace pathlab {

struct DebugViewRequest {
  DebugViewRequest(const Scene& s, int w, int h) : scene(s), width(w), height(h) {}

  const Scene& scene;
  int width = 0;
  int height = 0;
  IVec2 pixel{-1, -1};  // inspected pixel; (-1, -1) means the image centre
  int threads = 0;
  int depth = 3;        // tree depth, for views that show one level of a hierarchy
  // Views that draw rays in the scene draw them as seen from here (the GUI
  // orbits it to show paths in 3D); the rays are still traced through the
  // scene's camera. Unset: the scene's camera.
  std::optional<Camera> viewCamera;

  IVec2 inspectedPixel() const {
    return pixel.x < 0 ? IVec2(scene.render.width / 2, scene.render.height / 2) : pixel;
  }
  const Camera& drawingCamera() const { return viewCamera ? *viewCamera : scene.camera; }
};

// What a view produces: a picture, and optionally a few lines of numbers.
struct DebugOutput {
  Image image;
  std::string report;
};

// What a view reads besides the scene, so the GUI knows when to redraw it
// and which controls to show.
enum ViewInputs : unsigned {
  kNoInputs = 0,
  kUsesPixel = 1,     // the inspected pixel
  kUsesDepth = 2,     // the depth slider
  kCameraImage = 4,   // the image's top-left width x height is the camera's view: clicks pick pixels
  kUsesViewCamera = 8 // drawn from request.viewCamera (orbit in the panel)
};

struct DebugView {
  int task = 0;
  std::string name;
  std::string description;
  std::function<DebugOutput(const DebugViewRequest&)> render;
  unsigned inputs = kNoInputs;
};

// Helpers the views share.
class Accelerator;
// The scene under an eye light (albedo x |cos|, as the preview integrator),
// scaled by `brightness`, one ray per pixel centre, seen from
// request.drawingCamera() at request.width x request.height.
Image scenePreview(const DebugViewRequest& request, const Accelerator& accelerator, float brightness);
// A yellow square around the inspected pixel (when the view is drawn from the scene's camera).
void markInspectedPixel(Image& image, const DebugViewRequest& request);
// The BSDF lobe at the inspected pixel: sampled directions beside the pdf (debug/lobe_view.cpp).
DebugOutput bsdfLobeView(const DebugViewRequest& request);

// Every view of every task, in task order.
std::vector<DebugView> allDebugViews();

// Every task's views, in task order: each task's debugger.cpp defines
// add<Name>Views (tasks/01-camera-rays/debugger.cpp: addCameraRaysViews), and
// CMake generates this function, which calls them (framework/CMakeLists.txt).
void addTaskDebugViews(std::vector<DebugView>& views);

}  // namespace pathlab
