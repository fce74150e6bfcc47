// pathlab-gui [SCENE] [--panel N] [--screenshot FILE.png] [--script FILE]
// The visual debugger (see app.h). With --screenshot it renders a few
// passes, shows panel N, saves the window and exits: tests, docs and CI run
// it under Xvfb.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "app.h"
#include "util/error.h"
#include "scene/scene_io.h"
#include "task_summary.h"

namespace {

using namespace pathlab;

struct Arguments {
  std::string scene;
  int panel = 1;
  std::string screenshot;
  std::string script;
  int threads = 0;
  int width = 1500, height = 900;
  double timeout = 600.0;
};

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot read the script");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

int run(const Arguments& args) {
  gui::AppOptions options;
  options.panel = args.panel;
  options.threads = args.threads;
  options.taskSummary = linkedTaskSummary();
  if (!args.script.empty()) options.script = gui::parseScript(readFile(args.script), args.script);
  if (!args.screenshot.empty()) {
    if (!isWritableImagePath(args.screenshot)) throw Error("--screenshot: " + args.screenshot + ": use a .png file");
    // Show the panel after a few passes (16 spp, or all if fewer), then save.
    options.script.push_back({"wait-spp", {"16"}, 0});
    options.script.push_back({"wait-panel", {}, 0});
    options.script.push_back({"screenshot", {args.screenshot}, 0});
    options.script.push_back({"quit", {}, 0});
  }
  Scene scene = args.scene.empty() ? defaultScene() : loadScene(args.scene);

  gui::ShellOptions shell;
  shell.program = "pathlab-gui";
  shell.title = "PathLab debugger";
  shell.width = args.width;
  shell.height = args.height;
  if (!options.script.empty()) shell.timeout = args.timeout;
  return gui::runShell(shell, [&] { return std::make_unique<gui::App>(std::move(scene), std::move(options)); });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli("PathLab visual debugger: the render, a pixel inspector and one panel per task", "pathlab-gui");
  Arguments args;
  cli.add_option("scene", args.scene, "scene file (.json or .dae); default: the embedded Cornell box");
  cli.add_option("--panel", args.panel, "open on task N's panel (1-" + std::to_string(kTaskCount) + ")")->check(CLI::Range(1, kTaskCount));
  cli.add_option("--screenshot", args.screenshot,
                 "render, show the panel, save the window to FILE.png and exit (tests, docs, CI under xvfb-run)");
  cli.add_option("--script", args.script, "run the commands in FILE (see apps/gui/script.h), then keep going");
  cli.add_option("-t,--threads", args.threads, "render threads (default: all)")->check(CLI::Range(0, 1024));
  cli.add_option("--window", args.width, "window width in pixels")->check(CLI::Range(640, 8192));
  cli.add_option("--timeout", args.timeout, "seconds a --script or --screenshot run may take (default 600)")
      ->check(CLI::Range(1.0, 86400.0));
  cli.set_version_flag("--version", std::string("pathlab-gui 0.1 (tasks ") + linkedTaskSummary() + ")");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e);
  }
  args.height = args.width * 3 / 5;
  try {
    return run(args);
  } catch (const std::exception& e) {
    pathlab::printError("pathlab-gui", e.what());
    return 1;
  }
}
