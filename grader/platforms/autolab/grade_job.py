"""Grades one Autolab job: the student's handin in the job folder (the
current folder), as the assessment's settings say (pathlab-autolab.json,
from autograde.tar), with tools/grade of this tree and its build-grade.
Prints the feedback a student reads, then, as its last line, Autolab's
autoresult: {"scores": {problem: points}, "scoreboard": [...]}.

Run as root by pathlab-autolab-grade (grade_as_root.c), which the job's
Makefile calls; it always ends with the autoresult line and exit code 0,
because Autolab reads the last line and `make` would print after a failure.

  grade-job [--sandbox auto|bwrap|uid|none] [--sandbox-uid UID]"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
from grader.driver import results as results_format
from tools import pathlab_tasks
from grader.driver.grading import judge_manifest

SETTINGS = "pathlab-autolab.json"
MARGIN = 45               # seconds kept for starting, linking and printing before Autolab's timeout
FEEDBACK_BYTES = 200_000  # of the output Autolab keeps (Tango: 1,000 KB by default, its middle elided beyond)


def settings() -> dict:
    """The assessment's settings, checked: they come from the TA's autograde.tar."""
    path = Path(SETTINGS)
    if not path.is_file() or path.stat().st_size > 1 << 20:
        raise ValueError(f"no {SETTINGS} in the job folder: is autograde.tar PathLab's (tools/autolab/make-autograder)?")
    data = json.loads(path.read_text())
    every = pathlab_tasks.tasks()
    if not (isinstance(data.get("tasks"), list) and data["tasks"] and all(n in every for n in data["tasks"])
            and data.get("per") in ("task", "test") and isinstance(data.get("problems"), list)
            and isinstance(data.get("timeout"), int) and isinstance(data.get("handin"), str)
            and "/" not in data["handin"] and isinstance(data.get("scoreboard"), list)):
        raise ValueError(f"{SETTINGS} is malformed: remake autograde.tar with tools/autolab/make-autograder")
    return data


def feedback(results: dict, settings_: dict, notes) -> str:
    lines = [f"PathLab, tasks {', '.join(map(str, settings_['tasks']))}: {results.get('output', '').splitlines()[0]}"
             if results.get("output") else "PathLab"]
    lines += notes
    # Hidden tests (results_format.shown) count in the task's points, but are never named nor their output shown.
    visible = [t for t in results["tests"] if results_format.shown(t.get("visibility"))]
    for n, (earned, possible) in results_format.per_task(results, settings_["tasks"]).items():
        lines.append(f"\nTask {n}: {earned:g} of {possible:g} points")
        mine = [t for t in visible if results_format.task_of(t) == n]
        for test in mine:
            mark = "passed" if test["score"] >= test["max_score"] else f"{test['score']:g} of {test['max_score']:g}"
            lines.append(f"  {mark:>10}  {test['name'][len(f'Task {n}: '):]}")
        hidden = sum(results_format.task_of(t) == n for t in results["tests"]) - len(mine)
        if hidden:
            lines.append(f"  plus {hidden} hidden test{'s' if hidden > 1 else ''} (not shown)")
    failed = [t for t in visible if t["score"] < t["max_score"]]
    if failed:
        lines.append("\nWhat the failed tests said:")
    text = "\n".join(lines)
    for test in failed:
        block = f"\n--- {test['name']}\n{test.get('output', '').strip()}"
        if len(text) + len(block) > FEEDBACK_BYTES:
            text += f"\n(the outputs of {len(failed)} failed tests do not all fit Autolab's feedback: the rest left out)"
            break
        text += block
    return text


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sandbox", default="auto", choices=["auto", "bwrap", "uid", "none"])
    parser.add_argument("--sandbox-uid", type=int, help="the candidate's uid (default: tools/grade's, 64990)")
    args = parser.parse_args()
    env = dict(os.environ)
    if args.sandbox_uid is not None:
        if not 1000 <= args.sandbox_uid < 1 << 31:
            parser.error("--sandbox-uid: an unprivileged uid, 1000 or more")
        env["PATHLAB_SANDBOX_UID"] = str(args.sandbox_uid)
    problems, columns = [], []
    try:
        s = settings()
        problems, columns = [tuple(p) for p in s["problems"]], s["scoreboard"]
        notes = []
        # The assessment's problems must be this image's judges' tests: a tarball made for other
        # judges would score tests it does not know as 0.
        build = ROOT / "build-grade"
        judges = {n: judge_manifest(build, n) for n in s["tasks"]}
        if problems != results_format.autolab_problems(judges, s["per"]):
            notes.append("WARNING: this assessment's problems are not this image's tests (autograde.tar and the "
                         "image come from different PathLab trees): remake both from one tree.")
        with tempfile.TemporaryDirectory(prefix="pathlab-autolab-") as scratch:
            handin = Path(s["handin"])
            submission = handin
            if handin.suffix == ".cpp" and handin.is_file():  # one task's file: a folder of it
                submission = Path(scratch) / "handin"
                submission.mkdir()
                (submission / handin.name).write_bytes(handin.read_bytes()[:4 << 20])
            out = Path(scratch) / "results.json"
            start = time.time()
            run = subprocess.run([sys.executable, str(ROOT / "tools/grade"), str(submission.resolve()), "--tasks",
                                  ",".join(map(str, s["tasks"])), "--out", str(out), "--build-dir", str(build),
                                  "--budget", str(max(60, s["timeout"] - MARGIN)), "--sandbox", args.sandbox],
                                 capture_output=True, text=True, env=env)
            if not out.exists():
                raise RuntimeError(f"the grader wrote no results (exit {run.returncode}): {run.stderr[-500:]}")
            results = results_format.load(out)
            if not handin.exists():
                notes.append(f"No handin file {handin.name} was found.")
            print(feedback(results, s, notes))
            print(f"(graded in {time.time() - start:.0f} s of Autolab's {s['timeout']} s)")
            result = results_format.autolab(results, problems, s["per"], columns)
    except Exception as e:  # noqa: BLE001 — Autolab still gets its last line
        print(f"PathLab could not grade this handin: {type(e).__name__}: {e}")
        result = {"scores": {name: 0 for name, _ in problems}, "scoreboard": [0 for _ in columns]}
    sys.stdout.flush()
    print(json.dumps(result))
    return 0
