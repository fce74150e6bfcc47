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
source "$autograder/source/source/tools/packages.sh"
if [ "${PATHLAB_SKIP_APT:-}" = 1 ]; then
  missing=$(missing_packages "${pathlab_grading[@]}")
  if [ -n "$missing" ]; then
    echo "setup.sh: PATHLAB_SKIP_APT=1 but packages are missing:" $missing >&2
    exit 1
  fi
else
  install_packages "${pathlab_grading[@]}"
fi
# Ubuntu 22.04 (Gradescope's default image) has CMake 3.22: a newer one from PyPI.
source "$autograder/source/source/tools/gradescope/ensure-cmake.sh"
# Build the framework and the reference once; grading rebuilds only the student's files.
cd "$autograder/source/source"
# Build the judges once (tools/grade configures build-grade the same way);
# grading then compiles only the student's files, in its sandbox.
cmake --preset grade -DPATHLAB_SUBMISSION_OBJECTS="$autograder/source/source/build-grade/submission-objects"
cmake --build build-grade --parallel "$(nproc)" --target pathlab-judges
# The grade runs as root in Gradescope's container; the candidate runs as an
# unprivileged uid that must not read the repository (tools/grade also
# makes it private while grading, and checks).
chmod 700 "$autograder/source"
