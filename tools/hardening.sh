#!/usr/bin/env bash
# The hardening jobs CI runs after the test suite (docs/reliability.md):
#   asan   ASan + UBSan under Clang with libc++ (the macOS toolchain): every
#          test except the grader's own rebuilds, the write-up, the docs
#          checks and the validity matrix (same code as the suites), with
#          three task suites drawn per commit (PATHLAB_ASAN_TASKS=1,5 names
#          them); the other suites' sources are compiled with -fsyntax-only.
#   tsan   TSan: the multithreaded render loop (framework tests), the CLI, the
#          GUI's background workers, and the grader on task 5 (with the same
#          TSan build; the course repository only).
#   fuzz   libFuzzer: each of the five targets for RUNS executions (default
#          2000), with the seed fixed at 1 so the job is repeatable; then the
#          generated adversary (tools/adversary, docs/adversary.md): hostile
#          answers drawn per commit from the judges' wire schema, against
#          the release build's judges (the course repository only).
# Installs clang and its sanitizer runtime if missing (Debian packages).
#   tools/hardening.sh [RUNS] [asan] [tsan] [fuzz]     (no job named: all three)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=2000
jobs=()
for arg in "$@"; do
  case $arg in
    asan|tsan|fuzz) jobs+=("$arg") ;;
    *[!0-9]*|"") echo "usage: tools/hardening.sh [RUNS] [asan] [tsan] [fuzz]" >&2; exit 2 ;;
    *) runs=$arg ;;
  esac
done
((${#jobs[@]})) || jobs=(asan tsan fuzz)
source tools/packages.sh
install_packages "${pathlab_hardening[@]}" "${pathlab_libcxx[@]}"

step() { echo; echo "== $* ($(date +%T))"; }
# The presets (CMakePresets.json) configure, build and test; the build's
# output goes to a log shown only on failure.
# workflow PRESET [CACHE SETTING...]: configure (with the settings), build, test.
workflow() {
  local preset=$1 log="build-$1.log"
  shift
  if ! { cmake --preset "$preset" "$@" && cmake --build --preset "$preset" &&
         CTEST_PARALLEL_LEVEL="$((2 * $(nproc)))" ctest --preset "$preset"; } > "$log" 2>&1; then
    grep -E "Failed|\*\*\*|error:" "$log" | head -40 || true
    tail -40 "$log"
    exit 1
  fi
  sed -n '/^Test project/,$p' "$log" | grep -E "tests passed|Total Test time|Label Time|^ +Start|Passed|Failed" | tail -30
}
for job in "${jobs[@]}"; do
  case $job in
    asan)
      # Three suites per commit, as the aarch64 check draws (each suite and its
      # candidates took 50 s of the build and 25 s of tests under ASan, 09-mis
      # twice that); the framework, the CLI, the GUI and the benchmarks run
      # every time.
      sample=(python3 tools/pathlab_tasks.py sample asan 3 PATHLAB_ASAN_TASKS)
      numbers=$("${sample[@]}" --numbers)  # a bad PATHLAB_ASAN_TASKS stops here
      others=$("${sample[@]}" --others | sed 's|.*|tests/&/|')
      step "ASan + UBSan under Clang with libc++: suites $("${sample[@]}" | paste -sd' ') (PATHLAB_ASAN_TASKS to choose)"
      workflow asan -DPATHLAB_SUITES="$numbers"
      step "the other suites compile under Clang with libc++ (tools/syntax-check)"
      [[ -z $others ]] || tools/syntax-check build-asan $others ;;
    tsan)
      step "TSan: build and tests (cmake --workflow --preset tsan)"
      workflow tsan
      # One task: every judge runs the same render loop (task 5's renders the
      # most); task 1 beside it added 20 s and no code path.
      if [[ -x tools/grade ]]; then  # a student release has no grader and no solutions/
        step "TSan: the grader on the reference, task 5, in the same build (each test case in its own TSan process)"
        tools/grade solutions --tasks 5 --sanitize thread --build-dir build-tsan \
          --out build-tsan/grade-results.json --fail-under 100 --timeout 300
      fi ;;
    fuzz)
      step "fuzzing, $runs executions per target"
      tools/fuzz "$runs" 1  # a fixed seed: the CI run is repeatable
      if [[ -x tools/adversary && -d build/tests ]]; then  # the course repository, after the README's tests
        step "the generated adversary: 4 strategies per task drawn for this commit, 1 graded in each sandbox"
        tools/adversary --build-dir build --sample 4 --seed commit --grade 1
      elif [[ -x tools/adversary ]]; then
        echo "the generated adversary: skipped, no release build in build/ (tools/quickstart.sh test makes it)"
      fi ;;
  esac
done
step "hardening jobs passed: ${jobs[*]}"
