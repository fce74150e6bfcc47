#!/usr/bin/env bash
# Packs the Gradescope autograder: setup.sh and run_autograder at the zip's
# root, the repository (tracked files, without build folders) in source/.
#   tools/gradescope/make-zip.sh OUT.zip
set -euo pipefail
out=$(realpath "${1:?usage: make-zip.sh OUT.zip}")
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/source"
git -C "$root" archive HEAD | tar -x -C "$stage/source"
cp "$here/setup.sh" "$here/run_autograder" "$stage/"
chmod +x "$stage/setup.sh" "$stage/run_autograder"
(cd "$stage" && rm -f "$out" && python3 -m zipfile -c "$out" setup.sh run_autograder source)
echo "wrote $out"
