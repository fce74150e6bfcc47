#include <atomic>
#include <csignal>
#include <cstdio>
#include <exception>

#include "cli.h"

namespace {

std::atomic<bool> gCancel{false};

extern "C" void onInterrupt(int signal) {
  gCancel.store(true);
  std::signal(signal, SIG_DFL);  // a second Ctrl-C ends the program at once
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
  try {
    return pathlab::runCli(argc, argv, gCancel);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pathlab: internal error: %s\n", e.what());
    return 2;
  }
}
