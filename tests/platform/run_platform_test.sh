#!/usr/bin/env bash
# Runs test_platform in a scratch folder and checks what it printed to
# stderr: nothing while silenced, something after, and a sanitizer's report
# (in a sanitizer build) even while silenced.
#   run_platform_test.sh [RUNNER...] PROGRAM     RUNNER: wine64, for the Windows build
set -uo pipefail
program=$(realpath "${@: -1}")
runner=("${@:1:$#-1}")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch" || exit 1
"${runner[@]}" "$program" > out.txt 2>&1
code=$?
cat out.txt
if grep -q LEAKED out.txt; then echo "FAIL: stderr was not silenced"; exit 1; fi
grep -q 'stderr restored' out.txt || { echo "FAIL: stderr was not restored"; exit 1; }
if grep -q "a sanitizer's report is expected" out.txt && ! grep -q 'SANITIZER REPORT WHILE SILENCED' out.txt; then
  echo "FAIL: a sanitizer's report raised while stderr was silenced did not reach stderr"; exit 1
fi
exit $code
