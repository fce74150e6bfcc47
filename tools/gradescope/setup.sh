#!/usr/bin/env bash
# Gradescope autograder set-up (runs once when the image is built).
# The zip made by tools/gradescope/make-zip.sh holds this file, run_autograder
# and the PathLab tree in source/; Gradescope unpacks it into
# /autograder/source, so the tree is /autograder/source/source.
# AUTOGRADER_ROOT (default /autograder) stands in for /autograder in
# tests/grader/test_gradescope.py, which also sets PATHLAB_SKIP_APT=1: the
# packages must then be installed already (checked).
set -euo pipefail
autograder=${AUTOGRADER_ROOT:-/autograder}
packages=(build-essential cmake ninja-build pkg-config python3
  libglm-dev libopenimageio-dev doctest-dev nlohmann-json3-dev libcli11-dev libpugixml-dev
  bubblewrap util-linux)
if [ "${PATHLAB_SKIP_APT:-}" = 1 ]; then
  missing=$(dpkg-query -W -f='${db:Status-Abbrev} ${Package}\n' "${packages[@]}" 2>&1 | grep -v '^ii ' || true)
  if [ -n "$missing" ]; then
    echo "setup.sh: PATHLAB_SKIP_APT=1 but packages are missing:" >&2
    echo "$missing" >&2
    exit 1
  fi
else
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${packages[@]}"
fi
# Build the framework and the reference once; grading rebuilds only the student's files.
cd "$autograder/source/source"
# Build the judges once (tools/grade configures build-grade the same way);
# grading then compiles only the student's files, in its sandbox.
cmake -S . -B build-grade -G Ninja -DCMAKE_BUILD_TYPE=Release -DPATHLAB_TASKS=reference -DPATHLAB_BUILD_VALIDITY=OFF \
  -DPATHLAB_SUBMISSION_OBJECTS="$autograder/source/source/build-grade/submission-objects"
for t in 01-camera-rays 02-intersection 03-bvh 04-direct-lighting 05-path-tracing 06-mirror-glass 07-environment; do
  cmake --build build-grade --parallel "$(nproc)" --target "test-$t"
done
# The grade runs as root in Gradescope's container; the candidate runs as an
# unprivileged uid that must not read the repository (tools/grade also
# makes it private while grading, and checks).
chmod 700 "$autograder/source"
