#!/usr/bin/env bash
# Gradescope autograder set-up (runs once when the image is built).
# The zip made by tools/gradescope/make-zip.sh holds this file, run_autograder
# and the PathLab tree in source/; Gradescope unpacks it into
# /autograder/source, so the tree is /autograder/source/source.
# AUTOGRADER_ROOT (default /autograder) stands in for /autograder in
# grader/tests/test_gradescope.py, which also sets PATHLAB_SKIP_APT=1: the
# packages must then be installed already (checked by tools/install-grader).
set -euo pipefail
autograder=${AUTOGRADER_ROOT:-/autograder}
# The packages, CMake and the judges (tools/install-grader, which the other
# platforms' images run too); PATHLAB_SKIP_APT=1 passes through.
bash "$autograder/source/source/tools/install-grader"
# The grade runs as root in Gradescope's container; the candidate runs as an
# unprivileged uid that must not read the repository (tools/grade also
# makes it private while grading, and checks).
chmod 700 "$autograder/source"
