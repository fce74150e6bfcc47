#!/usr/bin/env bash
# The hardening jobs CI runs after the test suite (docs/reliability.md):
#   1. ASan + UBSan: every test except the grader's own rebuilds and the
#      validity matrix (same code as the suites, 65 more builds).
#   2. TSan: the multithreaded render loop (framework tests), the CLI, the
#      GUI's background workers, and the grader on tasks 1 and 5.
#   3. libFuzzer: each of the four targets for RUNS executions (default 2000),
#      with the seed fixed at 1 so the job is repeatable.
# Installs clang and its sanitizer runtime if missing (Debian packages).
#   tools/hardening.sh [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-2000}
source tools/packages.sh
install_packages "${pathlab_hardening[@]}"

step() { echo; echo "== $* ($(date +%T))"; }
step "ASan + UBSan build"
cmake --preset asan > /dev/null
cmake --build --preset asan > build-asan/build.log 2>&1 || { tail -30 build-asan/build.log; exit 1; }
step "ASan + UBSan tests"
ctest --preset asan --parallel "$(nproc)"
step "TSan build"
cmake --preset tsan > /dev/null
cmake --build --preset tsan > build-tsan/build.log 2>&1 || { tail -30 build-tsan/build.log; exit 1; }
step "TSan tests"
ctest --preset tsan --parallel "$(nproc)"
step "TSan: the grader on the reference, tasks 1 and 5 (each test case in its own TSan process)"
tools/grade solutions --tasks 1,5 --sanitize thread --build-dir build-tsan-grade \
  --out build-tsan-grade/results.json --fail-under 100 --timeout 300
step "fuzzing, $runs executions per target"
tools/fuzz "$runs" 1  # a fixed seed: the CI run is repeatable
step "hardening jobs passed"
