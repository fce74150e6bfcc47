"""Keeps each handout's test table (tasks/NN-name/README.md, "## Tests (N
points)") and the TA guide's points per task (docs/ta-guide.md) equal to the
suites: names and points come from each judge's own manifest
(test-NN-name --list-test-cases), the one source of truth.

  tools/handout-tables BUILD_DIR            rewrite the tables
  tools/handout-tables BUILD_DIR --check    exit 1 naming each stale table (CTest handout-tables)
  --tasks LIST                              only these tasks' tables (their judges built: a
                                            course's own task after its suite changed)"""
import re
import subprocess
import sys
from pathlib import Path

from tools import pathlab_tasks

ROOT = pathlab_tasks.ROOT
# {n: folder}: one suite per task the course hands out (in a student release, tasks/handed-out.txt)
SUITES = {n: pathlab_tasks.tasks()[n][0] for n in pathlab_tasks.handed_out()}


def manifest(build: Path, suite: str):
    """(name, points) per test case, in the suite's order."""
    out = subprocess.run([str(build / "tests" / f"test-{suite}"), "--list-test-cases", "--no-version"],
                         capture_output=True, text=True, check=True).stdout
    cases = []
    for line in out.splitlines():
        m = re.match(r"TEST (\d+) \S+ (.*)$", line)
        if m:
            cases.append((m.group(2), int(m.group(1))))
    return cases


def rewritten(text: str, cases) -> str:
    """The handout with its test table and total made from `cases`."""
    lines = text.split("\n")
    heading = next(i for i, l in enumerate(lines) if re.match(r"## Tests \(\d+ points\)", l))
    lines[heading] = f"## Tests ({sum(p for _, p in cases)} points)"
    first = next(i for i in range(heading, len(lines)) if lines[i].startswith("| T"))
    last = first
    while last < len(lines) and lines[last].startswith("| T"):
        last += 1
    rows = [f"| {name.replace('|', '/')} | {points} |" for name, points in cases]
    return "\n".join(lines[:first] + rows + lines[last:])


def main() -> int:
    if sys.argv[1:2] in (["-h"], ["--help"]):
        print(__doc__)
        return 0
    args = sys.argv[2:]
    chosen = SUITES
    if "--tasks" in args:
        at = args.index("--tasks")
        if at + 1 == len(args):
            print(__doc__, file=sys.stderr)
            return 2
        listed = pathlab_tasks.parse_task_list(args[at + 1], SUITES, "--tasks (of the tasks handed out)")
        chosen = {n: SUITES[n] for n in listed}
        del args[at:at + 2]
    if len(sys.argv) < 2 or sys.argv[1].startswith("-") or set(args) - {"--check"}:
        print(__doc__, file=sys.stderr)
        return 2
    build, check = Path(sys.argv[1]), "--check" in args
    missing = [suite for suite in chosen.values() if not (build / "tests" / f"test-{suite}").is_file()]
    if missing:
        print(f"handout-tables: {build} has no judge test-{missing[0]} (build it first: cmake --build {build})",
              file=sys.stderr)
        return 2
    stale = []
    for suite in chosen.values():
        handout = ROOT / "tasks" / suite / "README.md"
        text = handout.read_text()
        new = rewritten(text, manifest(build, suite))
        if new != text:
            stale.append(str(handout.relative_to(ROOT)))
            if not check:
                handout.write_text(new)
    guide = ROOT / "docs" / "ta-guide.md"
    if not guide.exists():  # a student release has no TA guide
        print(("stale: " if check else "updated: ") + (", ".join(stale) if stale else "none"))
        return 1 if check and stale else 0
    text = guide.read_text()
    new = text
    for n, suite in chosen.items():
        cases = manifest(build, suite)
        new = re.sub(rf"^\| {n} ([^|]+) \| \d+ \| \d+ \|$", lambda m: f"| {n} {m.group(1)} | "
                     f"{sum(p for _, p in cases)} | {len(cases)} |", new, flags=re.M)
    if new != text:
        stale.append(str(guide.relative_to(ROOT)))
        if not check:
            guide.write_text(new)
    if check and stale:
        print("test tables differ from the suites in: " + ", ".join(stale) +
              " (run tools/handout-tables BUILD_DIR)", file=sys.stderr)
        return 1
    print(("stale: " if check else "updated: ") + (", ".join(stale) if stale else "none"))
    return 0
