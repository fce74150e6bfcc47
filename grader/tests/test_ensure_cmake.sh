#!/usr/bin/env bash
# tools/ensure-cmake.sh (tools/install-grader's CMake check) with stand-ins
# first on PATH: a `cmake` that reports 3.22.1 (Ubuntu 22.04, Gradescope's
# default image) and a `python3` whose `-m pip install` either fails (no
# network) or puts a CMake 3.25+ first on PATH (the real one behind a shim).
#   test_ensure_cmake.sh REPO_ROOT
root=$1
script="$root/tools/ensure-cmake.sh"
real_cmake=$(command -v cmake)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# stand-ins MODE: MODE old (cmake 3.22.1), none (no cmake); pip ok or broken.
stand_ins() {
  local bin=$work/$1-$2
  rm -rf "$bin"; mkdir -p "$bin"
  if [[ $1 == old ]]; then
    printf '#!/bin/sh\n[ "$1" = --version ] && echo "cmake version 3.22.1" && exit 0\nexit 1\n' > "$bin/cmake"
  else
    printf '#!/bin/sh\nexit 127\n' > "$bin/cmake"  # stands for "not installed" in front of the real one
  fi
  if [[ $2 == ok ]]; then
    printf '#!/bin/sh\nif [ "$1 $2" = "-m pip" ]; then [ "$3" = install ] && printf "#!/bin/sh\\nexec %s \\"\\$@\\"\\n" > "%s/cmake" && chmod +x "%s/cmake"; exit 0; fi\nexec /usr/bin/python3 "$@"\n' \
      "$real_cmake" "$bin" "$bin" > "$bin/python3"
  else
    printf '#!/bin/sh\nif [ "$1 $2" = "-m pip" ]; then [ "$3" = --version ] && exit 0; echo "pip: no network" >&2; exit 1; fi\nexec /usr/bin/python3 "$@"\n' > "$bin/python3"
  fi
  chmod +x "$bin/cmake" "$bin/python3"
  echo "$bin"
}

out=$(PATHLAB_SKIP_APT=1 bash "$script" 2>&1); rc=$?
[[ $rc -eq 0 && -z $out ]] || fail "with this machine's CMake: exit $rc, said: $out"

for missing in old none; do
  bin=$(stand_ins "$missing" broken)
  out=$(PATH="$bin:$PATH" PATHLAB_SKIP_APT=1 bash "$script" 2>"$work/err"); rc=$?
  err=$(cat "$work/err")
  [[ $rc -eq 1 && $out == *"installing a newer CMake"* && $(wc -l <<< "$err") -eq 1 && $err == *"Ubuntu 24.04"* ]] ||
    fail "CMake $missing, pip without network: exit $rc (want 1), said: $out / $err"

  bin=$(stand_ins "$missing" ok)
  out=$(PATH="$bin:$PATH" PATHLAB_SKIP_APT=1 bash "$script" 2>&1); rc=$?
  [[ $rc -eq 0 && $out == *"installing a newer CMake"* && $out == *"now CMake 3."* ]] ||
    fail "CMake $missing, pip that installs one: exit $rc (want 0), said: $out"
  # Sourced, as tools/install-grader does: the new cmake is the one found afterwards.
  out=$(PATH="$bin:$PATH" PATHLAB_SKIP_APT=1 bash -c "set -euo pipefail; source '$script' > /dev/null; cmake --version" 2>&1)
  [[ $out == "cmake version 3."* && $out != *"3.22"* ]] || fail "CMake $missing, sourced: then cmake --version says: $out"
done
((failures == 0)) && echo "ensure-cmake: 7 of 7 checks passed"
exit $((failures > 0))
