"""Check before you submit: the grade your task files will get.

  tools/check [SUBMISSION] [--tasks 1,2,...] [--out FILE] [--all] [--summary FILE]

Grades SUBMISSION (default: this repository's tasks/; also a folder or a
.zip shaped like a Gradescope submission) exactly as the course's grader
does, minus its sandbox: each task file compiled alone with the grader's
flags and include rules, linked with the reference for every other task,
judged by the same suites with the same points, time limits and budgets.
Prints a line per task (a mark per test: . passed, x failed, t timed out
or not run) with what failed and what ran close to its time limit, and
writes the grader's results.json (default: build-check/results.json).

The score is Gradescope's for the visible tests when this release carries
the reference compiled for your platform (it says so when it does not);
hidden tests and a machine much slower or faster than the grader's can
still differ: each test's time is shown against its limit.
(Windows: python3 tools/check.)"""
import argparse
import json
import re
import shutil
import sys
import textwrap
import threading
import time
from pathlib import Path

from tools import pathlab_tasks
from . import grading  # what tools/grade and tools/check share
from .results import shown

ROOT = grading.ROOT
SLOW = 0.5  # a test that used more than this share of its time limit is reported


class Progress:
    """One line that rewrites itself on a terminal (plain lines elsewhere),
    with the seconds spent on the current step."""

    def __init__(self):
        self.tty = sys.stdout.isatty()
        self.text, self.since = "", time.time()
        self.shown = None  # a log's last step
        self.notes = []    # what the grader said besides progress (which file it graded, ...)
        self.lock = threading.Lock()
        self.done = threading.Event()
        if self.tty:
            threading.Thread(target=self._tick, daemon=True).start()

    def _tick(self):
        while not self.done.wait(1.0):
            with self.lock:
                self._draw()

    def _draw(self):
        seconds = time.time() - self.since
        line = f"{self.text} ({seconds:.0f} s)" if seconds >= 2 else self.text
        width = shutil.get_terminal_size((100, 20)).columns - 1
        sys.stdout.write("\r\033[K" + line[:width])
        sys.stdout.flush()

    def __call__(self, text, progress=False):
        with self.lock:
            if progress:
                self.text, self.since = text, time.time()
                if self.tty:
                    self._draw()
                elif text.split(":")[0] != self.shown:  # a log: one line per task
                    self.shown = text.split(":")[0]
                    print(f"check: {self.shown}", flush=True)
            else:
                self.notes.append(text)

    def stop(self):
        self.done.set()
        if self.tty:
            sys.stdout.write("\r\033[K")
            sys.stdout.flush()


def reference_status(build: Path) -> str:
    path = build / "pathlab-reference.txt"
    return path.read_text().strip() if path.exists() else "unknown"


def why(output: str):
    """A failed test's first error and its hint, from the judge's output (or
    the build failure that failed every test of its task)."""
    lines = [l.strip() for l in output.splitlines() if l.strip() and not l.startswith("=====")]
    if not lines:
        return [""]
    if re.search(r"did not (compile|link|assemble)", lines[0]):
        first = next((l for l in lines[1:] if re.search(r"error|undefined reference|multiple definition", l)), "")
        return [lines[0], first] if first else [lines[0]]
    error = next((l for l in lines if "ERROR:" in l), lines[0]).split(" ERROR: ", 1)[-1]
    hint = next((l.split("): ", 1)[-1] for l in lines if l.startswith("HINT (")), "")
    return [error] + ([f"hint: {hint}"] if hint else [])


def indented(text_lines: list) -> list:
    """Each line whole, wrapped at 110 columns under a test's line: a hint is never cut short."""
    out = []
    for line in text_lines:
        out += textwrap.wrap(line, 110, initial_indent=" " * 7, subsequent_indent=" " * 9,
                             break_long_words=False, break_on_hyphens=False) or [" " * 7]
    return out


def listed(results: dict) -> list:
    """The tests a report names: the visible ones (a course's hidden tests count in the totals, unnamed,
    as on every grading platform: results.shown)."""
    return [t for t in results["tests"] if shown(t.get("visibility"))]


def report(results: dict, reference: str, show_all: bool) -> None:
    """The table: a line per task, then what failed and what was slow."""
    tasks = {}
    for test in listed(results):
        task, _, name = test["name"].partition(": ")
        tasks.setdefault(task, []).append((name, test))
    print()
    for task, tests in tasks.items():
        score = sum(t["score"] for _, t in tests)
        points = sum(t["max_score"] for _, t in tests)
        marks = "".join("." if t["score"] >= t["max_score"] else
                        ("t" if t["output"].startswith(("timed out", "not run")) else "x") for _, t in tests)
        seconds = sum(t.get("extra_data", {}).get("seconds", 0) for _, t in tests)
        print(f"{task:<8} {score:>5g} / {points:<4g} {marks:<24} {seconds:6.1f} s of {grading.TASK_BUDGET:g} s")
    total = sum(t["max_score"] for t in results["tests"])
    print(f"{'Total':<8} {results['score']:>5g} / {total:<4g}")
    for entry in results.get("leaderboard", []):  # ungraded: what the course's leaderboard would show
        better = "lower" if entry.get("order") == "asc" else "higher"
        print(f"Leaderboard (ungraded): {entry['name']} = {entry['value']:.4g} ({better} is better)")
    lines = []
    for task, tests in tasks.items():
        not_started = all(t["score"] == 0 for _, t in tests)
        spent = sum(t.get("extra_data", {}).get("seconds", 0) for _, t in tests)
        if spent > SLOW * grading.TASK_BUDGET:
            lines.append(f"  SLOW {task}: its tests took {spent:.0f} s of the task's {grading.TASK_BUDGET:g} s "
                         "budget here; tests past the budget score 0")
        if not_started and not show_all:  # a task not begun: one line, not a page of failures
            outputs = {t["output"] for _, t in tests}
            if len(outputs) == 1:  # one reason for every test: its file did not build, or was not found
                lines.append(f"  {task}: every test failed:")
                lines += indented(why(outputs.pop()))
            else:
                lines.append(f"  {task}: no test passes yet ({len(tests)} tests; --all lists them)")
        for name, test in tests:
            extra = test.get("extra_data", {})
            seconds, limit = extra.get("seconds"), extra.get("time_limit")
            slow = seconds is not None and limit and seconds > SLOW * limit
            failed = test["score"] < test["max_score"]
            if not (slow or show_all or (failed and not not_started)):
                continue
            timing = f"  [{seconds:.1f} s of {limit:g} s]" if seconds is not None else ""
            mark = "FAIL" if failed else ("SLOW" if slow else "ok")
            lines.append(f"  {mark} {test['score']:g}/{test['max_score']:g}  {test['name']}{timing}")
            if failed:
                lines += indented(why(test["output"]))
            if slow:
                lines.append(f"       used {seconds / limit:.0%} of its time limit here: on a slower machine "
                             "(the grader's may be) it could time out")
    if lines:
        print("\n" + "\n".join(lines))
    if reference.startswith("none"):
        print(f"\nWARNING: {reference[len('none: '):]}.\nSo every task was judged with YOUR files for the other "
              "tasks, not the reference: the score above may differ from Gradescope's.")
    hidden = len(results["tests"]) - len(listed(results))
    print(f"\nVisible tests only{f' ({hidden} hidden tests count in the total, unnamed)' if hidden else ''}; "
          "Gradescope may also run hidden ones. Times are this machine's.")


def markdown(results: dict, reference: str) -> str:
    """The same report for a CI job summary (GitHub's $GITHUB_STEP_SUMMARY)."""
    tasks = {}
    for test in listed(results):
        tasks.setdefault(test["name"].partition(": ")[0], []).append(test)
    total = sum(t["max_score"] for t in results["tests"])
    lines = [f"### PathLab check: {results['score']:g} of {total:g} points", "",
             "| task | points | tests passed | seconds |", "| --- | ---: | ---: | ---: |"]
    for task, tests in tasks.items():
        passed = sum(t["score"] >= t["max_score"] for t in tests)
        seconds = sum(t.get("extra_data", {}).get("seconds", 0) for t in tests)
        lines.append(f"| {task} | {sum(t['score'] for t in tests):g} / {sum(t['max_score'] for t in tests):g} "
                     f"| {passed} / {len(tests)} | {seconds:.1f} |")
    failed = [t for t in listed(results) if t["score"] < t["max_score"]]
    if failed:
        lines += ["", "<details><summary>Tests not passed</summary>", ""]
        lines += [f"- {t['name']}: {why(t['output'])[0]}" for t in failed]
        lines += ["", "</details>"]
    if reference.startswith("none"):
        lines += ["", f"**Warning:** {reference[len('none: '):]}: judged with your own files for the other tasks, "
                  "so the score may differ from Gradescope's."]
    return "\n".join(lines) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("submission", nargs="?", default=str(ROOT / "tasks"),
                        help="your task files: a folder or a zip (default: tasks/)")
    parser.add_argument("--tasks", default=",".join(map(str, pathlab_tasks.handed_out())),
                        help="default: every task your course hands out")
    parser.add_argument("--build-dir", default=str(ROOT / "build-check"))
    parser.add_argument("--out", default=None, help="results.json's path (default: BUILD_DIR/results.json)")
    parser.add_argument("--all", action="store_true", help="list every test, not only what failed or was slow")
    parser.add_argument("--summary", metavar="FILE", help="also append the report to FILE as Markdown "
                        "(CI: $GITHUB_STEP_SUMMARY)")
    args = parser.parse_args()
    tasks = grading.task_numbers(args.tasks, "check")
    if tasks is None:
        return 2
    if why := pathlab_tasks.not_handed_out(tasks):
        print(f"check: {why}", file=sys.stderr)
        return 2
    build = Path(args.build_dir).resolve()
    build.mkdir(parents=True, exist_ok=True)
    out = Path(args.out) if args.out else build / "results.json"
    # The grader's own limits and configuration (its build preset): nothing to choose.
    options = argparse.Namespace(out=str(out), build_dir=str(build), timeout=grading.TEST_TIMEOUT,
                                 task_budget=grading.TASK_BUDGET, budget=grading.SUBMISSION_BUDGET,
                                 sanitize="", fail_under=None)
    progress = Progress()
    grader = grading.Grader(options, grading.Unsandboxed(), say=progress)
    try:
        code = grader.grade(Path(args.submission).resolve(), tasks)
    finally:
        progress.stop()
    if not out.exists():
        return 2
    results, reference = json.loads(out.read_text()), reference_status(build)
    report(results, reference, args.all)
    for note in progress.notes:  # a task file missing, or found twice
        if "ignored" in note or ": no " in note:
            print(note.replace(str(ROOT) + "/", ""))
    if args.summary:
        with open(args.summary, "a") as summary:
            summary.write(markdown(results, reference))
    print(f"Written: {out}")
    return code
