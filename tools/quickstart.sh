#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a picture or a test report.
#
#   bash tools/quickstart.sh render   install, build, render the built-in Cornell box to render.png
#   bash tools/quickstart.sh test     install, build, run every test (ctest)
#
# Installs the Debian packages PathLab builds with (only when one is
# missing), configures build/ in Release mode and builds it.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config git python3 libglm-dev libopenimageio-dev doctest-dev
          nlohmann-json3-dev libcli11-dev libpugixml-dev libembree-dev
          libglfw3-dev libimgui-dev python3-matplotlib)
# The tests also start the GUI on a virtual display (Xvfb with Mesa's
# software OpenGL) and look at its screenshots with ImageMagick, and run the
# grader's sandbox (bubblewrap) against hostile submissions.
test_packages=(xvfb xauth libgl1-mesa-dri libglx-mesa0 imagemagick bubblewrap)

install_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]} == 0)) && return
  local sudo=()
  [[ $(id -u) -ne 0 ]] && sudo=(sudo)
  echo "Installing: ${missing[*]}"
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPATHLAB_BUILD_TESTS=ON > /dev/null
  cmake --build build --parallel "$(nproc)"
}

case "${1:-}" in
  render)
    install_packages
    build
    ./build/pathlab -o render.png
    echo "Wrote $(pwd)/render.png"
    ;;
  test)
    packages+=("${test_packages[@]}")
    install_packages
    build
    ctest --test-dir build --output-on-failure --parallel "$(nproc)"
    ;;
  *)
    echo "usage: bash tools/quickstart.sh render|test" >&2
    exit 2
    ;;
esac
