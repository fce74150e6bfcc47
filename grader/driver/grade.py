"""Grades a submission task by task, as a TA (or Gradescope) would.

  tools/grade SUBMISSION [--tasks 1,2,...] --out results.json [--timeout S]
              [--task-budget S] [--budget S] [--build-dir DIR] [--fail-under PERCENT]
              [--sandbox auto|bwrap|uid|none] [--sanitize thread|address,undefined]

SUBMISSION is a folder or a .zip: the task files are found anywhere in it
(flat, tasks/NN-name/, or a whole repository) and the file graded for each
task is printed. `tools/grade solutions` gives full marks, `tools/grade
tasks` (the stubs) none.

Judge and candidate (docs/ta-guide.md): each task's suite is a judge built
from the repository alone (tests, framework, reference); it owns the test
cases, their points and the verdicts, and never runs student code. The
student's file is compiled in a sandbox and linked into a candidate with the
framework and the reference for the other tasks; the candidate only computes
what the judge asks, in the sandbox, one fresh sandbox per test case. The
points come from a verdict file only the judge can write, never from
anything the candidate prints. Every test case has a time limit (--timeout),
every task and the whole submission a budget: tests not reached are reported
as such. results.json (Gradescope's schema) is always written; a failed
image test names its pictures in its output, in results-images/ beside it
(for --out results.json)."""
import argparse
import os
from pathlib import Path

from tools import pathlab_tasks  # the task list, and which tasks are the core
from . import grading  # what tools/grade and tools/check share
from .processes import become_subreaper
from .sandbox import SANDBOX_UID, Sandbox, protect_grader_from_oom

ROOT = grading.ROOT


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("submission")
    parser.add_argument("--tasks", default=pathlab_tasks.core_tasks(),
                        help="the tasks the course handed out (default: the seven core tasks; extensions from 8)")
    parser.add_argument("--out", required=True)
    parser.add_argument("--build-dir", default=str(ROOT / "build-grade"))
    parser.add_argument("--timeout", type=float, default=grading.TEST_TIMEOUT, help="seconds per test case")
    parser.add_argument("--task-budget", type=float, default=grading.TASK_BUDGET,
                        help="seconds for one task: compiling and all its tests")
    parser.add_argument("--budget", type=float, default=grading.SUBMISSION_BUDGET,
                        help="seconds for the whole submission")
    parser.add_argument("--sandbox", default=os.environ.get("PATHLAB_SANDBOX", "auto"),
                        choices=["auto", "bwrap", "uid", "none"], help="default: auto, or PATHLAB_SANDBOX")
    parser.add_argument("--sanitize", default="", help="build with these sanitizers: thread, or address,undefined")
    parser.add_argument("--fail-under", type=float, default=None, metavar="PERCENT",
                        help="exit 1 when the score is below PERCENT of the points (for CI)")
    args = parser.parse_args()
    tasks = grading.task_numbers(args.tasks, "grade")
    if tasks is None:
        return 2
    if args.sanitize:
        os.environ["PATHLAB_SANITIZED"] = "1"
        # Reports end the test case with an error; only system libraries are suppressed.
        os.environ.setdefault("TSAN_OPTIONS", f"halt_on_error=1:suppressions={ROOT}/tests/tsan.supp")
        os.environ.setdefault("ASAN_OPTIONS", "abort_on_error=1")
        os.environ.setdefault("LSAN_OPTIONS", f"suppressions={ROOT}/tests/lsan.supp")
    become_subreaper()
    protect_grader_from_oom()
    # One grade at a time per sandbox uid: each kills every process of that
    # uid after each test (PATHLAB_SANDBOX_UID gives a second grader its own).
    import fcntl
    lock = open(f"/tmp/pathlab-sandbox-{SANDBOX_UID}.lock", "w")
    fcntl.flock(lock, fcntl.LOCK_EX)
    grader = grading.Grader(args, Sandbox(args.sandbox))
    grader.sandbox.clean_up(stale=True)  # a killed grade's leftovers (we hold the uid's lock)
    return grader.grade(Path(args.submission).resolve(), tasks)

