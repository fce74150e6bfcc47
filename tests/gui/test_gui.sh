#!/usr/bin/env bash
# The GUI under Xvfb, as CI runs it: a scripted session (panel switches, a
# click, an orbit of a panel's 3D view, screenshots) on the configured build
# (the reference in the course repository), every panel on the student files
# (pathlab-gui-stubs), and the errors a user can cause.
#   test_gui.sh BUILD_DIR
# It holds for any mix of done and undone tasks (in a student release both
# programs run the student's code): what needs a task's code is checked only
# when that task is done, and the TODO lines only for undone tasks.
set -uo pipefail
build=$(realpath "$1")
gui=$build/pathlab-gui
stubs=$build/pathlab-gui-stubs
root=$(realpath "$(dirname "$(realpath "${BASH_SOURCE[0]}")")/../..")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

source "$root/tests/support/student_tasks.sh"
# done_in PROGRAM N...: every task N runs finished code in PROGRAM: the
# reference, or a student file without TODOs (`--version` says which is linked).
done_in() {
  local program=$1 summary n; shift
  summary=$(env -u DISPLAY "$program" --version)
  for n in "$@"; do
    grep -q " $n:reference" <<< " ${summary#*(tasks }" && continue
    task_undone "$n" && return 1
  done
  return 0
}
undone=()
for n in $(seq "$task_count"); do task_undone "$n" && undone+=("$n"); done
echo "$(env -u DISPLAY "$gui" --version); student files still undone (PATHLAB_TODO left): ${undone[*]:-none}"

# check_todo_lines STDERR_FILE WHAT: every "task N not implemented: FILE:LINE
# (TODO TN.k)" line names task N's student file and a line of it that calls
# PATHLAB_TODO("TN.k"), so only undone tasks print one.
check_todo_lines() {
  local line n file number tag
  while IFS= read -r line; do
    if [[ ! $line =~ ^task\ ([0-9]+)\ not\ implemented:\ (.+):([0-9]+)\ \(TODO\ (T([0-9]+)\.[0-9]+)\)$ ]]; then
      fail "$2: malformed TODO line: $line"; continue
    fi
    n=${BASH_REMATCH[1]} file=${BASH_REMATCH[2]} number=${BASH_REMATCH[3]} tag=${BASH_REMATCH[4]}
    if [[ ${BASH_REMATCH[5]} != "$n" || $file != "$(shown_as "$n")" ]] ||
       ! sed -n "${number}p" "$(task_file "$n")" | grep -qF "PATHLAB_TODO(\"$tag\")"; then
      fail "$2: \"$line\" does not point at a PATHLAB_TODO of task $n's file $(shown_as "$n")"
    fi
  done < <(grep -E '^task [0-9]+ not implemented:' "$1")
}

command -v Xvfb > /dev/null || { echo "Xvfb is missing: apt-get install xvfb"; exit 1; }
command -v convert > /dev/null || { echo "ImageMagick is missing: apt-get install imagemagick"; exit 1; }
# Each run on its own display (xvfb-run -a's displays raced under a loaded CI).
xrun() { "$root/tools/with-xvfb" "$@"; }

# Standard deviation of an image's grey levels, 0..1: a blank window is ~0.
spread() { convert "$1" -colorspace Gray -format "%[fx:standard_deviation]" info:; }
# Fraction of pixels that differ between two images of the same size.
differ() { compare -metric AE -fuzz 2% "$1" "$2" null: 2>&1 | awk -v n="$3" '{ printf "%.4f", $1 / n }'; }
expect() {  # expect DESCRIPTION CONDITION(awk)
  awk "BEGIN { exit !($2) }" || fail "$1 ($2)"
}

# 1. A scripted session on the configured build.
cat > "$out/session.txt" << 'SCRIPT'
# panel 1, click a pixel on the left sphere, then task 5's paths seen from the side
panel 1
wait
screenshot OUT/panel1.png
panels
click 140 200
panel 5
view paths
wait-panel
screenshot OUT/paths-front.png
view-orbit 50 20
wait-panel
screenshot OUT/paths-side.png
lab cosine-hemisphere
wait-panel
screenshot OUT/lab.png
lab annulus
lab-set mistake 1
wait-panel
screenshot OUT/lab-mistake.png
lab environment
lab-map ROOT/media/envmaps/sky-sun.exr
wait-panel
screenshot OUT/lab-map.png
lab-map ROOT/no-such-map.exr
wait-panel
quit
SCRIPT
# First, every warp of the lab with every default, as a user first sees it: ACCEPTED.
# PATHLAB_GUI_LAB_WARPS=N: N warps drawn by the commit (the sanitizer builds:
# one worker thread serves every warp alike, each warp's sampling runs 3 to 10
# times slower, and the release build's run checks every warp's verdict).
warps=$("$build/pathlab" lab --list | awk '{print $1}')
if [[ -n ${PATHLAB_GUI_LAB_WARPS:-} ]]; then
  warps=$(python3 "$root/tools/pathlab_tasks.py" draw gui-warps "$PATHLAB_GUI_LAB_WARPS" <<< "$warps") ||
    { echo "FAIL: PATHLAB_GUI_LAB_WARPS=$PATHLAB_GUI_LAB_WARPS: not a number"; exit 1; }
  echo "the lab's warps drawn by the commit (PATHLAB_GUI_LAB_WARPS=$PATHLAB_GUI_LAB_WARPS):" $warps
fi
{ for warp in $warps; do printf 'lab %s\nwait-panel\nlab-verdict\n' "$warp"; done; cat "$out/session.txt"; } \
  > "$out/session.all" && mv "$out/session.all" "$out/session.txt"
sed -i "s|OUT|$out|g; s|ROOT|$root|g" "$out/session.txt"
if ! xrun "$gui" --script "$out/session.txt" --timeout 300 > "$out/session.log" 2> "$out/session.err"; then
  fail "scripted session exited with $?"; cat "$out/session.err"
fi
grep -q "click 140 200 -> pixel 140,200: 16 samples" "$out/session.log" || fail "the click was not inspected"
# The panel buttons: one per task and the lab's, none cut by the window's
# edge, each labelled with its number and task.json's label.
panels=$(grep "^script: panels -> " "$out/session.log")
count=$task_count
[[ $panels == *" -> $((count + 1)) buttons in "*" rows, 0 cut: "* ]] ||
  fail "the panel buttons are not one per task and the lab, all whole: $panels"
for ((n = 1; n <= count; ++n)); do
  label=$(python3 "$root/tools/pathlab_tasks.py" manifest "$n" label)
  [[ $panels == *": $n $label"* || $panels == *"| $n $label"* ]] || fail "no whole button \"$n $label\": $panels"
done
# A warp that runs a task's routine (lab --list's second column: T<n>...)
# is ACCEPTED by default once that task is done, and the tasks it also runs
# ("(also runs tasks 2, 3)" ending its line): a student release's stubs are
# rejected, rightly. The seed warps are the framework's own.
while read -r warp tag rest; do
  grep -qx "$warp" <<< "$warps" || continue
  n=${tag#T} n=${n%%.*}
  also=()
  [[ $rest =~ \(also\ runs\ tasks?\ ([0-9, ]+)\)$ ]] && read -ra also <<< "${BASH_REMATCH[1]//,/ }"
  if [[ $tag == T* ]] && ! done_in "$gui" "$n" ${also[@]+"${also[@]}"}; then
    echo "skipped: the lab's $warp runs task${also[*]:+s} $n${also[*]:+ ${also[*]}}, not all done in $(basename "$gui")"
    continue
  fi
  grep -q "script: lab-verdict -> $warp: ACCEPTED" "$out/session.log" ||
    fail "the lab panel with every default does not show $warp ACCEPTED: $(grep "lab-verdict -> $warp:" "$out/session.log")"
done < <("$build/pathlab" lab --list)
grep -q "no-such-map.exr: cannot open" "$out/session.err" || fail "a missing map file in the lab was not reported"
for f in panel1 paths-front paths-side lab lab-mistake lab-map; do
  [[ -s $out/$f.png ]] || { fail "no screenshot $f.png"; continue; }
  size=$(identify -format "%wx%h" "$out/$f.png")
  [[ $size == 1500x900 ]] || fail "$f.png is $size, not the 1500x900 window"
  s=$(spread "$out/$f.png"); expect "$f.png is not blank (grey-level spread $s)" "$s > 0.08"
done
pixels=$((1500 * 900))
d=$(differ "$out/panel1.png" "$out/paths-front.png" $pixels)
expect "switching panel 1 -> 5 changed the window ($d of the pixels)" "$d > 0.05"
check_todo_lines "$out/session.err" "scripted session"
d=$(differ "$out/paths-side.png" "$out/lab.png" $pixels)
expect "the sampling lab's panel changed the window ($d of the pixels)" "$d > 0.05"
d=$(differ "$out/lab.png" "$out/lab-mistake.png" $pixels)
expect "another warp, with its mistake, redrew the lab ($d of the pixels)" "$d > 0.02"
d=$(differ "$out/lab-mistake.png" "$out/lab-map.png" $pixels)
expect "the environment warp on a map file redrew the lab ($d of the pixels)" "$d > 0.02"
# The paths view draws the clicked pixel's paths: camera rays (task 1), hits
# (task 2) and the path tracer (tasks 4 and 5). On stubs there is next to
# nothing to orbit.
if done_in "$gui" 1 2 4 5; then
  d=$(differ "$out/paths-front.png" "$out/paths-side.png" $pixels)
  expect "orbiting the 3D view redrew the panel ($d of the pixels)" "$d > 0.02"
else
  echo "skipped: orbiting the paths view (tasks 1, 2, 4 and 5 are not all done in $(basename "$gui"))"
fi

# 2. --screenshot, the documented one-liner, on another panel. Not under
# TSan (PATHLAB_TEST_RACES_ONLY=1): the session's panels ran the same render
# worker, and panel 7 took TSan 32 s.
if [[ -z ${PATHLAB_TEST_RACES_ONLY:-} ]]; then
  xrun "$gui" --panel 7 --screenshot "$out/panel7.png" > /dev/null 2> "$out/panel7.err" ||
    fail "--panel 7 --screenshot exited with $?: $(tail -5 "$out/panel7.err")"
  [[ -s $out/panel7.png ]] && { s=$(spread "$out/panel7.png"); expect "panel7.png is not blank ($s)" "$s > 0.08"; }
else
  echo "skipped under TSan (PATHLAB_TEST_RACES_ONLY): --panel 7 --screenshot"
fi

# 3. Every panel on the student files (the untouched stubs in the course
# repository): no crash, the TODOs of undone tasks flagged, none of done ones.
# Each task's panel, with the view that runs most of its student code.
extra_view() {
  case $1 in
    3) echo "view traversal" ;; 4) echo "view shadow-rays" ;; 5) echo "view paths" ;; 8) echo "view curves" ;;
  esac
}
{
  for n in $(seq "$task_count"); do
    echo "panel $n"
    extra_view "$n"
    echo "wait-panel"
  done
  printf '%s\n' "lab environment" "wait-panel" "click 10 10" "wait" "screenshot $out/stubs.png" "quit"
} > "$out/stubs.txt"
if ! xrun "$stubs" --script "$out/stubs.txt" --timeout 300 > "$out/stubs.log" 2> "$out/stubs.err"; then
  fail "the stubs session exited with $?"; tail -5 "$out/stubs.err"
fi
if task_undone 1; then
  grep -q "^task 1 not implemented: $(shown_as 1):" "$out/stubs.err" ||
    fail "task 1 is undone but the stubs session did not report its TODOs: $(tail -5 "$out/stubs.err")"
fi
check_todo_lines "$out/stubs.err" "the stubs session"
[[ -s $out/stubs.png ]] || fail "no screenshot of the stubs session"

# 4. Mistakes get one clear line and exit 1, never a crash or a hang.
check_error() {  # check_error EXPECTED_TEXT ARGS...
  local expected=$1; shift
  xrun "$gui" "$@" > /dev/null 2> "$out/err.txt"; local rc=$?
  [[ $rc == 1 ]] || fail "pathlab-gui $* exited with $rc, expected 1: $(cat "$out/err.txt")"
  grep -q "$expected" "$out/err.txt" || fail "pathlab-gui $*: expected '$expected' in: $(cat "$out/err.txt")"
}
check_error "no-such.json" no-such.json --screenshot "$out/x.png"
printf 'panel 3\nfly 1 2\n' > "$out/bad.txt"
check_error "bad.txt:2: unknown command \"fly\"" --script "$out/bad.txt"
printf 'panel 3\nview nothing\n' > "$out/bad.txt"
check_error "panel 3 has no view \"nothing\"" --script "$out/bad.txt"
printf 'lab no-such-warp\n' > "$out/bad.txt"
check_error 'the lab has no warp "no-such-warp"' --script "$out/bad.txt"
printf 'lab glass\nlab-set colour 2\n' > "$out/bad.txt"
check_error 'the warp has no parameter "colour"' --script "$out/bad.txt"
printf 'panel 2\nclick 10 ten\n' > "$out/bad.txt"
check_error 'bad.txt:2: click: "ten" is not a number' --script "$out/bad.txt"
printf 'click 5000 1\n' > "$out/bad.txt"
check_error "click: pixel outside the image" --script "$out/bad.txt"
check_error "use a .png file" --screenshot "$out/x.txt"
printf 'wait-spp 100000\n' > "$out/slow.txt"
check_error "did not finish within 3 s" --script "$out/slow.txt" --timeout 3 -t 1
env -u DISPLAY "$gui" --screenshot "$out/x.png" > /dev/null 2> "$out/err.txt"; rc=$?
[[ $rc == 1 ]] && grep -q "cannot open a window" "$out/err.txt" || fail "no display: exit $rc, $(cat "$out/err.txt")"

if ((failures > 0)); then echo "$failures GUI check(s) failed"; exit 1; fi
echo "GUI: all checks passed"
