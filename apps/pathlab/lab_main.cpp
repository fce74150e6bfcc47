// pathlab-lab: `pathlab lab` alone, for the validity build's programs that
// link one task from a single file (a sampling mistake or a correct
// alternative, tests/CMakeLists.txt) and the reference for the others.
#include <cstdio>

#include "lab_cli.h"
#include "util/error.h"

int main(int argc, char** argv) {
  CLI::App app("PathLab's sampling lab: a warp's samples against its pdf", "pathlab-lab");
  pathlab::lab::LabArgs args;
  pathlab::lab::addLabOptions(app, args);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return pathlab::lab::runLab(args);
  } catch (const std::exception& e) {
    pathlab::printError("pathlab-lab", e.what());
    return 1;
  }
}
