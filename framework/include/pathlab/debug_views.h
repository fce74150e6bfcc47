// Debugger views: each task contributes named views that turn the scene and
// the task's code into an image. `pathlab debug` writes them to PNG; the GUI
// (a later issue) shows the same images in its panels.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "pathlab/image.h"
#include "pathlab/scene.h"

namespace pathlab {

struct DebugViewRequest {
  const Scene& scene;
  int width = 0;
  int height = 0;
  IVec2 pixel{-1, -1};  // inspected pixel; (-1, -1) means the image centre
  int threads = 0;
  int depth = 3;        // tree depth, for views that show one level of a hierarchy
};

// What a view produces: a picture, and optionally a few lines of numbers.
struct DebugOutput {
  Image image;
  std::string report;
};

struct DebugView {
  int task = 0;
  std::string name;
  std::string description;
  std::function<DebugOutput(const DebugViewRequest&)> render;
};

// Every view of every task, in task order.
std::vector<DebugView> allDebugViews();

// Each task's debugger.cpp provides one of these.
void addCameraRayViews(std::vector<DebugView>& views);     // tasks/01-camera-rays/debugger.cpp
void addIntersectionViews(std::vector<DebugView>& views);  // tasks/02-intersection/debugger.cpp
void addBvhViews(std::vector<DebugView>& views);           // tasks/03-bvh/debugger.cpp
void addDirectLightingViews(std::vector<DebugView>& views); // tasks/04-direct-lighting/debugger.cpp
void addPathTracingViews(std::vector<DebugView>& views);    // tasks/05-path-tracing/debugger.cpp
void addMirrorGlassViews(std::vector<DebugView>& views);    // tasks/06-mirror-glass/debugger.cpp
void addEnvironmentViews(std::vector<DebugView>& views);    // tasks/07-environment/debugger.cpp

}  // namespace pathlab
