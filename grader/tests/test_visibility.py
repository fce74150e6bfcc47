#!/usr/bin/env python3
"""Hidden tests stay hidden on the platforms that cannot release a test later
(Autolab, PrairieLearn, GitHub Classroom, and the student's tools/check whose
report Classroom's job shows; Gradescope honours results.json's "visibility"
itself).

A synthetic results.json of two tasks: visible tests, and "hidden",
"after_due_date" and "after_published" ones whose names, hints and outputs
carry the marker SECRET, one naming a failure picture whose bytes carry it
too. Every adapter's student-facing output (Autolab's problems, the yml and
autograde.tar make-autograder writes, grade-job's feedback and autoresult;
PrairieLearn's results; Classroom's report, also through
tools/classroom/report, and what it posts) must hold no marker (the
secret picture looked for as its data URL), keep the visible tests with
their scores, total the grader's points (hidden ones included) and, per test
on Autolab, fold a task's hidden tests into one problem "Task N: hidden tests".
No build: a few seconds.

usage: test_visibility.py REPO_ROOT WORK_DIR"""
import base64
import contextlib
import io
import json
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

root, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
sys.dont_write_bytecode = True  # no __pycache__ left in the tree's tools/
sys.path.insert(0, str(root))  # the repository: the import root (docs/architecture.md)
from grader.driver import results as results_format  # noqa: E402
from grader.platforms.autolab import grade_job, make_autograder as maker  # noqa: E402
from tests.support.fake_github import FakeGitHub  # noqa: E402

MARK = "SECRET"
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)


def leaks(what, text):
    check(MARK not in text and secret_png not in text, f"{what}: a hidden test shows:\n{text[:1500]}")


scratch = Path(tempfile.mkdtemp(prefix="visibility-", dir=work))
pictures = scratch / "results-images"
pictures.mkdir()
png = b"\x89PNG\r\n\x1a\n"
(pictures / "shown.png").write_bytes(png + b"a visible test's picture")
(pictures / "secret.png").write_bytes(png + MARK.encode() + b" picture")
secret_png = base64.b64encode((pictures / "secret.png").read_bytes()).decode()
shown_png = base64.b64encode((pictures / "shown.png").read_bytes()).decode()


def test(task, name, score, points, output, visibility=None):
    t = {"name": f"Task {task}: {name}", "score": score, "max_score": points, "output": output,
         "status": "passed" if score >= points else "failed"}
    if visibility:  # none: visible, as Gradescope reads a missing field
        t["visibility"] = visibility
    return t


tests = [
    test(1, "shown passes", 3, 3, "passed", "visible"),
    test(1, "shown fails", 0, 2, "HINT(shown hint): look here\npictures: results-images/shown.png (render)", "visible"),
    test(1, f"{MARK} name A", 1, 4, f"HINT({MARK} hint A): no\n{MARK} output A\n"
         "pictures: results-images/secret.png (render, reference)", "hidden"),
    test(1, f"{MARK} name B", 5, 5, f"passed {MARK} B", "after_due_date"),
    test(2, "shown two", 1, 1, "passed"),
    test(2, f"{MARK} name C", 0, 6, f"HINT({MARK} hint C): no\n{MARK} output C", "after_published"),
]
results = {"score": 10, "output": "10 of 21 points", "tests": tests}
(scratch / "results.json").write_text(json.dumps(results))
results = results_format.load(scratch / "results.json")  # the grader's shape
manifests = {n: [(t["name"].split(": ", 1)[1], t["max_score"], t.get("visibility", "visible"))
                 for t in tests if results_format.task_of(t) == n] for n in (1, 2)}
total, possible = 10, 21  # the hidden tests' 6 points included


def section(name, body):
    try:
        body()
    except Exception as e:  # noqa: BLE001 — one adapter's failure is reported, the others still checked
        failures.append(f"{name}: {type(e).__name__}: {e}")


# ---------------------------------------------------------------- Autolab

def autolab():
    per_test = results_format.autolab_problems(manifests, "test")
    leaks("autolab problems per test", json.dumps(per_test))
    want = [("Task 1: shown passes", 3), ("Task 1: shown fails", 2), ("Task 1: hidden tests", 9),
            ("Task 2: shown two", 1), ("Task 2: hidden tests", 6)]
    check(per_test == want, f"autolab problems per test: {per_test}, not {want}")
    per_task = results_format.autolab_problems(manifests, "task")
    check(per_task == [("Task 1", 14), ("Task 2", 7)], f"autolab problems per task: {per_task}")
    for per, problems, scores in (
            ("test", per_test, {"Task 1: shown passes": 3, "Task 1: shown fails": 0, "Task 1: hidden tests": 6,
                                "Task 2: shown two": 1, "Task 2: hidden tests": 0}),
            ("task", per_task, {"Task 1": 9, "Task 2": 1})):
        result = results_format.autolab(results, problems, per, ["total"])
        leaks(f"autolab autoresult per {per}", json.dumps(result))
        check(result == {"scores": scores, "scoreboard": [total]},
              f"autolab autoresult per {per}: {result}, not {scores} and total {total}")

    # make-autograder's assessment, with these manifests for its judges; grade-job's check agrees with it.
    maker.judges = lambda build, tasks: {n: manifests[n] for n in tasks}
    for per in ("test", "task"):
        out = scratch / f"autolab-{per}"
        argv, sys.argv = sys.argv, ["make-autograder", str(out), "--tasks", "1,2", "--per", per, "--name", "a",
                                    "--timeout", "300"]
        try:
            maker.main()
        finally:
            sys.argv = argv
        leaks(f"make-autograder --per {per}: a.yml", (out / "a/a.yml").read_text())
        with tarfile.open(out / "a/autograde.tar") as tar:
            settings = json.load(tar.extractfile("pathlab-autolab.json"))
        leaks(f"make-autograder --per {per}: autograde.tar", json.dumps(settings))
        problems = [tuple(p) for p in settings["problems"]]  # as grade-job reads them
        check(problems == grade_job.results_format.autolab_problems(manifests, per),
              f"make-autograder --per {per}: its problems are not what grade-job checks them against")

    text = grade_job.feedback(results, {"tasks": [1, 2]}, [])
    leaks("grade-job feedback", text)
    for needed in ("Task 1: 9 of 14 points", "Task 2: 1 of 7 points", "passed  shown passes", "0 of 2  shown fails",
                   "shown hint", "passed  shown two", "plus 2 hidden tests (not shown)",
                   "plus 1 hidden test (not shown)"):
        check(needed in text, f"grade-job feedback: no '{needed}':\n{text}")


# ---------------------------------------------------------------- PrairieLearn

def prairielearn():
    report = results_format.prairielearn(results, scratch)
    text = json.dumps(report)
    leaks("prairielearn results", text)
    check(shown_png in text, "prairielearn results: a visible test's picture is not inlined")
    check(abs(report["score"] - total / possible) < 1e-12, f"prairielearn score {report['score']}, not {total}/{possible}")
    points = {t["name"]: (t["points"], t["max_points"]) for t in report["tests"]}
    want = {"Task 1: shown passes": (3, 3), "Task 1: shown fails": (0, 2), "Task 2: shown two": (1, 1),
            "hidden tests": (6, 15)}
    check(points == want, f"prairielearn tests: {points}, not {want}")
    hidden = [t for t in report["tests"] if t["name"] == "hidden tests"]
    check(all(not t.get("output") and "images" not in t for t in hidden), f"prairielearn: hidden tests' entry {hidden}")


# ---------------------------------------------------------------- GitHub Classroom

def classroom():
    report = results_format.classroom(results, [1, 2])
    leaks("classroom report", json.dumps(report))
    check([t["max_score"] for t in report["tasks"]] == [14, 7], "classroom: max_score not the tasks' 14 and 7")
    check(report["score"] == total, f"classroom: {report['score']} points reported, the grader's {total}")
    scores = {t["name"]: t["score"] for task in report["tasks"] for t in task["tests"]}
    check(scores == {"Task 1: shown passes": 3, "Task 1: shown fails": 0, "Task 1: hidden tests": 6,
                     "Task 2: shown two": 1, "Task 2: hidden tests": 0}, f"classroom: tests {scores}")
    check(all(not t["output"] for task in report["tasks"] for t in task["tests"] if "hidden" in t["name"]),
          "classroom: output on the hidden tests' entry")
    with FakeGitHub() as github:
        run = subprocess.run([sys.executable, "-B", str(root / "tools/classroom/report"), str(scratch / "results.json"),
                              "--tasks", "1,2", "--notify"], capture_output=True, text=True, timeout=60,
                             env=dict(os.environ, **github.env()))
        posted = github.points()
        sent = json.dumps(github.updates)
    check(run.returncode == 1, f"tools/classroom/report (not full marks): exit {run.returncode}: {run.stderr[-800:]}")
    leaks("tools/classroom/report", run.stdout + run.stderr + sent)
    check(f"Total points: {total:g}/21\n" in run.stdout and posted == [f"Points {total:g}/21"],
          f"tools/classroom/report: posted {posted}, printed\n{run.stdout}")


def student_check():
    """tools/check's report and its Markdown summary (what Classroom's job log and run summary show)."""
    from grader.driver import check as check_tool
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        check_tool.report(results, "reference", show_all=True)
    text = printed.getvalue() + check_tool.markdown(results, "reference")
    leaks("tools/check's report", text)
    check("3 hidden tests" in text and "shown fails" in text, f"tools/check's report: visible tests or the count "
          f"of hidden ones missing:\n{text}")


for name, body in (("autolab", autolab), ("prairielearn", prairielearn), ("classroom", classroom),
                   ("tools/check", student_check)):
    section(name, body)
if failures:
    print("FAIL: " + "\n\nFAIL: ".join(failures))
    print(f"(scratch kept: {scratch})")
    sys.exit(1)
shutil.rmtree(scratch)
print("PASS: no hidden test's name, points, hint, output or picture in Autolab's, PrairieLearn's or Classroom's "
      "output; visible tests and the grader's total kept")
