#!/usr/bin/env bash
# End-to-end checks of the `pathlab` command line, as a user runs it.
# usage: test_cli.sh PATHLAB PATHLAB_ALL_STUBS INPUTS_DIR
# PATHLAB links the configured tasks, PATHLAB_ALL_STUBS every task from the
# student files (tasks/). Nothing here depends on which tasks are done: in
# the course repository the student files are the untouched stubs, in a
# student release they are the student's work, any mix of done and undone.
set -u
pathlab=$(realpath "$1")
stubs=$(realpath "$2")
inputs=$(realpath "$3")
root=$(realpath "$(dirname "$(realpath "${BASH_SOURCE[0]}")")/../..")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }

build=$(dirname "$pathlab")
source "$root/tests/support/student_tasks.sh"
undone=()
for n in 1 2 3 4 5 6 7; do task_undone $n && undone+=("$n"); done
echo "$("$pathlab" --version); student files still undone (PATHLAB_TODO left): ${undone[*]:-none}"

# check_todo_lines STDERR_FILE WHAT: every "task N not implemented: FILE:LINE
# (TODO TN.k)" line names task N's student file and a line of it that calls
# PATHLAB_TODO("TN.k"), so only undone tasks print one.
check_todo_lines() {
  local line n file number tag ok=1
  while IFS= read -r line; do
    if [[ ! $line =~ ^task\ ([0-9]+)\ not\ implemented:\ (.+):([0-9]+)\ \(TODO\ (T([0-9]+)\.[0-9]+)\)$ ]]; then
      fail "$2: malformed TODO line: $line"; ok=0; continue
    fi
    n=${BASH_REMATCH[1]} file=${BASH_REMATCH[2]} number=${BASH_REMATCH[3]} tag=${BASH_REMATCH[4]}
    if [[ ${BASH_REMATCH[5]} != "$n" || $file != "$(shown_as "$n")" ]] ||
       ! sed -n "${number}p" "$(task_file "$n")" | grep -qF "PATHLAB_TODO(\"$tag\")"; then
      fail "$2: \"$line\" does not point at a PATHLAB_TODO of task $n's file $(shown_as "$n")"; ok=0
    fi
  done < <(grep -E '^task [0-9]+ not implemented:' "$1")
  ((ok)) && pass
}

# --- renders -------------------------------------------------------------
"$pathlab" -q -s 2 -d 80x60 -o "$work/default.png" 2>"$work/default.err" && [[ -s $work/default.png ]] \
  && pass || fail "default scene does not render to PNG: $(cat "$work/default.err")"
check_todo_lines "$work/default.err" "default render"
# (files differ in their DateTime stamp, so compare pixels: any bit changed gives RMSE > 0)
"$pathlab" -q -s 3 -r 64 48 -t 1 --seed 5 -o "$work/one.exr"
out=$("$pathlab" -q -s 3 -r 64 48 -t 2 --seed 5 -o "$work/two.exr" --ref "$work/one.exr" 2>/dev/null)
grep -q "RMSE 0, relMSE 0$" <<< "$out" && pass || fail "1-thread and 2-thread EXR renders differ: $out"
out=$("$pathlab" -s 2 -d 64x48 -o "$work/stats.png" 2>/dev/null)
grep -q "samples/s" <<< "$out" && grep -q "rays/s" <<< "$out" && pass || fail "render summary lacks samples/s and rays/s: $out"
out=$("$pathlab" -q -s 2 -d 64x48 -o "$work/again.exr" --ref "$work/one.exr" 2>&1)
grep -q "RMSE" <<< "$out" && grep -q "relMSE" <<< "$out" && pass || fail "--ref does not print RMSE and relMSE: $out"
out=$("$pathlab" -q -s 1 -d 32x24 --integrator normals -o "$work/normals.png" 2>&1) && pass || fail "normals integrator: $out"
"$pathlab" --help > "$work/help.txt" && grep -q -- "--seed" "$work/help.txt" && pass || fail "--help"

# Every task on the student files: still renders and exits 0, and says which
# TODOs are missing: task 1's (every render reaches it) when its file is
# undone, and none of a done task.
"$stubs" -q -s 1 -d 32x24 -o "$work/stubs.png" >/dev/null 2>"$work/stubs.err"
rc=$?
[[ $rc -eq 0 && -s $work/stubs.png ]] && pass || fail "all-stubs render: exit $rc: $(cat "$work/stubs.err")"
if task_undone 1; then
  grep -q "^task 1 not implemented: $(shown_as 1):" "$work/stubs.err" && pass ||
    fail "all-stubs render: task 1 is undone but no \"task 1 not implemented: $(shown_as 1):\" line: $(cat "$work/stubs.err")"
fi
check_todo_lines "$work/stubs.err" "all-stubs render"
"$stubs" debug --task 2 --view normals -d 32x24 -o "$work/stub-normals.png" >/dev/null 2>"$work/stub-view.err" && pass ||
  fail "all-stubs debug view: $(cat "$work/stub-view.err")"
check_todo_lines "$work/stub-view.err" "all-stubs debug view"

# Ctrl-C (SIGINT) and SIGTERM write the image rendered so far and exit 130;
# the file carries the samples per pixel reached, and the temporary file it
# was written through is gone (written, then renamed).
interrupt() {  # interrupt SIGNAL NAME: a long render to NAME.exr, stopped once it catches SIGNAL
  "$pathlab" -s 1000000 -d 160x120 -o "$work/$2.exr" >/dev/null 2>"$work/$2.err" &
  local pid=$! number mask
  number=$(kill -l "$1")
  # Wait (up to 30 s on a loaded machine) until the handler is installed:
  # bit SIGNAL-1 of SigCgt in /proc; then a second of rendering.
  for _ in $(seq 300); do
    mask=$(awk '/^SigCgt:/ {print $2}' "/proc/$pid/status" 2>/dev/null) || break
    [[ -n $mask ]] && (( (0x$mask >> (number - 1)) & 1 )) && break
    sleep 0.1
  done
  sleep 1
  kill -"$1" $pid
  wait $pid
}
for signal in INT TERM; do
  interrupt $signal "stopped-$signal"
  rc=$?
  [[ $rc -eq 130 && -s $work/stopped-$signal.exr ]] && grep -q "interrupted" "$work/stopped-$signal.err" &&
    grep -aq "pathlab:spp" "$work/stopped-$signal.exr" && pass || fail "SIG$signal: exit $rc, $(cat "$work/stopped-$signal.err")"
done
ls -a "$work" | grep -q '^\..*\.partial\.' && fail "a temporary .partial file was left behind: $(ls -a "$work")" || pass

# --- debugger views --------------------------------------------------------
views=$("$pathlab" debug --list | awk '{print $2 " " $4}')
[[ $(wc -l <<< "$views") -ge 5 ]] && pass || fail "debug --list: $views"
while read -r task view; do
  "$pathlab" debug --task "$task" --view "$view" -d 64x48 -o "$work/view-$task-$view.png" >/dev/null \
    && [[ -s $work/view-$task-$view.png ]] && pass || fail "debug --task $task --view $view"
done <<< "$views"
err=$("$pathlab" debug --task 2 --view nope 2>&1 >/dev/null)
[[ $? -eq 1 ]] && grep -q "views: normals" <<< "$err" && pass || fail "unknown view: $err"

# --- bad input: one line on stderr naming the problem, exit code 1 --------
cd "$work" || exit 1
mkdir a-folder
while IFS='|' read -r file flags fragment; do
  [[ -z $file || $file == \#* ]] && continue
  file=$(xargs <<< "$file")
  flags=$(xargs <<< "$flags")
  fragment=$(sed 's/^ *//; s/ *$//' <<< "$fragment")
  args=()
  [[ $file != - ]] && args+=("$inputs/$file")
  # shellcheck disable=SC2206
  [[ -n $flags ]] && args+=($flags)
  timeout 20 "$pathlab" -q -s 1 -d 16x12 "${args[@]}" >/dev/null 2>"$work/err.txt"
  rc=$?
  lines=$(wc -l < "$work/err.txt")
  if [[ $rc -ne 1 ]]; then
    fail "$file $flags: exit code $rc, expected 1: $(head -3 "$work/err.txt")"
  elif [[ $lines -ne 1 ]]; then
    fail "$file $flags: $lines lines on stderr, expected 1: $(head -3 "$work/err.txt")"
  elif ! grep -qF -- "$fragment" "$work/err.txt"; then
    fail "$file $flags: error lacks \"$fragment\": $(cat "$work/err.txt")"
  elif [[ $file != - ]] && ! grep -qF -- "$file" "$work/err.txt"; then
    fail "$file: error does not name the file: $(cat "$work/err.txt")"
  else
    pass
  fi
done < "$inputs/catalog.txt"
"$pathlab" -q a-folder 2>"$work/err.txt"
[[ $? -eq 1 ]] && grep -q "is a directory" "$work/err.txt" && pass || fail "a folder as scene: $(cat "$work/err.txt")"

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
