#!/usr/bin/env bash
# Gradescope autograder set-up (runs once when the image is built).
# The zip made by tools/gradescope/make-zip.sh holds this file, run_autograder
# and the PathLab tree in source/.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends build-essential cmake ninja-build pkg-config python3 \
  libglm-dev libopenimageio-dev doctest-dev nlohmann-json3-dev libtinyobjloader-dev libcli11-dev libpugixml-dev
# Build the framework and the reference once; grading rebuilds only the student's files.
cd /autograder/source
cmake -S . -B build-grade -G Ninja -DCMAKE_BUILD_TYPE=Release -DPATHLAB_TASKS=student
cmake --build build-grade --parallel "$(nproc)" --target pathlab_framework pathlab_test_support
