#!/usr/bin/env bash
# Makes sure `cmake` is 3.25 or newer (PathLab's presets need it), for
# setup.sh. Ubuntu 22.04, Gradescope's default base image, ships 3.22: then
# a newer CMake comes from PyPI (pip, over the network Gradescope's image
# build has), and the script says so. If that fails, one line names the
# image to pick instead, and the script exits 1.
#   source tools/gradescope/ensure-cmake.sh   (or run it: the same checks)
need=3.25
cmake_version() { { cmake --version 2>/dev/null || true; } | head -1 | grep -oE '[0-9]+\.[0-9]+(\.[0-9]+)?' | head -1 || true; }
new_enough() { [[ -n $1 ]] && [[ $(printf '%s\n%s\n' "$need" "$1" | sort -V | head -1) == "$need" ]]; }
have=$(cmake_version)
if ! new_enough "$have"; then
  echo "setup.sh: CMake ${have:-(none)} is older than the $need PathLab's presets need:" \
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
    echo "setup.sh: CMake ${have:-(none)} is too old and no newer one could be installed (pip: $(tail -1 <<< \
"${pip_said:-nothing}")): choose Ubuntu 24.04 (CMake 3.28) as the autograder's base image on Gradescope" >&2
    exit 1
  fi
  echo "setup.sh: now CMake $have ($(command -v cmake))"
fi
