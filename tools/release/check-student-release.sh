# Sourced by tools/make-student-release once the release is made in $out: the
# check that it builds as its README says, that on the stubs only the task
# suites fail, that with every task finished every test passes and tools/check
# gives full marks, and that no reference source is in it. Uses the script's
# variables ($root, $out, $scratch, $bdir, $task_list, $clang, ...) and its
# helpers (minutes); exits 1 on any problem.
keep_scratch=1  # until the check passes: its logs and builds are the evidence
copy=$scratch/release
cp -a "$out/." "$copy"
problems=()
problem() { echo "make-student-release: CHECK FAILED: $*" >&2; problems+=("$*"); }

# The README's build commands for students (its first sh block after "## For students").
mapfile -t build_commands < <(awk '/^## For students/ {s = 1} s && /^```sh/ {b = 1; next} b && /^```/ {exit}
                                   b && /^cmake / {print}' "$copy/README.md")
((${#build_commands[@]} > 0)) || { problem "README.md: no cmake commands under \"## For students\""; }
if ((clang)); then  # the configure step with the clang-libcxx preset's compiler settings
  build_commands=("${build_commands[@]//cmake --preset student/cmake --preset student -DCMAKE_CXX_COMPILER=clang++ -DPATHLAB_LIBCXX=ON}")
  grep -q PATHLAB_LIBCXX <<< "${build_commands[*]}" || problem "--clang: no 'cmake --preset student' in the README's commands"
fi

# run_ctest LOG: the full ctest, as a student runs it.
run_ctest() {
  (cd "$copy" && ctest --test-dir "$bdir" --output-on-failure --parallel "$(nproc)") > "$1" 2>&1 || true
  grep -q "tests passed" "$1" || problem "ctest did not run: $(tail -3 "$1")"
}
not_passed() { sed -n -E 's/^[[:space:]]+[0-9]+ - ([^ ]+) \(([^)]*)\).*$/\1 \2/p' "$1"; }  # "name status" per test
summary() { grep -E "tests passed" "$1" | tr -s ' '; }

# The reference's source is not in the release: no line of it that is its
# own (in none of the stubs, framework, programs and suites) appears in any
# file of the release: documents, tools, the compiled objects included.
python3 - "$root" "$scratch/solutions" "$out" << 'EOF_PY' || problem "the reference's source reaches the release (above)"
import sys
from pathlib import Path
root, solutions, release = (Path(a) for a in sys.argv[1:])
sys.path.insert(0, str(root))  # the repository: the import root (docs/architecture.md)
from tools.release.package_tree import tree_files
# Code a student has anyway, reviewed as such: the stubs, the framework, the
# programs and the suites (not tests/mutants/, whose reviewed survivors quote
# the reference). A reference line inside any of them is not its own.
# The files as the release takes them (tools/package-tree's): a new task's, not
# yet committed, included.
shipped = [root / f for f in tree_files(root) if f.startswith(("tasks/", "framework/", "apps/", "tests/"))
           and not f.startswith("tests/mutants/")]
text = "\n".join(f.read_text(errors="replace") for f in shipped if f.is_file())
own = {line.strip() for f in solutions.rglob("*.cpp") for line in f.read_text().splitlines()
       if len(line.strip()) >= 24 and line.strip() not in text}
if len(own) < 100:
    sys.exit(f"only {len(own)} lines of the reference are its own: is solutions/ the reference?")
found = []
for f in release.rglob("*"):
    if f.is_file() and not f.is_symlink():
        data = f.read_bytes()
        found += [(f, line) for line in own if line.encode() in data]
for f, line in found[:5]:
    print(f"  {f.relative_to(release)}: {line}", file=sys.stderr)
print(f"make-student-release: {len(own)} lines of the reference's own source; {len(found)} found in the release")
sys.exit(1 if found else 0)
EOF_PY

# check_score LOG EXPECTED: tools/check as the README says, on the copy's tasks/;
# the score must be EXPECTED (0, or "full"), with every task's tests present
# and the compiled reference linked.
check_score() {
  (cd "$copy" && python3 tools/check --build-dir "$scratch/build-check" --out "$scratch/check.json") > "$1" 2>&1 || true
  python3 - "$scratch/check.json" "$2" "$scratch/build-check/pathlab-reference.txt" "${#suites[@]}" << 'EOF_PY' ||
import json, sys
results, expected, reference = json.load(open(sys.argv[1])), sys.argv[2], open(sys.argv[3]).read()
task_count = int(sys.argv[4])
points = sum(t["max_score"] for t in results["tests"])
tasks = {t["name"].split(":")[0] for t in results["tests"]}
want = points if expected == "full" else float(expected)
print(f"{results['score']:g} of {points:g} points, {len(results['tests'])} tests, {len(tasks)} tasks; reference {reference.strip()}")
ok = results["score"] == want and len(tasks) == task_count and reference.startswith("compiled") and points > 0
sys.exit(0 if ok else 1)
EOF_PY
    problem "tools/check on the $3 did not give $2 with the compiled reference (see $1)"
}

# (a) the untouched release
t=$SECONDS
echo "make-student-release: (a) building the release as the README says: ${build_commands[*]/%/;}"
for command in "${build_commands[@]}"; do
  (cd "$copy" && bash -c "$command") >> "$scratch/build-stubs.log" 2>&1 || {
    problem "the release does not build: '$command' failed (see $scratch/build-stubs.log)"
    tail -20 "$scratch/build-stubs.log" >&2
    exit 1
  }
done
build_a=$((SECONDS - t))
# The programs the release's documents run exist; their ctest filters select tests.
for program in $(grep -ohE "(^|[^[:alnum:]_./-])\./$bdir/[[:alnum:]_./-]*[[:alnum:]_-]" "${shown[@]/#$out/$copy}" |
                 sed -E "s#^[^.]##" | sort -u); do
  [[ -e $copy/$program ]] || problem "the release's documents run $program, which the build did not make"
done
while IFS= read -r command; do
  count=$(cd "$copy" && eval "${command%%#*} -N" 2>&1 | sed -n 's/^Total Tests: //p')
  [[ ${count:-0} -gt 0 ]] || problem "'$command' (in the release's documents) selects no test"
done < <(grep -ohE "^ctest --test-dir ${bdir}[^\`]*" "$copy/README.md" "$copy"/tasks/*/README.md | sort -u)
"$copy/$bdir/pathlab" -q -s 1 -d 64x48 -o "$scratch/stub-render.png" 2> /dev/null && [[ -s $scratch/stub-render.png ]] ||
  problem "the release does not render on the stubs"
# The tasks not handed out link the compiled reference; the others the student's files.
owners=$("$copy/$bdir/pathlab" --version | sed -n 's/^pathlab .* (tasks \(.*\))$/\1/p')
[[ $owners == "${expected_owners[*]}" ]] ||
  problem "(a) pathlab --version says '$owners' for the tasks, not '${expected_owners[*]}' (tasks/handed-out.txt: $task_list)"
t=$SECONDS
run_ctest "$scratch/ctest-stubs.log"
not_passed_a=$(not_passed "$scratch/ctest-stubs.log")
ctest_a=$((SECONDS - t))
for suite in "${suites[@]}"; do
  grep -qx "$suite Failed" <<< "$not_passed_a" ||
    problem "(a) suite $suite does not fail on the stubs: $(grep "^$suite " <<< "$not_passed_a" || echo "it passes: a test that cannot fail?")"
done
while read -r name status; do
  [[ -z $name ]] && continue
  [[ " ${suites[*]} " == *" $name "* && $status == Failed ]] && continue
  problem "(a) $name ($status) on the untouched stubs: only the task suites may fail (see $scratch/ctest-stubs.log)"
done <<< "$not_passed_a"
echo "make-student-release: (a) stubs: $(summary "$scratch/ctest-stubs.log"); not passed: $(paste -sd, <<< "$not_passed_a")"
t=$SECONDS
check_score "$scratch/check-stubs.log" 0 stubs
check_a=$((SECONDS - t))
echo "make-student-release: (a) tools/check on the stubs: $(grep -m1 '^Total' "$scratch/check-stubs.log" | tr -s ' ')"

# (b) every handed-out task finished: the reference solutions in tasks/
for suite in "${suites[@]}"; do cp -r "$scratch/solutions/$suite/." "$copy/tasks/$suite/"; done
t=$SECONDS
for command in "${build_commands[@]}"; do
  (cd "$copy" && bash -c "$command") >> "$scratch/build-finished.log" 2>&1 || {
    problem "(b) the finished release does not build: '$command' (see $scratch/build-finished.log)"
    break
  }
done
build_b=$((SECONDS - t))
t=$SECONDS
run_ctest "$scratch/ctest-finished.log"
not_passed_b=$(not_passed "$scratch/ctest-finished.log")
ctest_b=$((SECONDS - t))
while read -r name status; do
  [[ -n $name ]] && problem "(b) $name ($status) with every task finished (see $scratch/ctest-finished.log)"
done <<< "$not_passed_b"
echo "make-student-release: (b) finished: $(summary "$scratch/ctest-finished.log"); not passed: $(paste -sd, <<< "${not_passed_b:-none}")"
t=$SECONDS
check_score "$scratch/check-finished.log" full "finished tasks"
check_b=$((SECONDS - t))
echo "make-student-release: (b) tools/check, every task finished: $(grep -m1 '^Total' "$scratch/check-finished.log" | tr -s ' ')"

# (b) the write-up of the finished tasks, as docs/writeup.md says (the page; printing needs a browser):
# every task's pictures and comparisons, made with the release's compiled reference for the other tasks.
t=$SECONDS
if (cd "$copy" && python3 tools/writeup --no-pdf --no-convergence --out "$scratch/writeup") > "$scratch/writeup.log" 2>&1; then
  page="$scratch/writeup/writeup.html"
  grep -q "Not implemented yet\|Could not be made\|No comparison" "$page" &&
    problem "(b) the write-up of the finished tasks has a task not done or a picture missing (see $page)"
  imaged=0  # the suites with image tests (a course's own task may have none)
  for folder in "${suites[@]}"; do grep -qs 'TEST_CASE("T[0-9.]* image:' "$copy/tests/$folder"/*.cpp && imaged=$((imaged + 1)); done
  [[ $(grep -o 'class="compare-slider"' "$page" | wc -l) -ge $imaged ]] ||
    problem "(b) the write-up of the finished tasks has fewer comparisons than the $imaged suites with image tests (see $page)"
else
  problem "(b) tools/writeup failed on the finished tasks (see $scratch/writeup.log)"
fi
writeup_c=$((SECONDS - t))
echo "make-student-release: (b) tools/writeup, every task finished: $(tail -1 "$scratch/writeup.log")"

echo "make-student-release: times: build $(minutes $build_a), ctest $(minutes $ctest_a) (stubs);" \
     "rebuild $(minutes $build_b), ctest $(minutes $ctest_b) (finished); tools/check $(minutes $check_a)" \
     "(stubs, its build included), $(minutes $check_b) (finished); tools/writeup $(minutes $writeup_c);" \
     "total $(minutes $((SECONDS - start)))"
if ((${#problems[@]} > 0)); then
  echo "make-student-release: ${#problems[@]} problem(s); builds and logs kept in $scratch" >&2
  exit 1
fi
# shellcheck disable=SC2034  # read by the EXIT trap
keep_scratch=0
echo "make-student-release: $out checked: builds as the README says; on the stubs only the task suites fail;" \
     "with every task finished every test passes; tools/check gives 0 and full marks; no reference source in it"
