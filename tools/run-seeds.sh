#!/usr/bin/env bash
# Runs a test suite under many seeds (PATHLAB_TEST_SEED=1..N) and counts the
# runs in which any test case failed: the measured false-failure rate of the
# suite's statistical checks on the reference.
#   tools/run-seeds.sh build/tests/test-05-path-tracing 100
set -u
suite=$1
runs=${2:-100}
failed=0
for seed in $(seq 1 "$runs"); do
  if ! PATHLAB_TEST_SEED=$seed "$suite" > /tmp/run-seeds.$$ 2>&1; then
    failed=$((failed + 1))
    echo "seed $seed failed:"
    grep -E "ERROR|HINT" /tmp/run-seeds.$$ | head -5
  fi
done
rm -f /tmp/run-seeds.$$
echo "$(basename "$suite"): $((runs - failed)) of $runs seeds passed"
[[ $failed -eq 0 ]]
