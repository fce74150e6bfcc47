#include <atomic>
#include <csignal>
#include <cstdio>
#include <exception>
#include <new>

#include "cli.h"
#include "util/error.h"
#include "util/platform.h"

namespace {

std::atomic<bool> gCancel{false};
std::atomic<bool> gRendering{false};

// While rendering, a signal asks the render to stop (the image so far is
// written); before that (reading a scene, building the tree) there is
// nothing to save, so the process ends at once, as the user asked.
extern "C" void onInterrupt(int signal) {
  if (!gRendering.load()) {
    pathlab::exitFromSignalHandler("pathlab: interrupted before rendering began\n", 130);
  }
  gCancel.store(true);
  std::signal(signal, SIG_DFL);  // a second Ctrl-C ends the program at once
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
  try {
    return pathlab::runCli(argc, argv, gCancel, gRendering);
  } catch (const std::bad_alloc&) {
    pathlab::printError("pathlab", "out of memory: the scene or image is too large for this machine");
    return 1;
  } catch (const std::exception& e) {
    pathlab::printError("pathlab", std::string("internal error: ") + e.what());
    return 2;
  }
}
