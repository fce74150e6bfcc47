// pathlab-demo: the lecture's sampling demos.
//   pathlab-demo --list                      one demo per line, name first
//   pathlab-demo NAME [-o OUT] [--set P=V]   writes the figure (PNG) and prints its numbers
//   pathlab-demo NAME --gui                  the live window with sliders
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "demos.h"
#include "util/input_file.h"
#include "util/error.h"
#ifdef PATHLAB_HAVE_GUI
#include "demo_window.h"
#endif

namespace {

using namespace pathlab;
using namespace pathlab::demo;
int run(const std::string& name, const std::string& out, const std::vector<std::string>& settings, bool gui,
        const std::string& screenshot) {
  const std::vector<Demo>& demos = allDemos();
  const auto found = std::find_if(demos.begin(), demos.end(), [&](const Demo& d) { return d.name == name; });
  if (found == demos.end()) {
    std::string names;
    for (const Demo& d : demos) names += (names.empty() ? "" : ", ") + d.name;
    throw Error("no demo \"" + name + "\" (demos: " + names + ")");
  }
  const Values values = parseSettings(found->name, found->parameters, settings);
  if (gui || !screenshot.empty()) {
#ifdef PATHLAB_HAVE_GUI
    return runDemoWindow(*found, values, screenshot);
#else
    throw Error("--gui: this build has no window (install libglfw3-dev and libimgui-dev, then rebuild)");
#endif
  }
  const std::string path = figurePath(out, name);
  if (!isWritableImagePath(path)) throw Error("-o " + out + ": use a .png file, a folder or a prefix");
  const auto start = std::chrono::steady_clock::now();
  const DemoResult result = found->run(values);
  writeFigure(result.figure, path);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: %s\n%s", path.c_str(), found->summary.c_str(), result.numbers.c_str());
  std::printf("(%.1f s)\n", seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli("PathLab lecture demos: sampling maths as figures and numbers", "pathlab-demo");
  std::string name, out, screenshot;
  std::vector<std::string> settings;
  bool list = false, gui = false;
  cli.add_flag("--list", list, "print one demo per line: its name, then what it shows");
  cli.add_option("name", name, "the demo to run (see --list)");
  cli.add_option("-o,--out", out, "a .png file, a folder (gets NAME.png) or a prefix (gets PREFIX.png); default NAME.png");
  cli.add_option("--set", settings, "a parameter, NAME=VALUE (repeatable); the --gui sliders show them all");
  cli.add_flag("--gui", gui, "open the live window with sliders");
  cli.add_option("--screenshot", screenshot, "with --gui: save the window to FILE.png once drawn, then exit");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e);
  }
  try {
    if (list) {
      for (const Demo& demo : allDemos()) std::printf("%-20s %s\n", demo.name.c_str(), demo.summary.c_str());
      return 0;
    }
    if (name.empty()) throw Error("give a demo name (pathlab-demo --list shows them)");
    return run(name, out, settings, gui, screenshot);
  } catch (const std::exception& e) {
    pathlab::printError("pathlab-demo", e.what());
    return 1;
  }
}
