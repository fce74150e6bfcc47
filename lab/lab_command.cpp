// `pathlab lab`: the sampling lab headless, its listings, its figure and
// its table (lab.h: runLab; lab_cli.h: its options).
#include <cstdio>
#include <fstream>

#include "demo_support.h"
#include "lab.h"
#include "util/error.h"
#include "util/image.h"
#include "util/output_file.h"

namespace pathlab::lab {

// pathlab lab WARP: the sampling lab headless (lab/lab.h).
int runLab(const LabArgs& args) {
  if (args.list) {
    for (const Warp& warp : allWarps()) {
      std::string also;
      for (int n : warp.alsoRuns) {
        also += (!also.empty() ? ", " : warp.alsoRuns.size() > 1 ? " (also runs tasks " : " (also runs task ") +
                std::to_string(n);
      }
      std::printf("%-20s %-5s %s%s\n", warp.name.c_str(), warp.task.c_str(), warp.summary.c_str(),
                  also.empty() ? "" : (also + ")").c_str());
    }
    return 0;
  }
  if (args.warp.empty()) throw Error("lab: give a warp (pathlab lab --list shows them)");
  const Warp* warp = findWarp(args.warp);
  if (!warp) {
    std::string names;
    for (const Warp& w : allWarps()) names += (names.empty() ? "" : ", ") + w.name;
    throw Error("lab: no warp \"" + args.warp + "\" (warps: " + names + ")");
  }
  const demo::Values values = demo::parseSettings(warp->name, parametersOf(*warp), args.settings);
  if (args.params) {
    for (const demo::Parameter& p : parametersOf(*warp)) {
      const std::string names = demo::choiceNames(p);
      std::printf("%-10s %-8g [%g, %g]  %s%s\n", p.name.c_str(), p.value, p.min, p.max, p.help.c_str(),
                  names.empty() ? "" : (": " + names).c_str());
    }
    return 0;
  }
  const std::string figure = args.noFigure ? "" : demo::figurePath(args.output, "lab-" + warp->name);
  if (!figure.empty() && !isWritableImagePath(figure)) throw Error("-o " + args.output + ": use a .png file, a folder or a prefix");
  if (!args.map.empty() && !warp->takesEnvironmentMap) {
    throw Error("lab: --map is for the environment warp (" + warp->name + " reads no map)");
  }
  // Every output checked before anything is written: a table that cannot
  // be written must not leave the figure behind, nor one file replace another.
  if (!figure.empty()) checkOutputFile("-o", figure, OutputKind::Image);
  if (args.csv) checkOutputFile("--csv", *args.csv, OutputKind::Text);
  checkDistinctFiles({{"-o", figure}, {"--csv", args.csv.value_or("")}, {"--map", args.map}});
  const LabResult result = runWarp(*warp, values, WarpFiles{args.map});
  if (args.csv) {
    std::ofstream csv(*args.csv);
    csv << result.csv;
    if (!csv.flush()) throw Error("--csv " + shown(*args.csv, 200) + ": cannot write it");
  }
  if (!figure.empty()) demo::writeFigure(result.shown.figure, figure);
  if (!figure.empty()) std::printf("%s\n", figure.c_str());
  std::printf("%s", result.shown.numbers.c_str());
  return 0;
}

}  // namespace pathlab::lab
