// The sampling lab's command line: `pathlab lab` and the validity build's
// pathlab-lab-* programs (one per sampling mistake) share it.
#pragma once

#include <CLI/CLI.hpp>

#include "lab.h"

namespace pathlab::lab {

inline void addLabOptions(CLI::App& command, LabArgs& args) {
  command.add_option("warp", args.warp, "The warp (see --list)");
  command.add_option("-o,--output", args.output, "The figure: a .png, a folder or a prefix (default lab-WARP.png)");
  command.add_option("--csv", args.csv, "Also write every cell's observed and expected counts as CSV");
  command.add_option("--set", args.settings, "A parameter, NAME=VALUE (repeatable): samples, sequence, seed, grid "
                                             "and the warp's own (--list shows the warps, --params WARP theirs)")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command.add_option("--map", args.map, "The environment warp on your own map (an .exr, .hdr or .png, "
                                        "equirectangular) instead of its built-in ones");
  command.add_flag("--no-figure", args.noFigure, "Only the numbers and the verdict (no matplotlib)");
  command.add_flag("--list", args.list, "List the warps");
  command.add_flag("--params", args.params, "List the warp's parameters, their defaults and ranges");
}

}  // namespace pathlab::lab
