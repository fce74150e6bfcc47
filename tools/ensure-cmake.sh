#!/usr/bin/env bash
# Makes sure `cmake` is 3.25 or newer (PathLab's presets need it), for
# tools/install-grader (Gradescope's setup.sh, the Autolab and PrairieLearn
# images). Ubuntu 22.04, Gradescope's default base image, ships 3.22: then a
# newer CMake comes from PyPI (pip, over the network an image build has),
# and the script says so. If that fails, one line names the image to pick
# instead, and the script exits 1.
#   source tools/ensure-cmake.sh   (or run it: the same checks)
need=3.25
cmake_version() { { cmake --version 2>/dev/null || true; } | head -1 | grep -oE '[0-9]+\.[0-9]+(\.[0-9]+)?' | head -1 || true; }
new_enough() { [[ -n $1 ]] && [[ $(printf '%s\n%s\n' "$need" "$1" | sort -V | head -1) == "$need" ]]; }
have=$(cmake_version)
if ! new_enough "$have"; then
  echo "install-grader: CMake ${have:-(none)} is older than the $need PathLab's presets need:" \
       "installing a newer CMake from PyPI (python3 -m pip install 'cmake>=$need,<4')"
  if ! python3 -m pip --version > /dev/null 2>&1 && [[ ${PATHLAB_SKIP_APT:-} != 1 ]] &&
     declare -F install_packages > /dev/null; then
    install_packages python3-pip
  fi
  pip_said=$( { python3 -m pip install --quiet "cmake>=$need,<4" ||
                python3 -m pip install --quiet --break-system-packages "cmake>=$need,<4"; } 2>&1 ) || true
  hash -r
  have=$(cmake_version)
  if ! new_enough "$have"; then
    echo "install-grader: CMake ${have:-(none)} is too old and no newer one could be installed (pip: $(tail -1 <<< \
"${pip_said:-nothing}")): choose Ubuntu 24.04 (CMake 3.28) as the grading image's base (on Gradescope: the autograder's base image)" >&2
    exit 1
  fi
  echo "install-grader: now CMake $have ($(command -v cmake))"
fi
