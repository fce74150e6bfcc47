// Task 6's visual debugger (students don't edit this file: it shows what
// their mirror_glass.cpp — and, for diffuse surfaces, task 5's sampler — do).
//   lobe  for the surface under the inspected pixel: directions drawn by the
//         BSDF beside what its pdf predicts (debug/lobe_view.cpp); for mirror
//         and glass a point mass at each direction with the lobe's probability.
#include "debug/debug_views.h"

namespace pathlab {

void addMirrorGlassViews(std::vector<DebugView>& views) {
  views.push_back({6, "lobe", "BSDF lobe at the inspected pixel: sampled directions beside the pdf", bsdfLobeView,
                   kUsesPixel});
}

}  // namespace pathlab
