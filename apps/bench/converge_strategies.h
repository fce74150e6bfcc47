// The converge bench's strategies (pathlab-bench converge --strategies):
// each changes one thing from the default, the course's recipe, and a probe
// render tells whether the linked code implements the change.
#pragma once

#include <string>
#include <vector>

#include "core/scene.h"
#include "linked_tasks.h"
#include "render/render.h"
#include "util/image.h"

namespace pathlab::bench {

struct Strategy {
  std::string name;
  RenderOptions options;
  // The tasks whose code the strategy runs besides the default's; empty for
  // the default strategy.
  std::vector<int> tasks;
  std::string change;  // what differs from the default, and whose code does it
  bool framework = false;  // run by the framework's path tracer (render/strategies.h), not tracePath
};

// The strategies' names. Task 9's four are its integrators' (render.h's
// kIntegrators: light, bsdf, mis-balance, mis), "mis-power" the same as "mis".
inline constexpr const char* kStrategyNames[] = {"reference", "cosine", "uniform-hemisphere", "nee", "no-nee", "rr",
                                                 "no-rr", "light", "bsdf", "mis-balance", "mis", "mis-power",
                                                 "env-importance", "env-uniform", "independent", "stratified",
                                                 "adaptive"};

// The strategy of that name (an unknown name: pathlab::Error listing them).
Strategy strategy(const std::string& name);

// A strategy `scene` cannot render (mediaProblem: a scene with media takes
// task 12's path tracer only), said with this program's flags before
// anything renders.
void checkStrategyFits(const char* flag, const Strategy& s, const Scene& scene, const std::string& sceneName);

// The probe: a small render of the scene with the strategy's change and
// without, same seed. Rendering is deterministic (the same image for any
// thread count), so identical images mean the change did nothing here (the
// linked code ignores it, or is unfinished): running the strategy would time
// the default under another name.
inline constexpr int kProbeWidth = 64;
inline constexpr int kProbeSpp = 8;
Scene probeScene(const Scene& scene);
Image probeImage(const Scene& probe, RenderOptions options, int threads);
bool identical(const Image& a, const Image& b);

struct Availability {
  bool available = true;
  std::string reason;  // why not, when not
  std::string note;    // a caveat, when available
};

// Whether the strategy can be measured here, from its probe and the linked code.
Availability judge(const Strategy& s, const Scene& scene, const LinkedTasks& linked, bool identicalToDefault);

}  // namespace pathlab::bench
