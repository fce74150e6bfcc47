"""PrairieLearn's external-grading entrypoint for a PathLab question
(docs/ta-prairielearn.md): grades the task its question names
(/grade/tests/pathlab-question.json) on the files in /grade/student, with
tools/grade of this tree (the image's /opt/pathlab, built by
tools/install-grader), and writes /grade/results/results.json in
PrairieLearn's format (grader/driver/results.py): the score in [0, 1], a
test per visible test case (the hidden ones as one, "hidden tests", their
points summed), the failure pictures inlined while the file stays under
PrairieLearn's 1 MB, and "gradable": false for a submission that holds no
task file, so that it costs the student no attempt.

PL_GRADE_ROOT (default /grade) stands in for /grade in
grader/tests/test_platforms.py."""
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
from grader.driver import results as results_format
from tools import pathlab_tasks

GRADE = Path(os.environ.get("PL_GRADE_ROOT", "/grade"))
MARGIN = 20  # seconds kept for starting, linking and writing the results before PrairieLearn's timeout


def write(report: dict):
    (GRADE / "results").mkdir(parents=True, exist_ok=True)
    (GRADE / "results" / "results.json").write_text(json.dumps(report))


def main() -> int:
    try:
        question = json.loads((GRADE / "tests" / "pathlab-question.json").read_text())
        task, timeout = question["task"], question["timeout"]
        if task not in pathlab_tasks.tasks() or not isinstance(timeout, int):
            raise ValueError(f"pathlab-question.json names task {task!r}, timeout {timeout!r}")
    except (OSError, ValueError, KeyError, TypeError) as e:
        write({"gradable": False, "score": 0.0,
               "message": f"This question is not set up for PathLab's grader ({e}): please tell the course staff."})
        return 0
    with tempfile.TemporaryDirectory(prefix="pathlab-prairielearn-") as scratch:
        out = Path(scratch) / "results.json"
        run = subprocess.run([sys.executable, str(ROOT / "tools/grade"), str(GRADE / "student"), "--tasks", str(task),
                              "--out", str(out), "--build-dir", str(ROOT / "build-grade"),
                              "--budget", str(max(30, timeout - MARGIN))], capture_output=True, text=True)
        print(run.stdout[-20000:], run.stderr[-20000:], sep="\n")  # PrairieLearn shows the job's output to staff
        if not out.exists():
            write({"gradable": False, "score": 0.0, "message": "The grader failed: please tell the course staff.",
                   "output": run.stderr[-4000:]})
            return 0
        report = results_format.prairielearn(results_format.load(out), Path(scratch))
        if not report["gradable"]:
            folder, file = pathlab_tasks.tasks()[task]
            report["message"] = (f"No {file} was found in what you submitted (the task's file, "
                                 f"tasks/{folder}/{file}): this submission was not graded and costs you no attempt.")
        write(report)
    return 0
