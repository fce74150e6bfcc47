#include "pathlab/debug_views.h"

namespace pathlab {

std::vector<DebugView> allDebugViews() {
  std::vector<DebugView> views;
  addCameraRayViews(views);
  addIntersectionViews(views);
  addBvhViews(views);
  addDirectLightingViews(views);
  addPathTracingViews(views);
  addMirrorGlassViews(views);
  addEnvironmentViews(views);
  return views;
}

}  // namespace pathlab
