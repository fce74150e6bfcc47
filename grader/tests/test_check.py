#!/usr/bin/env python3
"""A student's `tools/check` gives Gradescope's grade, test by test.

test_gradescope.py graded submissions with run_autograder in the Gradescope
layout and kept each one (WORK_DIR/gradescope-results/KIND/, the files as
handed in) with its results.json (KIND.json): a half-done submission (the
reference's files for half the tasks, the stubs for the others), five
mutants and two alternates. Here the student release is made
(tools/make-student-release --no-check --worktree: no solutions/, no grader, the
reference compiled into reference-objects/; the default course, the seven core
tasks, while the zip grades every task) and, inside it, tools/check
grades each of those submissions as a student would run it. For every
submission: on the tasks the release hands out, the same tests, each with
the same score and points, the same total; and the check says it linked
the compiled reference. A task the release does not hand out has no suite
there, and the check refuses it by name. Also: the
release holds no solutions/ and no tools/grade; a task file that includes
a file outside the framework's headers, or that links only with the
student's own other task (a helper in another task's file), loses that
task's points as Gradescope's grader does (the rules are the grader's).
The half-done submission also goes through GitHub Classroom's workflow (the
release is made with --classroom): its steps run in the student's
repository as GitHub runs them, and what the last step posts to the
classroom and shows in the log is tools/check's points, test by test
(classroom()).

The release and its check's build (build-check/, the judges linked with
the compiled reference) are made by a first run with --prepare, which CTest
runs beside gradescope-zip; the comparison runs once both are done.

usage: test_check.py REPO_ROOT WORK_DIR [--prepare] [--keep]"""
import json
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import yaml  # Debian's python3-yaml (tools/packages.sh, pathlab_test)

root, work_dir = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
sys.path.insert(0, str(root))  # the repository: the import root (docs/architecture.md)
from tests.support.fake_github import FakeGitHub  # noqa: E402
from tests.support.scratch import finish  # noqa: E402
keep = "--keep" in sys.argv[3:]
prepare_only = "--prepare" in sys.argv[3:]
graded = work_dir / "gradescope-results"
work = work_dir / "student-check"
release = work / "release"
from tools import pathlab_tasks  # noqa: E402
CORE = [int(n) for n in pathlab_tasks.core_tasks().split(",")]
WITHHELD = [n for n in pathlab_tasks.tasks(root) if n not in CORE]  # the extensions: not handed out


def task_of(test_name: str) -> int:
    return int(re.match(r"Task (\d+):", test_name).group(1))


def per_test(report):
    return {t["name"]: (t["score"], t["max_score"]) for t in report["tests"]}


def check(submission: Path, out: Path, options=()):
    """tools/check in the release, as the README says; (exit code, stdout, results or None)."""
    start = time.time()
    run = subprocess.run([sys.executable, "tools/check", str(submission), "--out", str(out), *options], cwd=release,
                         capture_output=True, text=True, timeout=1800)
    print(f"  tools/check {submission.name}: exit {run.returncode}, {time.time() - start:.0f} s")
    return run.returncode, run.stdout + run.stderr, json.loads(out.read_text()) if out.exists() else None


def prepare() -> int:
    """The student release, made as the TA makes it, and its check's build."""
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    t = time.time()
    made = subprocess.run([str(root / "tools/make-student-release"), "--no-check", "--worktree", "--classroom",
                           str(release)], capture_output=True, text=True, timeout=1200)
    print(f"student release: exit {made.returncode}, {time.time() - t:.0f} s")
    if made.returncode != 0:
        print(f"FAIL: make-student-release:\n{made.stdout[-2000:]}{made.stderr[-2000:]}")
        return 1
    failures = []
    for absent in ("solutions", "tools/grade", "tests/mutants"):
        if (release / absent).exists():
            failures.append(f"the release has {absent}")
    if pathlab_tasks.handed_out(release) != CORE:
        failures.append(f"the release hands out {pathlab_tasks.handed_out(release)}, not the core tasks {CORE}")
    every = pathlab_tasks.tasks(root)
    for n in WITHHELD:
        folder = every[n][0]
        handout = (release / "tasks" / folder / "README.md").read_text()
        if (release / "tests" / folder).exists() or "Not handed out in this course" not in handout or \
                not (release / "tasks" / folder / every[n][1]).exists():
            failures.append(f"task {n}, not handed out: its suite is in the release, its stub is not, or its "
                            f"handout does not say so")
    if not list(release.glob("reference-objects/*/manifest.json")):
        failures.append("the release has no compiled reference (reference-objects/*/manifest.json)")
    # The check's build, as a student's first tools/check makes it (task 1 of the stubs), then every judge.
    code, output, report = check(release / "tasks", work / "stubs-task-1.json", ["--tasks", "1"])
    if report is None:
        failures.append(f"tools/check on the release's stubs wrote no results.json:\n{output[-2000:]}")
    built = subprocess.run(["cmake", "--build", str(release / "build-check"), "--target", "pathlab-judges",
                            "--parallel", str(os.cpu_count() or 2)], capture_output=True, text=True, timeout=1200)
    if built.returncode != 0:
        failures.append(f"building the release's judges failed:\n{built.stdout[-2000:]}")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


def classroom(submission: Path, mine: dict) -> list:
    """GitHub Classroom's workflow (.github/workflows/classroom.yml, installed by --classroom) on the
    student's repository holding `submission`'s files: its run steps, in order, as GitHub runs them
    (bash in the repository, with GITHUB_OUTPUT and GITHUB_STEP_SUMMARY files; the Install step's
    packages are here already), the last against a stand-in for GitHub's API (fake_github.py). The
    points it posts to the classroom, and the total and every test's points its log shows, must be
    tools/check's. Then the same step where the check wrote nothing: it must post 0 of the tasks' points."""
    problems = []
    workflow = yaml.safe_load((release / ".github/workflows/classroom.yml").read_text())
    steps = workflow.get("jobs", {}).get("run-autograding-tests", {}).get("steps", [])
    runs = [s for s in steps if "run" in s]
    listed = ",".join(map(str, CORE))
    if not (workflow.get("name") == "Autograding Tests" and [s["name"] for s in runs][:1] == ["Install"] and
            len(runs) == 3 and f"tools/check --tasks {listed} " in runs[1]["run"] and
            runs[2]["run"] == f"python3 tools/classroom/report pathlab-results.json --tasks {listed} --notify" and
            runs[2].get("if") == "always()" and runs[2].get("env") == {"GITHUB_TOKEN": "${{ github.token }}"} and
            workflow.get("permissions", {}).get("checks") == "write"):
        return [f"classroom.yml: not GitHub Classroom's workflow, the check and the points for tasks {CORE}: {runs}"]
    saved = {}
    for n in CORE:  # the student's files in their repository's tasks/ (the stubs put back after)
        folder, name = pathlab_tasks.tasks(root)[n]
        if (submission / name).exists():
            saved[release / "tasks" / folder / name] = (release / "tasks" / folder / name).read_bytes()
            shutil.copy(submission / name, release / "tasks" / folder / name)
    outputs, summary = work / "classroom-output", work / "classroom-summary.md"
    outputs.write_text("")
    summary.write_text("")
    most = sum(t["max_score"] for t in mine["tests"])
    logs = {}
    try:
        with FakeGitHub() as github:
            for step in runs[1:]:
                ran = subprocess.run(["bash", "-e", "-c", step["run"]], cwd=release, capture_output=True, text=True,
                                     timeout=1800, env=dict(os.environ, GITHUB_OUTPUT=str(outputs),
                                                            GITHUB_STEP_SUMMARY=str(summary), **github.env()))
                print(f"  classroom.yml step '{step['name']}': exit {ran.returncode}")
                logs[step["name"]] = ran
            posted = github.points()
    finally:
        for path, data in saved.items():
            path.write_bytes(data)
    points = logs[runs[2]["name"]]
    # Not full marks: the step fails, as GitHub's reporter fails it; what it posted is what counts.
    if points.returncode != (0 if mine["score"] == most else 1):
        problems.append(f"classroom.yml's points step: exit {points.returncode}:\n{points.stdout[-800:]}{points.stderr[-800:]}")
    if posted != [f"Points {mine['score']:g}/{most:g}"]:
        problems.append(f"classroom: posted {posted}, tools/check gave {mine['score']:g} of {most:g}")
    if f"Total points: {mine['score']:g}/{most:g}\n" not in points.stdout:
        problems.append(f"classroom: the log's total is not tools/check's {mine['score']:g}/{most:g}:\n"
                        f"{points.stdout[-600:]}")
    shown_lines = {line.strip() for line in points.stdout.splitlines()}
    missing = [t["name"] for t in mine["tests"] if
               f"{'ok  ' if t['score'] >= t['max_score'] else 'FAIL'} {t['score']:g}/{t['max_score']:g}  {t['name']}"
               .strip() not in shown_lines]
    if missing:
        problems.append(f"classroom: the log does not show tools/check's points for {missing[:3]}")
    if not problems:
        print(f"  classroom: posted {posted[0]}, the log's total and its {len(mine['tests'])} tests tools/check's")
    if f"### PathLab check: {mine['score']:g} of" not in summary.read_text():
        problems.append("classroom: the grade's table is not on the run's summary page")
    # A check that wrote nothing (it crashed, or the runner ran out of time): 0 points are posted.
    with FakeGitHub() as github:
        crashed = subprocess.run(["bash", "-e", "-c", runs[2]["run"].replace("pathlab-results.json", "no-such.json")],
                                 cwd=release, capture_output=True, text=True, timeout=300,
                                 env=dict(os.environ, **github.env()))
        posted = github.points()
    handouts = sum(pathlab_tasks.handout_points(n, release) for n in CORE)
    if crashed.returncode != 1 or posted != [f"Points 0/{handouts}"]:
        problems.append(f"classroom: with no results the points step exited {crashed.returncode} and posted {posted}, "
                        f"not Points 0/{handouts}:\n{crashed.stderr[-600:]}")
    return problems


def main() -> int:
    if prepare_only:
        return prepare()
    failures = []
    kinds = sorted(p.stem for p in graded.glob("*.json"))
    expected = {"half-done"}
    if not expected <= set(kinds) or len(kinds) < 8:
        print(f"FAIL: {graded} holds {kinds}: run gradescope-zip first (test_gradescope.py)")
        return 1
    if not (release / "build-check" / "pathlab-reference.txt").exists():
        print(f"FAIL: no student release with its check's build in {release}: run test_check.py --prepare first")
        return 1

    for kind in kinds:
        gradescope = json.loads((graded / f"{kind}.json").read_text())
        code, output, mine = check(graded / kind, work / f"{kind}.json")
        if mine is None:
            failures.append(f"{kind}: tools/check wrote no results.json:\n{output[-2000:]}")
            continue
        theirs = {n: v for n, v in per_test(gradescope).items() if task_of(n) in CORE}
        ours = per_test(mine)
        gradescope_score = sum(t["score"] for t in gradescope["tests"] if task_of(t["name"]) in CORE)
        differ = [(n, theirs.get(n), ours.get(n)) for n in sorted(set(theirs) | set(ours)) if theirs.get(n) != ours.get(n)]
        print(f"{kind}: Gradescope {gradescope_score:g}, tools/check {mine['score']:g} of "
              f"{sum(t['max_score'] for t in mine['tests']):g}; {len(ours)} tests, {len(differ)} differ")
        for name, a, b in differ[:5]:
            failures.append(f"{kind}: {name}: Gradescope {a}, tools/check {b}")
        if mine["score"] != gradescope_score:
            failures.append(f"{kind}: total {mine['score']:g} against Gradescope's {gradescope_score:g} (tasks {CORE})")
        if "WARNING" in output or "compiled: reference-objects/" not in \
                (release / "build-check/pathlab-reference.txt").read_text():
            failures.append(f"{kind}: the check did not link the compiled reference:\n{output[-1500:]}")
        if "Total" not in output:
            failures.append(f"{kind}: no table in the check's output:\n{output[-1500:]}")
        if kind == "half-done":  # the same submission through GitHub Classroom's workflow
            failures += classroom(graded / kind, mine)

    # A task the release does not hand out: refused by name, not graded against a suite it lacks.
    for n in WITHHELD:
        code, output, _ = check(release / "tasks", work / f"withheld-{n}.json", ["--tasks", str(n)])
        if code != 2 or f"task {n} is not handed out in this course" not in output:
            failures.append(f"tools/check --tasks {n} (not handed out): exit {code}, not a refusal:\n{output[-800:]}")

    # The grader's include rule: a framework-internal path is refused, as on Gradescope.
    sneaky = work / "sneaky"
    sneaky.mkdir(exist_ok=True)
    source = (root / "solutions/01-camera-rays/camera_rays.cpp").read_text()
    (sneaky / "camera_rays.cpp").write_text('#include "../../framework/core/camera.h"\n' + source)
    _, output, report = check(sneaky, work / "sneaky.json")
    task1 = [t for t in (report or {"tests": []})["tests"] if t["name"].startswith("Task 1:")]
    if not task1 or any(t["score"] for t in task1) or "includes files other than" not in task1[0]["output"]:
        failures.append(f"an include outside the framework's headers was not refused:\n{output[-1500:]}")

    # A task file that only links with the student's own other task (a helper
    # written in intersection.cpp, used by direct_lighting.cpp): fine in the
    # student's build, 0 for task 4 on Gradescope, and so in the check.
    shared = work / "shared-helper"
    shared.mkdir(exist_ok=True)
    intersection = (root / "solutions/02-intersection/intersection.cpp").read_text()
    end = intersection.rindex("}  // namespace pathlab")
    (shared / "intersection.cpp").write_text(
        intersection[:end] + "float myInverseOrZero(float x) { return x != 0.0f ? 1.0f / x : 0.0f; }\n" + intersection[end:])
    lighting = (root / "solutions/04-direct-lighting/direct_lighting.cpp").read_text()
    helper_use = "Color lambertianBrdf(const Color& albedo) { return albedo * kInvPi; }"
    if helper_use not in lighting:
        failures.append("solutions/04-direct-lighting/direct_lighting.cpp changed: update the shared-helper case")
    (shared / "direct_lighting.cpp").write_text(lighting.replace(
        helper_use, "float myInverseOrZero(float x);\n"
                    "Color lambertianBrdf(const Color& albedo) { return albedo * (kInvPi * myInverseOrZero(1.0f)); }"))
    _, output, report = check(shared, work / "shared-helper.json")
    by_task = {}
    for test in (report or {"tests": []})["tests"]:
        by_task.setdefault(test["name"].split(":")[0], []).append(test)
    task2, task4 = by_task.get("Task 2", []), by_task.get("Task 4", [])
    if not task2 or any(t["score"] < t["max_score"] for t in task2) or not task4 or \
            any(t["score"] for t in task4) or "did not link on its own" not in task4[0]["output"] or \
            "myInverseOrZero" not in output:
        failures.append(f"a task file using another task's helper: not task 2 full and task 4 0 "
                        f"with the linker's reason in the table:\n{output[-1500:]}")

    return finish("student-check", failures, work, keep, 0,
                  f"{len(kinds)} submissions, the same score test by test as Gradescope's")


if __name__ == "__main__":
    sys.exit(main())
