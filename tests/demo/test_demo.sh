#!/usr/bin/env bash
# pathlab-demo as a lecturer runs it: --list, every demo writes its PNG in
# under 20 s and prints numbers that agree with the theory, the -o forms,
# bad input, and the live window under Xvfb.
#   test_demo.sh BUILD_DIR TASK7_VARIANT HAVE_GUI (ON: the build made the window; OFF: it has none)
# env-importance runs task 7's code: its numbers are checked only when the
# build links the reference (in a student release it shows the student's).
set -uo pipefail
demo=$1/pathlab-demo
task7=${2:-reference}
root=$(realpath "$(dirname "$(realpath "${BASH_SOURCE[0]}")")/../..")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect() { awk "BEGIN { exit !($2) }" || fail "$1 ($2)"; }
number() { grep -oE "$2 [-0-9.e+]+" "$1" | head -1 | awk '{print $NF}'; }  # number after a phrase

names=$("$demo" --list | awk '{print $1}')
[[ $(echo "$names" | wc -l) == 8 ]] || fail "--list: expected 8 demos, got: $names"
for name in pdf-cdf discrete annulus hemisphere pi rendering-equation env-importance sequences; do
  echo "$names" | grep -qx "$name" || fail "--list lacks $name"
done

# Every demo: a PNG of a sensible size, numbers, under 20 s. The demos use
# fixed seeds, so the checks below are deterministic. The bounds were swept
# over seeds 1-61 (--set seed=N, 57 seeds): all held at every seed except
# the chi-square's 0.1 % critical value, which seed 8 exceeded (20.77), as
# one seed in a thousand should; the nearest other misses were sample mean
# 0.7696 (bound 0.765), light/exact 0.990 (0.98) and speed-up 507x (100x).
# So a change that only reshuffles the random numbers fails here with
# probability about 0.1 %.
for name in $names; do
  start=$(date +%s.%N)
  if ! "$demo" "$name" -o "$out/" > "$out/$name.txt" 2> "$out/$name.err"; then
    fail "$name exited with $?: $(cat "$out/$name.err")"; continue
  fi
  seconds=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { print e - s }')
  expect "$name took $seconds s" "$seconds < 20"
  [[ -s $out/$name.png ]] || { fail "$name wrote no $out/$name.png"; continue; }
  size=$(stat -c %s "$out/$name.png")
  expect "$name.png is a real figure ($size bytes)" "$size > 20000"
done

# The numbers agree with the theory.
t=$out/pdf-cdf.txt
expect "pdf-cdf: F(2) = 1" "$(number "$t" 'F\(2\) =') > 0.999999999 && $(number "$t" 'F\(2\) =') < 1.000000001"
expect "pdf-cdf: sample mean near 0.7733" "$(number "$t" 'sample mean') > 0.765 && $(number "$t" 'sample mean') < 0.782"
t=$out/discrete.txt
expect "discrete: chi-square below the 0.1% critical value 20.5" "$(number "$t" 'chi-square') < 20.5"
t=$out/annulus.txt
expect "annulus: the square-root mapping is uniform" "$(number "$t" 'square-root mapping:') > 0.9 && $(number "$t" 'square-root mapping:') < 1.1"
expect "annulus: the naive mapping crowds the inside" "$(number "$t" 'naive mapping:') > 2.5"
t=$out/hemisphere.txt
expect "hemisphere: uniform mean cos near 1/2" "$(number "$t" 'uniform') > 0.48 && $(number "$t" 'uniform') < 0.52"
expect "hemisphere: cosine mean cos near 2/3" "$(number "$t" 'cosine') > 0.65 && $(number "$t" 'cosine') < 0.685"
t=$out/pi.txt
expect "pi: estimate within 0.02" "$(number "$t" 'estimate') > 3.12 && $(number "$t" 'estimate') < 3.16"
t=$out/rendering-equation.txt
exact=$(number "$t" 'area\) =|angle\) =')
light=$(grep "light (area)" "$t" | grep -oE "mean [0-9.]+" | awk '{print $2}')
expect "rendering-equation: light sampling agrees with the exact value ($light vs $exact)" "$light / $exact > 0.98 && $light / $exact < 1.02"
expect "rendering-equation: light sampling beats uniform by > 100x" "$(grep -oE 'needs [0-9.e+]+x' "$t" | awk '{print $2}' | tr -d x) > 100"
t=$out/sequences.txt  # slopes over seeds 1-20: -0.52..-0.47, -1.04..-0.98, -1.51..-1.45
expect "sequences: independent points converge as 1/sqrt(N)" "$(number "$t" 'independent: RMS error [0-9.e-]+ at N = [0-9]+, slope of log error against log N') > -0.6 && $(number "$t" 'independent: RMS error [0-9.e-]+ at N = [0-9]+, slope of log error against log N') < -0.4"
expect "sequences: jittered points as 1/N" "$(grep stratified "$t" | grep -oE 'log N -?[0-9.]+' | awk '{print $3}') < -0.9"
expect "sequences: Sobol points as N^-1.5" "$(grep Sobol "$t" | grep -oE 'log N -?[0-9.]+' | awk '{print $3}') < -1.35"
t=$out/env-importance.txt
if [[ $task7 == reference ]]; then
grep -q "hold [0-9.]*% of the PMF and received [0-9.]*% of the samples" "$t" || fail "env-importance: no share line"
pmf=$(grep -oE "hold [0-9.]+" "$t" | awk '{print $2}'); got=$(grep -oE "received [0-9.]+" "$t" | awk '{print $2}')
expect "env-importance: samples follow the PMF ($got% vs $pmf%)" "$got - $pmf < 5 && $pmf - $got < 5"
fi

# -o forms: a file, a prefix.
"$demo" pi -o "$out/custom.png" > /dev/null && [[ -s $out/custom.png ]] || fail "-o FILE.png"
"$demo" pi -o "$out/lecture3-" > /dev/null && [[ -s $out/lecture3-.png ]] || fail "-o PREFIX"
"$demo" pi --set samples=1000 --set runs=5 -o "$out/small.png" > /dev/null || fail "--set"

# Bad input: one line, exit 1.
check_error() {  # check_error EXPECTED ARGS...
  local expected=$1; shift
  "$demo" "$@" > /dev/null 2> "$out/err.txt"; local rc=$?
  [[ $rc == 1 ]] || fail "pathlab-demo $* exited with $rc, expected 1"
  grep -q "$expected" "$out/err.txt" || fail "pathlab-demo $*: expected '$expected' in: $(cat "$out/err.txt")"
}
check_error 'no demo "nope"' nope
check_error "has the parameters" pi --set colour=3
check_error "is not a number" pi --set samples=many
check_error "must be between" pi --set samples=0
check_error "give a demo name" 

# The live window, when this build has one (CMake found GLFW and Dear ImGui);
# a build without them says so clearly.
if [[ $3 == OFF ]]; then
  "$demo" annulus --gui > /dev/null 2> "$out/nogui.err" && fail "--gui succeeded in a build without a window"
  grep -q "this build has no window" "$out/nogui.err" || fail "--gui without a window: $(cat "$out/nogui.err")"
elif command -v Xvfb > /dev/null; then
  # (Mesa's GL driver leaks by LeakSanitizer's count, unloaded before the report: no leak check for the window.)
  if ASAN_OPTIONS=detect_leaks=0 "$root/tools/with-xvfb" "$demo" annulus --gui --screenshot "$out/gui.png" \
      > /dev/null 2> "$out/gui.err"; then
    spread=$(convert "$out/gui.png" -colorspace Gray -format "%[fx:standard_deviation]" info:)
    expect "the demo window is not blank ($spread)" "$spread > 0.05"
  else
    fail "--gui --screenshot: $(cat "$out/gui.err")"
  fi
fi

if ((failures > 0)); then echo "$failures demo check(s) failed"; exit 1; fi
echo "demos: all checks passed"
