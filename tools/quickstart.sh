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

# The tests' nested builds (the Gradescope zip's setup.sh, the student
# release and its check, all under build/) compile the framework again with
# the release build's flags. A compiler cache in build/ccache serves them:
# paths are hashed relative to each tree, and the __FILE__ prefix map (each
# tree maps its own root away) is left out of the key. Without ccache all
# still builds, only slower; a build/ configured before without it leaves
# the cache to the nested builds, which then share it among themselves.
use_compiler_cache() {
  command -v ccache > /dev/null || return 0
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_DIR="$PWD/build/ccache" CCACHE_BASEDIR="$PWD" \
         CCACHE_NOHASHDIR=1 CCACHE_IGNOREOPTIONS='-fmacro-prefix-map=*'
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
    use_compiler_cache
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
