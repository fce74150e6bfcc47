"""Line coverage of each reference solution by its own task's suite.

  tools/coverage [TASK ...] [--build-dir DIR] [--write-doc]

For task NN it counts which lines of solutions/NN-name/FILE.cpp run in the
candidate process of suite NN (build-coverage/tests/candidate-NN-name, the
reference in the default build) while the suite's judge (test-NN-name) runs,
and prints per task the executable lines, the lines reached, the percentage
and every unreached line with its code. TASK numbers (1-7) limit the run;
the default is all seven. --write-doc writes the result into
docs/test-power.md between <!-- coverage:begin --> and
<!-- coverage:end --> (both added, under a heading, at the end if absent).

Why the candidate only: student code only ever runs in the candidate, so a
line of the reference that the candidate never runs is behaviour the suite
does not check. The judge links the same reference (the OBJECT library
pathlab_taskN_reference, and so the same .gcda file), and any line it ran
for its own expectations would hide such a line if its counts were merged
in. (Today no judge runs its own task's reference, but other tasks' ones.)

How the counts are kept apart:
  - build-coverage/ is the default Release build (no validity matrix) in
    which only the files of solutions/ are instrumented: a compiler launcher
    (build-coverage/coverage-compile, CMAKE_CXX_COMPILER_LAUNCHER) adds
    -O0 --coverage -fprofile-update=atomic to their compile commands alone,
    with -fprofile-filter-files so that only functions written in solutions/
    get counters (not glm's or the standard library's, which they call).
    -O0 gives honest line counts (no inlining, no code motion); atomic
    counters are needed because the candidate renders on several threads:
    with plain counters gcov's counts derived by flow conservation go wrong
    and a line that never ran can show a count (seen in task 5). Judges,
    framework and tests stay at -O3, uninstrumented: instrumenting every
    file at -O0 with atomic counters made the suites about 5 times slower.
    Judges and candidates also run the other tasks' references (suite 3's
    judge runs task 2's intersection), at -O0 with counters as well.
  - The judge runs with GCOV_PREFIX pointing at a throw-away folder, and with
    PATHLAB_CANDIDATE set to a small launcher that gives the candidate its own
    GCOV_PREFIX: each process writes its .gcda files into its own tree, and
    nothing is written into build-coverage/ itself.
  - A candidate writes its counts when it exits, but the judge ends it with
    SIGKILL right after closing its request pipe, and a candidate kills
    itself when its parent dies (PR_SET_PDEATHSIG). So the launcher does not
    exec the candidate: it starts a subshell that starts the candidate and
    waits for it. The judge's SIGKILL ends only the launcher; the candidate,
    whose parent (the subshell) lives on, sees the end of its requests and
    exits normally. This script is a child subreaper, so the orphaned
    subshell comes back to it, and it waits for every one before reading the
    counts. (When the candidate is quicker than the kill, the launcher ends
    by itself and nothing is orphaned.) Each subshell leaves the candidate's
    exit status in a file: none means the judge never started a candidate.
  - gcov (the one matching the compiler) reads the candidate's .gcda with the
    build's .gcno; the .gcov listings stay in build-coverage/coverage/NN-name/.
    A line is executable when gcov gives it a count, as in gcov's own
    summary; '=====' lines (reachable only by an exception) are unreached
    lines too, and marked as such.

PATHLAB_TEST_SEED is removed from the suites' environment, so the counts are
those of the suites' fixed seeds. Needs only cmake, ninja, g++ and gcov
(build-essential): no gcovr."""
import argparse
import ctypes
import os
import re
import shlex
import shutil
import subprocess
import sys
import time
from pathlib import Path

from grader.driver.processes import reap_orphans  # noqa: E402
from tools import pathlab_tasks  # noqa: E402  (the task list: the tasks/NN-name folders)

ROOT = Path(__file__).resolve().parents[2]
TASKS = pathlab_tasks.tasks()  # {n: (folder, file)}: the tasks/NN-name folders
DOC = ROOT / "docs" / "test-power.md"
BEGIN, END = "<!-- coverage:begin -->", "<!-- coverage:end -->"
HEADING = "## Coverage of the reference solutions by their own suites"
SUITE_TIMEOUT = 1800  # seconds; the slowest suite (03-bvh) takes 1 to 3 minutes
ORPHAN_TIMEOUT = 60   # seconds for candidates to exit after their judge
EXCEPTIONAL = "  (gcov =====: only on an exception's path)"


class Failure(Exception):
    """A step that failed: the message says which and why."""


# ---- Build ------------------------------------------------------------------

def run_step(what: str, command: list, log: Path) -> None:
    """Runs a build command with its output in log; fails with the log's tail."""
    with open(log, "w") as out:
        p = subprocess.run(command, cwd=ROOT, stdout=out, stderr=subprocess.STDOUT)
    if p.returncode != 0:
        tail = "\n".join(log.read_text(errors="replace").splitlines()[-25:])
        raise Failure(f"{what} failed (exit {p.returncode}): {shlex.join(command)}\n"
                      f"--- last lines of {log} ---\n{tail}")


def write_compile_launcher(path: Path) -> None:
    """The compiler launcher: instruments the compile commands of solutions/ files only.
    (Ninja does not rebuild when this text changes: delete the build folder then.)"""
    path.write_text(f"""#!/bin/sh
# Written by tools/coverage (CMAKE_CXX_COMPILER_LAUNCHER): a file of solutions/
# is compiled at -O0 with coverage counters (atomic: the candidate renders on
# several threads); every other file as the build type says, uninstrumented.
case " $* " in
  *" -c "{shlex.quote(str(ROOT / "solutions"))}/*)
    exec "$@" -O0 --coverage -fprofile-update=atomic {shlex.quote("-fprofile-filter-files=^" + re.escape(str(ROOT / "solutions")) + "/")} ;;
esac
exec "$@"
""")
    path.chmod(0o755)


def build(build_dir: Path, tasks: list) -> None:
    """Configures (idempotent) and builds the judges and candidates of the tasks."""
    build_dir.mkdir(parents=True, exist_ok=True)
    launcher = build_dir / "coverage-compile"
    write_compile_launcher(launcher)
    run_step("configuring", ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-G", "Ninja",
                             "-DCMAKE_BUILD_TYPE=Release", "-DPATHLAB_BUILD_TESTS=ON",
                             "-DPATHLAB_BUILD_VALIDITY=OFF", "-DPATHLAB_TASKS=reference",
                             f"-DCMAKE_CXX_COMPILER_LAUNCHER={launcher}", "-DCMAKE_CXX_FLAGS=",
                             "-DCMAKE_EXE_LINKER_FLAGS=--coverage"],
             build_dir / "coverage-configure.log")
    targets = []
    for n in tasks:
        name = TASKS[n][0]
        targets += [f"test-{name}", f"candidate-{name}"]
    run_step("building", ["cmake", "--build", str(build_dir), "--target", *targets],
             build_dir / "coverage-build.log")


def compiler_of(build_dir: Path) -> str:
    cache = (build_dir / "CMakeCache.txt").read_text()
    m = re.search(r"^CMAKE_CXX_COMPILER:\w+=(.*)$", cache, re.M)
    if not m:
        raise Failure(f"no CMAKE_CXX_COMPILER in {build_dir}/CMakeCache.txt")
    return m.group(1)


def find_gcov(build_dir: Path) -> str:
    """The gcov of the build's compiler: gcov-MAJOR if installed, else gcov of the same major."""
    compiler = compiler_of(build_dir)
    banner = subprocess.run([compiler, "--version"], capture_output=True, text=True).stdout
    if "clang" in banner.lower():
        raise Failure(f"{build_dir} is built with clang ({compiler}); this tool reads GCC's gcov data")
    version = subprocess.run([compiler, "-dumpfullversion"], capture_output=True, text=True).stdout.strip()
    major = version.split(".")[0]
    for gcov in (f"gcov-{major}", "gcov"):
        path = shutil.which(gcov)
        if not path:
            continue
        out = subprocess.run([path, "--version"], capture_output=True, text=True).stdout
        m = re.search(r"(\d+)\.\d+\.\d+", out.splitlines()[0] if out else "")
        if m and m.group(1) == major:
            return path
    raise Failure(f"no gcov for GCC {version} ({compiler}): install the gcc package of that version")


# ---- Running a suite with the candidate's counts kept apart -------------------

def become_subreaper() -> None:
    """Orphaned descendants (the launchers' subshells) come back to this process."""
    PR_SET_CHILD_SUBREAPER = 36
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) != 0:
        raise Failure(f"prctl(PR_SET_CHILD_SUBREAPER) failed: {os.strerror(ctypes.get_errno())}")


def write_launcher(path: Path, candidate: Path, prefix: Path, exits: Path) -> None:
    """PATHLAB_CANDIDATE for the judge: runs the candidate with its own GCOV_PREFIX,
    in a subshell that outlives the launcher (see the docstring at the top) and
    leaves the candidate's exit status in a file of the folder exits."""
    path.write_text(f"""#!/bin/bash
# Written by tools/coverage: the candidate's .gcda files go under GCOV_PREFIX.
# The judge SIGKILLs this launcher; the subshell, the candidate's parent,
# lives on (closing its own copies of the pipes) until the candidate exits.
export GCOV_PREFIX={shlex.quote(str(prefix))} GCOV_PREFIX_STRIP=0
(
  {shlex.quote(str(candidate))} &
  child=$!
  exec 0<&- 1>&- 2>&- 3<&- 4>&-
  wait "$child"
  status=$?
  echo "$status" > {shlex.quote(str(exits))}/"$BASHPID"
  exit "$status"
) &
wait "$!"
""")
    path.chmod(0o755)


def run_suite(build_dir: Path, out: Path, name: str) -> str:
    """Runs suite NAME's judge against its candidate; returns the judge's SCORE line."""
    judge = build_dir / "tests" / f"test-{name}"
    launcher = out / "launch-candidate"
    exits = out / "candidate-exits"
    exits.mkdir()
    write_launcher(launcher, build_dir / "tests" / f"candidate-{name}", out / "candidate-gcda", exits)
    env = {k: v for k, v in os.environ.items() if k not in ("PATHLAB_TEST_SEED", "GCOV_PREFIX_STRIP")}
    env.update(PATHLAB_CANDIDATE=str(launcher), GCOV_PREFIX=str(out / "judge-gcda"))
    log = out / "judge.log"
    with open(log, "w") as f:
        try:
            p = subprocess.run([str(judge)], stdout=f, stderr=subprocess.STDOUT, env=env, timeout=SUITE_TIMEOUT)
        except subprocess.TimeoutExpired:
            raise Failure(f"suite {name} did not finish in {SUITE_TIMEOUT} s (log: {log})")
    # A launcher the judge killed left its subshell to this process; one that
    # ended first (its candidate quicker than the kill) was waited for by the judge.
    # Every orphaned descendant (a launcher's subshell whose launcher the judge killed) waited for, so
    # that every candidate has exited and written its counts.
    if not reap_orphans(ORPHAN_TIMEOUT):
        raise Failure(f"a candidate was still running {ORPHAN_TIMEOUT} s after its judge ended")
    statuses = [f.read_text().strip() for f in sorted(exits.iterdir())]
    text = log.read_text(errors="replace")
    score = re.search(r"^SCORE (\d+)/(\d+) points.*$", text, re.M)
    if p.returncode != 0 or not score or score.group(1) != score.group(2):
        tail = "\n".join(text.splitlines()[-25:])
        raise Failure(f"suite {name} did not give the reference full marks (exit {p.returncode}); "
                      f"its coverage would not mean much\n--- last lines of {log} ---\n{tail}")
    if not statuses:
        raise Failure(f"suite {name}: the judge never started the candidate through {launcher}")
    if any(s != "0" for s in statuses):
        raise Failure(f"suite {name}: a candidate exited with status {statuses} (its counts may be lost)")
    return score.group(0)


# ---- Reading the counts ----------------------------------------------------------

def gcda_and_gcno(build_dir: Path, out: Path, n: int) -> Path:
    """The candidate's .gcda of task n's reference object, with the build's .gcno copied beside it."""
    name, file = TASKS[n]
    pattern = f"pathlab_task{n}_reference.dir/solutions/{name}/{file}"
    gcdas = [p for p in (out / "candidate-gcda").rglob(f"{file}.gcda") if pattern in str(p)]
    gcnos = list(build_dir.glob(f"CMakeFiles/{pattern}.gcno"))
    if len(gcnos) != 1:
        raise Failure(f"task {n}: {len(gcnos)} .gcno files for {pattern} in {build_dir}: is {pattern} "
                      f"compiled through {build_dir}/coverage-compile? (delete {build_dir} to start afresh)")
    if len(gcdas) != 1:
        raise Failure(f"task {n}: {len(gcdas)} .gcda files of the candidate for {pattern}: "
                      f"did the candidate exit normally?")
    shutil.copy2(gcnos[0], gcdas[0].with_suffix(".gcno"))
    return gcdas[0].with_suffix(".gcno")


def gcov_listing(gcov: str, gcno: Path, source: Path, workdir: Path) -> Path:
    """Runs gcov (listings of every file the object uses, into workdir); returns source's
    listing after checking that gcov's own summary of it matches what parse_listing reads."""
    workdir.mkdir(exist_ok=True)
    p = subprocess.run([gcov, str(gcno)], cwd=workdir, capture_output=True, text=True)
    if p.returncode != 0:
        raise Failure(f"gcov failed on {gcno}:\n{p.stderr}")
    listing = workdir / f"{source.name}.gcov"
    summary = re.search(rf"^File '{re.escape(str(source))}'\nLines executed:([\d.]+)% of (\d+)$", p.stdout, re.M)
    if not listing.exists() or not summary:
        raise Failure(f"gcov gave no listing of {source} from {gcno}:\n{p.stdout}{p.stderr}")
    counts = parse_listing(listing)
    reached = sum(1 for c in counts.values() if c not in ("#####", "====="))
    if len(counts) != int(summary.group(2)) or abs(100.0 * reached / len(counts) - float(summary.group(1))) > 0.01:
        raise Failure(f"{listing}: read {reached} of {len(counts)} lines, gcov says "
                      f"{summary.group(1)}% of {summary.group(2)}")
    return listing


def parse_listing(listing: Path) -> dict:
    """{line: count column} for the executable lines of a .gcov listing: a number
    (with '*' if some block of the line never ran), '#####' (never run) or '====='
    (never run, and only reachable by an exception). The per-instance sections of
    templates (between '------------------' lines, each headed by a symbol name)
    repeat lines: only the file's own rows are read."""
    rows = listing.read_text(errors="replace").splitlines()
    counts, in_instances = {}, False
    for i, row in enumerate(rows):
        if row.startswith("------------------"):
            following = rows[i + 1] if i + 1 < len(rows) else ""
            in_instances = bool(following) and not following[0].isspace() and following.endswith(":")
            continue
        m = re.match(r"^\s*([^:\s]+):\s*(\d+):", row)
        if in_instances or not m or m.group(2) == "0" or m.group(1) == "-":
            continue
        counts[int(m.group(2))] = m.group(1)
    return counts


def measure(build_dir: Path, gcov: str, n: int) -> dict:
    """Runs suite n and returns its task's coverage."""
    name, file = TASKS[n]
    out = build_dir / "coverage" / name
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    score = run_suite(build_dir, out, name)
    source = ROOT / "solutions" / name / file
    listing = gcov_listing(gcov, gcda_and_gcno(build_dir, out, n), source, out / "gcov")
    counts = parse_listing(listing)
    code = source.read_text().splitlines()
    unreached = [(line, code[line - 1].strip(), counts[line] == "=====")
                 for line in sorted(counts) if counts[line] in ("#####", "=====")]
    return {"n": n, "name": name, "source": f"solutions/{name}/{file}", "score": score,
            "lines": len(counts), "reached": len(counts) - len(unreached), "unreached": unreached,
            "listing": listing}


# ---- Output ---------------------------------------------------------------------

def percent(result: dict) -> str:
    return f"{100.0 * result['reached'] / result['lines']:.1f}"


def print_report(results: list) -> None:
    for r in results:
        print(f"\n{r['name']}  {r['source']}: {r['lines']} lines, {r['reached']} reached ({percent(r)}%)")
        print(f"  suite: {r['score']}")
        print(f"  listing: {r['listing']}")
        for line, text, exceptional in r["unreached"]:
            print(f"  {line:5d}  {text}{EXCEPTIONAL if exceptional else ''}")
    lines = sum(r["lines"] for r in results)
    reached = sum(r["reached"] for r in results)
    print(f"\nall: {lines} lines, {reached} reached ({100.0 * reached / lines:.1f}%)")


def inline_code(text: str) -> str:
    fence = "``" if "`" in text else "`"
    return f"{fence} {text} {fence}" if fence == "``" else f"`{text}`"


def doc_section(results: list, gcov_version: str) -> str:
    rows = ["Counted: the lines of `solutions/NN-name/FILE.cpp` executed in suite NN's candidate process",
            "(`candidate-NN-name`, which links that reference) while suite NN's judge runs; the judge's own",
            "copy of the reference is not counted. A line is executable when gcov gives it a count",
            f"({gcov_version}; the solutions compiled at -O0). Generated by `tools/coverage --write-doc`.", "",
            "| task | lines | reached | % |", "| --- | ---: | ---: | ---: |"]
    for r in results:
        rows.append(f"| {r['name']} | {r['lines']} | {r['reached']} | {percent(r)} |")
    lines = sum(r["lines"] for r in results)
    reached = sum(r["reached"] for r in results)
    rows += [f"| all | {lines} | {reached} | {100.0 * reached / lines:.1f} |", "", "Unreached lines:", ""]
    for r in results:
        if not r["unreached"]:
            rows.append(f"- {r['name']} (`{r['source']}`): none")
            continue
        rows.append(f"- {r['name']} (`{r['source']}`):")
        rows += [f"  - {line}: {inline_code(text)}{EXCEPTIONAL if exceptional else ''}"
                 for line, text, exceptional in r["unreached"]]
    return "\n".join(rows)


def write_doc(section: str) -> None:
    text = DOC.read_text()
    begin, end = text.find(BEGIN), text.find(END)
    if begin < 0 and end < 0:
        text = text.rstrip("\n") + f"\n\n{HEADING}\n\n{BEGIN}\n{END}\n"
        begin, end = text.find(BEGIN), text.find(END)
    if begin < 0 or end < begin:
        raise Failure(f"{DOC}: the markers {BEGIN} and {END} are not one pair in that order")
    DOC.write_text(text[:begin + len(BEGIN)] + "\n" + section + "\n" + text[end:])
    print(f"wrote the coverage section of {DOC.relative_to(ROOT)}")


# ---- Main -----------------------------------------------------------------------

def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("tasks", nargs="*", type=int, metavar="TASK",
                        help="task numbers 1-7 to measure (default: all)")
    parser.add_argument("--build-dir", type=Path, default=ROOT / "build-coverage",
                        help="the coverage build (default: build-coverage)")
    parser.add_argument("--write-doc", action="store_true",
                        help="write the result into docs/test-power.md (needs all tasks)")
    args = parser.parse_args()
    if any(n not in TASKS for n in args.tasks):
        parser.error(f"TASK is a number from 1 to {len(TASKS)}")
    args.tasks = sorted(set(args.tasks)) or sorted(TASKS)
    if args.write_doc and args.tasks != sorted(TASKS):
        parser.error("--write-doc measures all seven tasks: give no TASK")
    args.build_dir = args.build_dir.resolve()
    return args


def main() -> int:
    args = parse_args()
    start = time.monotonic()
    try:
        for tool in ("cmake", "ninja"):
            if not shutil.which(tool):
                raise Failure(f"{tool} not found (tools/quickstart.sh installs it)")
        print(f"building {args.build_dir} (solutions/ at -O0 --coverage) ...", end=" ", flush=True)
        build(args.build_dir, args.tasks)
        print(f"{time.monotonic() - start:.0f} s", flush=True)
        gcov = find_gcov(args.build_dir)
        gcov_version = subprocess.run([gcov, "--version"], capture_output=True, text=True).stdout.splitlines()[0]
        become_subreaper()
        results = []
        for n in args.tasks:
            print(f"running suite {TASKS[n][0]} ...", end=" ", flush=True)
            suite_start = time.monotonic()
            results.append(measure(args.build_dir, gcov, n))
            print(f"{time.monotonic() - suite_start:.0f} s", flush=True)
        print_report(results)
        if args.write_doc:
            write_doc(doc_section(results, re.sub(r"\s*\(.*?\)", "", gcov_version)))
    except Failure as e:
        print(f"tools/coverage: {e}", file=sys.stderr)
        return 1
    print(f"took {time.monotonic() - start:.0f} s")
    return 0
