#!/usr/bin/env bash
# The portability jobs (docs/setup.md, "What is proved where"); CI runs the
# aarch64 one after the hardening jobs:
#   clang-libcxx   Clang with libc++, the macOS toolchain, optimised: configure,
#                  build and test with the clang-libcxx preset (every test but
#                  the grader's and the write-up's). Not in CI, whose asan
#                  stage builds with the same toolchain (tools/hardening.sh).
#   aarch64        AArch64, Apple Silicon's instruction set: tools/aarch64-check
#                  --quick (cross-built, 3 suites drawn per commit and the framework tests under
#                  qemu-user, --accel fast images equal to --accel task3).
# The Windows check (tools/windows-check) is not part of CI: see docs/setup.md.
#   tools/portability.sh [clang-libcxx] [aarch64]     (no job named: both)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=()
for arg in "$@"; do
  case $arg in
    clang-libcxx|aarch64) jobs+=("$arg") ;;
    *) echo "usage: tools/portability.sh [clang-libcxx] [aarch64]" >&2; exit 2 ;;
  esac
done
((${#jobs[@]})) || jobs=(clang-libcxx aarch64)
source tools/packages.sh
install_packages "${pathlab_build[@]}" "${pathlab_test[@]}" "${pathlab_libcxx[@]}"
step() { echo; echo "== $* ($(date +%T))"; }

for job in "${jobs[@]}"; do
  case $job in
    clang-libcxx)
      step "Clang + libc++: build and tests (cmake --workflow --preset clang-libcxx)"
      log=build-clang-libcxx.log
      if ! CTEST_PARALLEL_LEVEL="$((2 * $(nproc)))" cmake --workflow --preset clang-libcxx > "$log" 2>&1; then
        grep -E "Failed|\*\*\*|error:" "$log" | head -40 || true
        tail -40 "$log"
        exit 1
      fi
      sed -n '/^Test project/,$p' "$log" | grep -E "tests passed|Total Test time" | tail -3 ;;
    aarch64)
      step "AArch64 under qemu-user (tools/aarch64-check --quick)"
      tools/aarch64-check --quick ;;
  esac
done
step "portability jobs passed: ${jobs[*]}"
