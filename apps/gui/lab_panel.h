// The debugger's "Lab" panel: the sampling lab (lab/lab.h) live. Pick a
// warp, move its parameters, and the samples, the warped grid, the
// histogram beside the integrated pdf, their difference and the chi-square
// verdict are recomputed in the background: the same code as `pathlab lab`
// and the suites' test, on the tasks this build links.
#pragma once

#include <string>

#include "background_worker.h"
#include "figure_view.h"
#include "lab.h"

namespace pathlab::gui {

class LabPanel {
 public:
  LabPanel();
  void draw();
  // The shown result is the current parameters' (for scripts and screenshots).
  bool settled() const;
  // Script: choose a warp (false: no such warp), set one of its parameters (false: no such parameter).
  bool select(const std::string& warp);
  bool set(const std::string& name, double value);
  // Script: the environment warp on the user's own map (empty: the built-in maps).
  void setEnvironmentMap(const std::string& path);
  // Script: what the panel shows now, as a line: "annulus: ACCEPTED, p = 0.824".
  std::string verdict() const;

 private:
  struct Job {
    const lab::Warp* warp;
    demo::Values values;
    lab::WarpFiles files;
    uint64_t generation;
  };
  struct Computed {
    lab::LabResult result;
    std::string error;
    uint64_t generation = 0;
  };
  void recompute();

  const lab::Warp* warp_;
  demo::Values values_;
  lab::WarpFiles files_;  // the map file, kept while other warps are shown
  char mapInput_[1024] = "";
  BackgroundWorker<Job, Computed> worker_;
  uint64_t generation_ = 0;
  Computed shown_;
  bool hasResult_ = false;
  demo::FigureView view_;
};

}  // namespace pathlab::gui
