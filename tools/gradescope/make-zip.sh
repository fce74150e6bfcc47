#!/usr/bin/env bash
# Packs the Gradescope autograder: setup.sh and run_autograder at the zip's
# root, the repository's working tree (tools/package-tree: tracked and new
# files, uncommitted edits included, nothing .gitignore ignores) in source/.
#   tools/gradescope/make-zip.sh OUT.zip [--timeout SECONDS] [--tasks 1,2,...]
# --timeout: the autograder timeout set on Gradescope (default 600, its own
# default). Gradescope does not tell the container, so the zip carries it
# (gradescope-timeout) and run_autograder ends the grade in time to write
# results.json before it (docs/ta-guide.md).
# --tasks: the tasks this assignment grades (default 1-7, the core tasks;
# add extension tasks, e.g. 1,2,3,4,5,6,7,8), carried as gradescope-tasks.
set -euo pipefail
usage="usage: make-zip.sh OUT.zip [--timeout SECONDS] [--tasks 1,2,...]"
case ${1:-} in
  -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
  ''|-*) echo "$usage" >&2; exit 2 ;;
esac
out=$(realpath "$1"); shift
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
timeout=600 tasks=$(python3 "$root/tools/pathlab_tasks.py" core)
while (($#)); do
  case $1 in
    --timeout) timeout=${2:?$usage}; shift 2 ;;
    --tasks) tasks=${2:?$usage}; shift 2 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
done
[[ $timeout =~ ^[0-9]+$ ]] && ((timeout >= 180)) || { echo "make-zip.sh: --timeout must be at least 180 seconds, got $timeout" >&2; exit 2; }
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
# The working tree as it is, uncommitted edits and new tasks included (tools/package-tree: every
# packager's one rule); it refuses a task whose folders are not all there.
python3 "$root/tools/package-tree" "$stage/source" --tasks "$tasks" || exit 2
cp "$here/setup.sh" "$here/run_autograder" "$stage/"
echo "$timeout" > "$stage/gradescope-timeout"
echo "$tasks" > "$stage/gradescope-tasks"
chmod +x "$stage/setup.sh" "$stage/run_autograder"
(cd "$stage" && rm -f "$out" && python3 -m zipfile -c "$out" setup.sh run_autograder gradescope-timeout gradescope-tasks source)
echo "wrote $out (tasks $tasks, for a Gradescope timeout of $timeout s)"
