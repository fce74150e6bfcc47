// Scripted sessions for tests, docs and CI: `pathlab-gui --script FILE`
// runs one command per line as if a person did it, e.g.
//   panel 5            show task 5's panel
//   view paths         pick the panel's view by name
//   click 200 150      click the render at pixel (200, 150): inspect it
//   orbit 30 10        drag the render camera (yaw, pitch in degrees)
//   view-orbit 40 20   drag the panel's 3D view
//   depth 2            move the depth slider
//   exposure -1        display exposure in stops
//   wait               until the render and the panel are finished
//   wait-spp 8         until the render has 8 samples per pixel
//   lab environment    show the sampling lab's panel, on that warp
//   lab-set map 3      set one of the warp's parameters
//   lab-map F.exr      the environment warp on a map file
//   lab-verdict        prints what the lab shows: "WARP: ACCEPTED, p = ..." (after wait-panel)
//   wait-panel         until the panel's view (or the lab's test) is computed
//   panels             prints the panel buttons as last drawn: "N buttons in R rows, K cut: 1 Camera | ..."
//   screenshot F.png   save the window
//   quit
// Blank lines and lines starting with # are skipped.
#pragma once

#include <string>
#include <vector>

namespace pathlab::gui {

struct ScriptCommand {
  std::string verb;
  std::vector<std::string> args;
  int line = 0;

  // Argument i as a number (parseScript has checked that it is one).
  double number(size_t i) const { return std::stod(args[i]); }
};

// Throws pathlab::Error naming the file and line for an unknown command,
// the wrong number of arguments, or a number that is not one.
std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& name);

}  // namespace pathlab::gui
