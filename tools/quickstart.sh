#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a picture or a test report.
#
#   bash tools/quickstart.sh render   install, build, render the built-in Cornell box to render.png
#   bash tools/quickstart.sh test     install, build, run every test (ctest)
#   bash tools/quickstart.sh writeup [--stubs]   install, build, make the write-up (page and PDF, tools/writeup)
#
# Installs the Debian packages PathLab builds with (only when one is
# missing), then configures and builds through the release preset.
set -euo pipefail
cd "$(dirname "$0")/.."

source tools/packages.sh

# The release preset (CMakePresets.json): Ninja, Release, tests on.
# build [TARGET...]: those targets only (none: everything).
build() {
  cmake --preset release > /dev/null
  cmake --build --preset release --parallel "$(nproc)" ${1:+--target "$@"}
}

case "${1:-}" in
  render)
    install_packages "${pathlab_build[@]}"
    build pathlab  # the renderer alone: the suites and tools build with the test command
    ./build/pathlab -o render.png
    echo "Wrote $(pwd)/render.png"
    ;;
  test)
    install_packages "${pathlab_build[@]}" "${pathlab_test[@]}"
    build
    # Two slots per core: the tests' resource groups share them (tests/CMakeLists.txt).
    ctest --preset release --parallel "$((2 * $(nproc)))"
    ;;
  writeup)
    shift
    install_packages "${pathlab_build[@]}" "${pathlab_writeup[@]}"
    build
    python3 tools/writeup "$@"
    ;;
  *)
    echo "usage: bash tools/quickstart.sh render|test|writeup [--stubs]" >&2
    exit 2
    ;;
esac
