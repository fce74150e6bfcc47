#!/usr/bin/env bash
# Gradescope autograder set-up (runs once when the image is built).
# The zip made by tools/gradescope/make-zip.sh holds this file, run_autograder
# and the PathLab tree in source/.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends build-essential cmake ninja-build pkg-config python3 \
  libglm-dev libopenimageio-dev doctest-dev nlohmann-json3-dev libtinyobjloader-dev libcli11-dev libpugixml-dev \
  bubblewrap util-linux
# Build the framework and the reference once; grading rebuilds only the student's files.
cd /autograder/source
# Build the judges once (tools/grade configures build-grade the same way);
# grading then compiles only the student's files, in its sandbox.
cmake -S . -B build-grade -G Ninja -DCMAKE_BUILD_TYPE=Release -DPATHLAB_TASKS=reference -DPATHLAB_BUILD_VALIDITY=OFF \
  -DPATHLAB_SUBMISSION_OBJECTS=/autograder/source/build-grade/submission-objects
for t in 01-camera-rays 02-intersection 03-bvh 04-direct-lighting 05-path-tracing 06-mirror-glass 07-environment; do
  cmake --build build-grade --parallel "$(nproc)" --target "test-$t"
done
# The grade runs as root in Gradescope's container; the candidate runs as an
# unprivileged uid that must not read the repository (tools/grade also
# makes it private while grading, and checks).
chmod 700 /autograder/source
