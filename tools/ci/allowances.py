"""What each task costs CI's test stage, measured from a build's last cold
build and ctest run: the seconds a task's tasks/NN-name/task.json asks for
under "ci": {"test": ...} (docs/ci.md, "What a task adds").

  tools/ci-allowances [BUILD_DIR]    (default: build; after a cold build and a full ctest)

A task's part of the stage (its CPU seconds over the stage's) is
  - its build steps: every object and program whose path names its folder
    (its suite, candidates, mutants, alternates, lab programs) or its task
    objects (pathlab_taskN_*), from BUILD_DIR/.ninja_log;
  - its own tests: every CTest test whose name holds its folder (its suite,
    its stub's, its mutants' and alternates'), from CTest's cost data;
  - its share of the tests that grade or draw from every task (EVERY_TASK
    below), their time split evenly.
Its allowance is that part of the stage's share (.ci/run's base plus the
tasks' allowances): the share is set from CI's clean-clone runs, whose
machines are slower than a developer's. The rest is the framework's, the
stage's base in .ci/run."""
import os
import re
import sys
from pathlib import Path

from tools import pathlab_tasks

# Tests whose time grows with every task: they grade, release, draw from or draw every task.
EVERY_TASK = re.compile(r"^(grader-.*|gradescope-zip|student-release|student-check-same-grade|mutation-sample|"
                        r"writeup|sampling-lab|handout-tables|release-text)$")


def build_seconds(log: Path) -> dict:
    """{output: seconds} of the last build of each output in a .ninja_log (v5: start end mtime output hash)."""
    steps = {}
    for line in log.read_text().splitlines():
        fields = line.split("\t")
        if len(fields) == 5 and fields[0].isdigit():
            steps[fields[3]] = (int(fields[1]) - int(fields[0])) / 1000
    return steps


def test_seconds(costs: Path) -> dict:
    """{test: average seconds} from CTest's CTestCostData.txt (NAME RUNS AVERAGE, then '---' and the failed)."""
    found = {}
    for line in costs.read_text().splitlines():
        if line.startswith("---"):
            break
        name, _, average = line.rpartition(" ")
        name = name.rpartition(" ")[0]
        found[name] = float(average)
    return found


def stage_share(stage: str) -> int:
    """The stage's share now: its base in .ci/run plus every task's allowance."""
    run = (pathlab_tasks.ROOT / ".ci" / "run").read_text()
    base = re.search(rf"^stage +{stage} +(\d+) ", run, re.M)
    return int(base.group(1)) + pathlab_tasks.ci_allowance(stage) if base else 0


def main() -> int:
    build = Path(sys.argv[1] if len(sys.argv) > 1 else pathlab_tasks.ROOT / "build").resolve()
    log, costs = build / ".ninja_log", build / "Testing/Temporary/CTestCostData.txt"
    for path in (log, costs):
        if not path.is_file():
            raise SystemExit(f"ci-allowances: no {path} (a build and a ctest run first)")
    cores = os.cpu_count() or 2
    steps, tests = build_seconds(log), test_seconds(costs)
    every = pathlab_tasks.tasks()
    shared = sum(s for name, s in tests.items() if EVERY_TASK.match(name)) / len(every)
    measured = (sum(steps.values()) + sum(tests.values())) / cores
    share = stage_share("test")
    print(f"{build}: {len(steps)} build steps and {len(tests)} tests, {measured:.0f} s on {cores} cores; the tests "
          f"of every task {shared * len(every):.0f} s of CPU, {shared:.0f} s a task. The test stage's share, "
          f"{share} s, split in the same proportions:")
    print(f"{'task':<24} {'build':>7} {'tests':>7} {'shared':>7} {'of the stage':>13} {'allowance':>10} {'task.json':>10}")
    total = 0
    for n, (folder, _) in every.items():
        mine = sum(s for out, s in steps.items() if folder in out or f"pathlab_task{n}_" in out)
        own = sum(s for name, s in tests.items() if folder in name and not EVERY_TASK.match(name))
        part = (mine + own + shared) / cores / measured
        total += part
        asked = pathlab_tasks.manifest(n)["ci"].get("test")
        print(f"{folder:<24} {mine:>6.0f}s {own:>6.0f}s {shared:>6.0f}s {100 * part:>12.1f}% "
              f"{5 * round(part * share / 5):>9}s {asked if asked is not None else '-':>9}s")
    print(f"{'the tasks':<24} {'':>23} {100 * total:>12.1f}% {5 * round(total * share / 5):>9}s  "
          f"(the framework's base: {100 * (1 - total):.1f} %)")
    return 0
