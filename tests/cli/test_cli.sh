#!/usr/bin/env bash
# End-to-end checks of the `pathlab` command line, as a user runs it.
# usage: test_cli.sh PATHLAB PATHLAB_STUBS INPUTS_DIR
# PATHLAB links the configured tasks, PATHLAB_STUBS every task from the
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
for n in $(seq "$task_count"); do task_undone "$n" && undone+=("$n"); done
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
"$pathlab" -q -s 2 -d 64x48 -o "$work/stats2.png" --stats "$work/stats.json" &&
  python3 -c 'import json, sys; j = json.load(open(sys.argv[1]))
assert (j["width"], j["height"], j["spp"], j["samples"], j["non_finite_samples"]) == (64, 48, 2, 64 * 48 * 2, 0), j
assert j["samples_per_second"] > 0 and j["rays"] >= 0 and j["tasks"].startswith("1:"), j' "$work/stats.json" &&
  pass || fail "--stats does not write the render's numbers as JSON"
# Every scene shipped in media/scenes loads and renders (tiny, 1 spp): a scene nobody ran is a broken handout.
for scene in "$root"/media/scenes/*.json; do
  "$pathlab" -q -s 1 -d 16x12 -o "$work/scene.png" "$scene" 2>"$work/scene.err" && [[ -s $work/scene.png ]] \
    && pass || fail "media/scenes/$(basename "$scene") does not render: $(grep -v '^task [0-9]* not implemented' "$work/scene.err")"
done
out=$("$pathlab" -q -s 2 -d 64x48 -o "$work/again.exr" --ref "$work/one.exr" 2>&1)
grep -q "RMSE" <<< "$out" && grep -q "relMSE" <<< "$out" && pass || fail "--ref does not print RMSE and relMSE: $out"
out=$("$pathlab" -q -s 1 -d 32x24 --integrator normals -o "$work/normals.png" 2>&1) && pass || fail "normals integrator: $out"
"$pathlab" --help > "$work/help.txt" && grep -q -- "--seed" "$work/help.txt" && pass || fail "--help"

# The image codec (OpenImageIO and the libraries it brings) loads only when an
# image is read or written (framework/util/image.cpp): not at every start.
if command -v readelf > /dev/null && readelf -h "$pathlab" > /dev/null 2>&1; then
  ! readelf -d "$pathlab" | grep -q "NEEDED.*OpenImageIO" && pass || fail "pathlab links OpenImageIO at start"
fi
out=$(PATHLAB_IMAGE_CODEC="$work/no-such-codec.so" "$pathlab" -q -s 1 -d 8x8 -o "$work/no-codec.png" 2>&1)
rc=$?
out=$(grep -v '^task [0-9]' <<< "$out")  # a student build's notes on undone tasks come first
[[ $rc -eq 1 && $(wc -l <<< "$out") -eq 1 && $out == *"image codec"*"no-such-codec.so"* ]] && pass ||
  fail "a codec that does not load: exit $rc, expected 1 and one line naming it: $out"

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
# Every case within 10 s of CPU time (prlimit --cpu: a busy CI machine does
# not make it flaky) and 60 s of wall time (a hang that uses no CPU, like a
# blocked read), and, without sanitizers, 1 GB of address space
# (PATHLAB_CATALOG_MEMORY_LIMIT, bytes; set by CTest). Inputs named
# generated/NAME are written at test time by tests/inputs/generate.py.
cd "$work" || exit 1
mkdir a-folder
python3 "$inputs/generate.py" "$work/generated" || fail "tests/inputs/generate.py"
limit=()
if [[ -n ${PATHLAB_CATALOG_MEMORY_LIMIT:-} ]]; then
  limit=(--as="$PATHLAB_CATALOG_MEMORY_LIMIT")
  export MALLOC_ARENA_MAX=2  # glibc reserves 64 MB of address space per thread's arena otherwise
fi
# bad_input NAME EXPECTED_FRAGMENT ARGS...: exit 1, one stderr line holding the fragment, in time.
bad_input() {
  local name=$1 fragment=$2 rc lines
  shift 2
  timeout -s KILL 60 prlimit --cpu=10:11 "${limit[@]}" "$pathlab" -q -s 1 -d 16x12 -o "$work/bad.png" "$@" >/dev/null 2>"$work/err.txt"
  rc=$?
  lines=$(wc -l < "$work/err.txt")
  if [[ $rc -eq 137 ]]; then
    fail "$name: killed after 60 s of wall time (a hang) or 11 s of CPU"
  elif [[ $rc -eq 152 ]]; then
    fail "$name: more than 10 s of CPU time (killed)"
  elif [[ $rc -ne 1 ]]; then
    fail "$name: exit code $rc, expected 1: $(head -3 "$work/err.txt")"
  elif [[ $lines -ne 1 ]]; then
    fail "$name: $lines lines on stderr, expected 1: $(head -3 "$work/err.txt" | cut -c1-300)"
  elif (( $(wc -c < "$work/err.txt") > 1100 )); then
    fail "$name: an error line of $(wc -c < "$work/err.txt") bytes (user text must be capped)"
  elif LC_ALL=C grep -q $'\x1b' "$work/err.txt"; then
    fail "$name: a raw escape character on stderr"
  elif ! grep -qF -- "$fragment" "$work/err.txt"; then
    fail "$name: error lacks \"$fragment\": $(cut -c1-300 "$work/err.txt")"
  elif [[ -e $work/bad.png ]] || ls -a "$work" | grep -q '^\.bad\.partial'; then
    fail "$name: an output file was left behind"; rm -f "$work/bad.png" "$work"/.bad.partial.*
  else
    pass; return 0
  fi
  return 1
}
while IFS='|' read -r file flags fragment; do
  [[ -z $file || $file == \#* ]] && continue
  file=$(xargs <<< "$file")
  flags=$(xargs <<< "$flags")
  fragment=$(sed 's/^ *//; s/ *$//' <<< "$fragment")
  args=()
  if [[ $file == generated/* ]]; then args+=("$work/$file"); elif [[ $file != - ]]; then args+=("$inputs/$file"); fi
  # shellcheck disable=SC2206
  [[ -n $flags ]] && args+=($flags)
  if bad_input "$file $flags" "$fragment" "${args[@]}" && [[ $file != - ]] && ! grep -qF -- "$file" "$work/err.txt"; then
    fail "$file: error does not name the file: $(cut -c1-300 "$work/err.txt")"
  fi
done < "$inputs/catalog.txt"
bad_input "a folder as scene" "is a folder" a-folder

# --- the operating system's odd files ---------------------------------------
g=$work/generated
mkfifo "$g/pipe.json" "$g/pipe.obj" "$g/pipe.exr" "$g/pipe.mtl"
for name in loop.json loop.obj loop.exr loop.png; do ln -s "$name" "$g/$name"; done
printf '{"meshes": [{"obj": "%s"}]}' pipe.obj > "$g/obj-pipe.json"
printf '{"meshes": [{"obj": "%s"}]}' /dev/zero > "$g/obj-zero.json"
printf '{"meshes": [{"obj": "%s"}]}' loop.obj > "$g/obj-loop.json"
printf '{"environment": {"image": "%s"}}' pipe.exr > "$g/map-pipe.json"
printf '{"environment": {"image": "%s"}}' loop.exr > "$g/map-loop.json"
long=$(printf 'n%.0s' $(seq 300))
bad_input "a FIFO as scene" "is a FIFO" "$g/pipe.json"
bad_input "/dev/zero as scene" "is a device" /dev/zero
bad_input "a FIFO as OBJ" "is a FIFO" "$g/obj-pipe.json"
bad_input "/dev/zero as OBJ" "is a device" "$g/obj-zero.json"
bad_input "a FIFO as environment map" "is a FIFO" "$g/map-pipe.json"
bad_input "a symlink loop as scene" "Too many levels of symbolic links" "$g/loop.json"
bad_input "a symlink loop as OBJ" "Too many levels of symbolic links" "$g/obj-loop.json"
bad_input "a symlink loop as environment map" "Too many levels of symbolic links" "$g/map-loop.json"
bad_input "a symlink loop as output" "Too many levels of symbolic links" -o "$g/loop.png"
bad_input "a 300-character scene name" "File name too long" "$g/$long.json"
bad_input "a 300-character output name" "too long" -o "$work/$long.png"
bad_input "--seed -1" "--seed: expected an integer" --seed -1
bad_input "-d with an empty value" "-d: expected WIDTHxHEIGHT" -d ""
bad_input "--spp-map with an empty value" "--spp-map: expected an output file name" --adaptive 0.1 --spp-map ""
bad_input "--stats with an empty value" "--stats: expected an output file name" --stats ""
bad_input "--ref with an empty value" "--ref: expected an image file name" --ref ""
# Two names of one file (a hard link): the render would overwrite its own reference.
"$pathlab" -q -s 1 -d 16x12 -o "$work/linked.exr" 2>/dev/null && ln "$work/linked.exr" "$work/link-of-linked.exr"
bad_input "--ref a hard link of -o" "-o and --ref name the same file" --ref "$work/link-of-linked.exr" -o "$work/linked.exr"
"$pathlab" -q -s 1 -d 20x10 -o "$work/small.exr" 2>/dev/null
bad_input "--ref of another size (before rendering: no output)" "--ref: " --ref "$work/small.exr"
bad_input "--stats in a missing folder (before rendering)" "--stats " --stats "$work/no-such-folder/stats.json"
# An OBJ naming a FIFO as its mtllib: materials come from the scene, the library is never opened.
printf 'mtllib pipe.mtl\nv -1 -1 -3\nv 1 -1 -3\nv 0 1 -3\nf 1 2 3\n' > "$g/mtl-pipe.obj"
printf '{"meshes": [{"obj": "mtl-pipe.obj"}]}' > "$g/mtl-pipe.json"
timeout -s KILL 60 prlimit --cpu=10:11 "$pathlab" -q -s 1 -d 16x12 -o "$work/mtl.png" "$g/mtl-pipe.json" 2>"$work/err.txt" && pass ||
  fail "an OBJ whose mtllib is a FIFO: exit $?, $(cat "$work/err.txt")"

# A read-only folder (as root, whom permissions do not stop, as user nobody
# through setpriv), and a full disk (a 16 KB tmpfs in a private mount namespace:
# root's own, or a user namespace's where the kernel allows one).
mkdir "$work/read-only" && chmod 555 "$work/read-only"
if [[ $(id -u) -ne 0 ]]; then
  bad_input "a read-only output folder" "not writable" -o "$work/read-only/out.png"
elif command -v setpriv >/dev/null && setpriv --reuid=65534 --regid=65534 --clear-groups true 2>/dev/null &&
     setpriv --reuid=65534 --regid=65534 --clear-groups test -x "$pathlab" 2>/dev/null; then
  chmod 755 "$work"
  setpriv --reuid=65534 --regid=65534 --clear-groups "$pathlab" -q -s 1 -d 16x12 -o "$work/read-only/out.png" 2>"$work/err.txt"
  [[ $? -eq 1 ]] && grep -q "not writable" "$work/err.txt" && pass || fail "a read-only output folder (as nobody): $(cat "$work/err.txt")"
else
  echo "skipped: a read-only output folder (running as root, and user nobody cannot run $pathlab)"
fi
if [[ $(id -u) -eq 0 ]]; then namespace=(unshare -m); else namespace=(unshare -rm); fi
if "${namespace[@]}" true 2>/dev/null; then
  for ext in png jpg exr hdr; do
    mkdir -p "$work/full"
    # Filled to the last byte first: even a black image (undone tasks) cannot fit.
    "${namespace[@]}" bash -c 'mount -t tmpfs -o size=16k none "$1" && { dd if=/dev/zero of="$1/fill" bs=4k 2>/dev/null; true; } &&
                               "$2" -q -s 1 -d 300x200 -o "$1/out.'$ext'"; rc=$?; ls -A "$1" > "$3"; exit $rc' \
      _ "$work/full" "$pathlab" "$work/left.txt" 2>"$work/err.txt"
    rc=$?
    grep -vE '^task [0-9]+( not implemented:|: )' "$work/err.txt" > "$work/errors.txt"  # what undone tasks print
    if [[ $rc -eq 1 && $(wc -l < "$work/errors.txt") -eq 1 ]] && grep -q "No space left on device" "$work/errors.txt" &&
       [[ $(cat "$work/left.txt") == fill ]]; then
      pass
    else
      fail "a full disk writing .$ext: exit $rc, left [$(cat "$work/left.txt" 2>/dev/null)], $(head -3 "$work/err.txt")"
    fi
  done
else
  echo "skipped: a full disk (no private mount namespace here: unshare -m needs root or user namespaces)"
fi

# --- legitimate extremes: a correct image, at most one warning ---------------
# (A picture is only right when the tasks drawing it work: the reference, or
# a done student file; "task N not implemented" lines are not warnings.)
linked=$("$pathlab" --version)  # "... (tasks 1:reference 2:student ...)"
task_works() { [[ $linked =~ [\ \(]$1:reference ]] || ! task_undone "$1"; }
if task_works 1 && task_works 2 && task_works 3 && task_works 4; then
  "$pathlab" -q -s 1 -m 1 -d 16x12 -o "$work/sky.exr" "$g/sky-sphere.json" 2>"$work/err.txt" &&
    out=$("$pathlab" -q -s 1 -m 1 -d 16x12 -o "$work/sky2.exr" "$g/sky-sphere.json" --ref "$g/sky-expected.pfm" 2>&1) &&
    [[ $out =~ RMSE\ ([0-9.e+-]+), ]] && awk -v e="${BASH_REMATCH[1]}" 'BEGIN { exit !(e < 1e-4) }' && pass ||
    fail "a sphere of radius 1e9 around the camera, lit from its centre, is not 0.5/pi everywhere: $out $(cat "$work/err.txt")"
  out=$("$pathlab" -q -s 1 -m 1 -d 16x12 -o "$work/transparent.exr" "$g/transparent-sky.json" \
          --ref "$g/transparent-sky-expected.pfm" 2>&1) &&
    [[ $out =~ "alpha channel is ignored" && $out =~ RMSE\ ([0-9.e+-]+), ]] &&
    awk -v e="${BASH_REMATCH[1]}" 'BEGIN { exit !(e < 1e-4) }' && pass ||
    fail "an RGBA environment map with alpha 0 is not its colours, with a warning: $out"
else
  echo "skipped: the sphere of radius 1e9 and the transparent sky (their images need tasks 1-4 done)"
fi
"$pathlab" -q -s 1 -d 16x12 -o "$work/texels.exr" "$g/bad-texels.json" 2>"$work/err.txt"
rc=$?
grep -vE '^task [0-9]+( not implemented:|: )' "$work/err.txt" > "$work/errors.txt"  # what undone tasks print
[[ $rc -eq 0 && $(wc -l < "$work/errors.txt") -eq 1 ]] && grep -q "12 texels are NaN, infinite or negative" "$work/errors.txt" && pass ||
  fail "an environment map with NaN, infinite and negative texels: exit $rc, $(cat "$work/err.txt")"
timeout -s KILL 60 prlimit --cpu=10:11 "$pathlab" -q -s 1 -d 16x12 -o "$work/disc.png" "$g/huge-convex-polygon.json" 2>"$work/err.txt" && pass ||
  fail "a convex polygon of 150,000 vertices: exit $?, $(cat "$work/err.txt")"
if [[ -n ${PATHLAB_CATALOG_MEMORY_LIMIT:-} ]]; then  # (unset under sanitizers, where it would cost minutes and GBs)
  timeout -s KILL 120 prlimit --cpu=30:31 "$pathlab" -q -s 1 -m 1 -d 2x2 -o "$work/lights.png" "$g/million-lights.json" \
    2>"$work/err.txt" && pass || fail "a scene of a million point lights does not load and render in 30 s of CPU: exit $?, $(cat "$work/err.txt")"
else
  echo "skipped under sanitizers: the scene of a million point lights"
fi
"$pathlab" -q -s 1 -d 1x1 -o "$work/one.png" 2>"$work/err.txt" && [[ -s $work/one.png ]] && pass || fail "a 1x1 image: $(cat "$work/err.txt")"

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
