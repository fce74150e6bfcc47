#!/usr/bin/env python3
"""The Gradescope autograder as Gradescope runs it: tools/gradescope/make-zip.sh
builds the zip (an assignment of every task, the extensions too); it is unpacked into a scratch folder standing in for
/autograder (AUTOGRADER_ROOT), so the zip's root is AUTOGRADER_ROOT/source;
setup.sh runs there once (as root, without apt-get: PATHLAB_SKIP_APT=1, the
packages must be installed), run_autograder is copied to AUTOGRADER_ROOT/,
and then, for each submission, the student's files are put flat in
AUTOGRADER_ROOT/submission and run_autograder must write
AUTOGRADER_ROOT/results/results.json in Gradescope's schema:
  - a half-done submission (flat): the reference's files for half the tasks,
    task 3 and five drawn afresh for each commit (PATHLAB_ZIP_DONE_TASKS=1,3
    names them), the untouched stubs for the others: full marks on the
    first, 0 on the others, every test present and none a build failure.
    (Each task is graded from the reference or from its stub on a commit,
    both within a few; the reference's full marks in every suite are
    grader-reference-full-marks' to check on each.)
  - five mutants and two alternates (SAME_SCORE_FILES: one task file each):
    graded, and kept with their submissions for grader/tests/test_check.py,
    which checks that a student's tools/check gives the same per-test scores.
Every submission and its results.json are kept in WORK_DIR/gradescope-results/.
Nothing may be written to the real /autograder. The scratch folder is
removed when everything passed (kept with --keep, or on failure).

usage: test_gradescope.py REPO_ROOT WORK_DIR [--keep]"""
import json
import os
import runpy
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile
from pathlib import Path

root, work_dir = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
keep = "--keep" in sys.argv[3:]
work = work_dir / "gradescope"
autograder = work / "autograder"  # stands in for /autograder
REAL = Path("/autograder")
SETUP_TIMEOUT, GRADE_TIMEOUT = 1200, 900
sys.path.insert(0, str(root))  # the repository: the import root (docs/architecture.md)
from tools import pathlab_tasks  # noqa: E402  (the task list: the tasks/NN-name folders)
from tools.release.platforms import unpack  # noqa: E402  (like unzip, as Gradescope unpacks the zip)
from tests.support.scratch import finish  # noqa: E402
ALL_TASKS = sorted(pathlab_tasks.tasks(root))
VISIBILITIES = {"hidden", "after_due_date", "after_published", "visible"}
# Graded here and by a student's tools/check (test_check.py): mistakes that
# keep part of the points, and correct solutions written differently.
SAME_SCORE_FILES = ["mutants/01-camera-rays/half-pixel-offset.cpp",  # generated (tests/mutants/generate.py)
                    "mutants/02-intersection/swapped-barycentrics.cpp",
                    "mutants/03-bvh/median-split.cpp",
                    "mutants/05-path-tracing/roulette-not-rescaled.cpp",
                    "mutants/07-environment/pdf-without-sin-theta.cpp",
                    "alternates/03-bvh/eight-bins.cpp",
                    "alternates/06-mirror-glass/exact-fresnel.cpp"]
kept = work_dir / "gradescope-results"  # KIND/ (the submission) and KIND.json, for test_check.py


def snapshot(path: Path):
    """What exists under `path` (paths, sizes, mtimes): the real /autograder must not change."""
    if not path.exists():
        return None
    found = {}
    for dirpath, dirnames, filenames in os.walk(path):
        for name in dirnames + filenames:
            p = os.path.join(dirpath, name)
            try:
                s = os.lstat(p)
                found[p] = (s.st_size, s.st_mtime_ns)
            except OSError:
                pass
    return found


def environment() -> dict:
    env = dict(os.environ, AUTOGRADER_ROOT=str(autograder), PATHLAB_SKIP_APT="1")
    if shutil.which("ccache") and "CMAKE_CXX_COMPILER_LAUNCHER" not in env:
        env["CMAKE_CXX_COMPILER_LAUNCHER"] = "ccache"  # picked up by setup.sh's first configure
    return env


def schema_problems(report) -> list:
    problems = []
    if not isinstance(report, dict):
        return ["results.json is not a JSON object"]
    if not isinstance(report.get("score"), (int, float)):
        problems.append("no numeric top-level score")
    tests = report.get("tests")
    if not isinstance(tests, list) or not tests:
        return problems + ["no tests[]"]
    for test in tests:
        for field, kind in (("name", str), ("score", (int, float)), ("max_score", (int, float)), ("output", str)):
            if not isinstance(test.get(field), kind):
                problems.append(f"test {test.get('name', '?')}: {field} missing or not {kind}")
        if "visibility" in test and test["visibility"] not in VISIBILITIES:
            problems.append(f"test {test.get('name')}: visibility {test['visibility']!r}")
        if "status" in test and test["status"] not in ("passed", "failed"):
            problems.append(f"test {test.get('name')}: status {test['status']!r}")
    for entry in report.get("leaderboard", []):  # Gradescope's form: name, value, optional order
        if not (isinstance(entry.get("name"), str) and isinstance(entry.get("value"), (int, float))
                and entry.get("order", "desc") in ("asc", "desc")):
            problems.append(f"leaderboard entry {entry!r}")
    names = [t.get("name") for t in tests]
    if len(set(names)) != len(names):
        problems.append("test names are not unique")
    if not problems and abs(sum(t["score"] for t in tests) - report["score"]) > 1e-6:
        problems.append(f"score {report['score']} is not the sum of the tests' scores")
    return problems


def grade(kind: str, sources, env, failures):
    """Runs run_autograder on `sources` put flat in the submission folder; returns results.json or None."""
    submission, results = autograder / "submission", autograder / "results"
    for folder in (submission, results):
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir()
    for source in sources:  # tasks/*/debugger.cpp: seven of one name, the first kept (the grader ignores it)
        name = source.name
        if source.parent.parent.name in ("mutants", "alternates"):  # handed in as the task's own file
            name = source.parent.name[3:].replace("-", "_") + ".cpp"
        if not (submission / name).exists():
            shutil.copy(source, submission / name)
    shutil.rmtree(kept / kind, ignore_errors=True)
    shutil.copytree(submission, kept / kind)
    start = time.time()
    with open(results / "stdout", "w") as log:  # as Gradescope's harness keeps it
        run = subprocess.run([str(autograder / "run_autograder")], cwd=autograder, env=env, stdout=log,
                             stderr=subprocess.STDOUT, timeout=GRADE_TIMEOUT)
    seconds = time.time() - start
    stdout = (results / "stdout").read_text(errors="replace")
    out = results / "results.json"
    print(f"{kind}: run_autograder exit {run.returncode}, {seconds:.0f} s")
    if run.returncode != 0:
        failures.append(f"{kind}: run_autograder exited {run.returncode}:\n{stdout[-2000:]}")
    if not out.exists():
        failures.append(f"{kind}: no results.json in {results}:\n{stdout[-2000:]}")
        return None
    if f"grading {submission}/" not in stdout:
        failures.append(f"{kind}: the grader did not grade the files in {submission}:\n{stdout[-1000:]}")
    shutil.copy(out, kept / f"{kind}.json")
    report = json.loads(out.read_text())
    problems = schema_problems(report)
    failures += [f"{kind}: {p}" for p in problems]
    if problems:
        return None
    points = sum(t["max_score"] for t in report["tests"])
    print(f"{kind}: score {report['score']:g} of {points:g}, {len(report['tests'])} tests; "
          f"output: {report.get('output', '').splitlines()[:1]}")
    return report


def main() -> int:
    failures = []
    real_before = snapshot(REAL)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    shutil.rmtree(kept, ignore_errors=True)
    kept.mkdir(parents=True)
    env = environment()
    start = time.time()

    # The zip, unpacked where Gradescope unpacks it.
    with tempfile.TemporaryDirectory(prefix="pathlab-zip-") as temp:
        archive = Path(temp) / "autograder.zip"
        # An assignment with every task, the extensions too (make-zip.sh --tasks).
        subprocess.run(["bash", str(root / "tools/gradescope/make-zip.sh"), str(archive), "--tasks",
                        ",".join(str(n) for n in ALL_TASKS)], check=True, stdout=subprocess.DEVNULL, timeout=300)
        names = set(zipfile.ZipFile(archive).namelist())
        for required in ("setup.sh", "run_autograder", "gradescope-timeout", "gradescope-tasks", "source/CMakeLists.txt",
                         "source/tools/grade"):
            if required not in names:
                failures.append(f"the zip has no {required}")
        print(f"zip: {archive.stat().st_size >> 20} MB, {len(names)} entries")
        unpack(archive, autograder / "source")
    for script in ("setup.sh", "run_autograder"):
        if not os.access(autograder / "source" / script, os.X_OK):
            failures.append(f"{script} is not executable in the zip")

    # setup.sh, once, from the unpacked zip (Gradescope runs it as root when it builds the image).
    t = time.time()
    log = work / "setup.log"
    with open(log, "w") as out:
        setup = subprocess.run(["bash", "./setup.sh"], cwd=autograder / "source", env=env, stdout=out,
                               stderr=subprocess.STDOUT, timeout=SETUP_TIMEOUT)
    print(f"setup.sh: exit {setup.returncode}, {time.time() - t:.0f} s (log: {log})")
    if setup.returncode != 0:
        failures.append(f"setup.sh exited {setup.returncode}:\n{log.read_text(errors='replace')[-3000:]}")
    else:
        cache = autograder / "source/source/build-grade/CMakeCache.txt"
        if f"CMAKE_HOME_DIRECTORY:INTERNAL={autograder}/source/source" not in cache.read_text():
            failures.append(f"setup.sh's build is not the unpacked tree's ({cache})")
        shutil.copy(autograder / "source/run_autograder", autograder / "run_autograder")  # as Gradescope does

        # Task 3 always done: the leaderboard below needs its tree.
        if os.environ.get("PATHLAB_ZIP_DONE_TASKS"):
            done = set(pathlab_tasks.parse_task_list(os.environ["PATHLAB_ZIP_DONE_TASKS"], ALL_TASKS,
                                                     "PATHLAB_ZIP_DONE_TASKS"))
        else:
            others = [n for n in ALL_TASKS if n != 3]
            done = {3, *pathlab_tasks.commit_random("gradescope-zip", root).sample(others, len(others) // 2)}
        folders = pathlab_tasks.tasks(root)
        sources = sorted(path for n in ALL_TASKS
                         for path in (root / ("solutions" if n in done else "tasks") / folders[n][0]).glob("*.cpp"))
        print(f"half-done: the reference's tasks {sorted(done)}, the stubs' {sorted(set(ALL_TASKS) - done)}")
        half_done = grade("half-done", sources, env, failures)
        if half_done:
            task_of = lambda test: int(test["name"].split(":")[0].split()[1])  # "Task 3: ..."
            wrong = [t["name"] for t in half_done["tests"]
                     if t["score"] != (t["max_score"] if task_of(t) in done else 0)]
            if wrong:
                failures.append(f"half-done: not full marks on the reference's tasks {sorted(done)} and 0 on "
                                f"the stubs' (wrong: {wrong[:3]})")
            tasks = {task_of(t) for t in half_done["tests"]}
            if tasks != set(ALL_TASKS):
                failures.append(f"half-done: the tests cover {sorted(tasks)}, not tasks {ALL_TASKS}")
            compiled = [t["name"] for t in half_done["tests"] if "did not compile" in t["output"]
                        or "did not link" in t["output"]]
            if compiled:
                failures.append(f"half-done: {len(compiled)} tests report a build failure, e.g. {compiled[0]}")

        boards = {}
        made = runpy.run_path(str(root / "tests/mutants/generate.py"))["variants"](root)
        for path in SAME_SCORE_FILES:
            kind = Path(path).parent.parent.name + "-" + Path(path).stem  # e.g. mutants-half-pixel-offset
            variant = work_dir / "variants" / path
            variant.parent.mkdir(parents=True, exist_ok=True)
            variant.write_text(made[path])
            report = grade(kind, [variant], env, failures)  # its score is the validity matrix's to judge
            if report and half_done:  # every test present, whatever the submission holds
                shape = lambda r: sorted((t["name"], t["max_score"]) for t in r["tests"])
                if shape(report) != shape(half_done):
                    failures.append(f"{kind}: not the tests of the half-done submission "
                                    f"({len(report['tests'])} against {len(half_done['tests'])})")
            boards[kind] = {e["name"]: e["value"] for e in (report or {}).get("leaderboard", [])}
        # The ungraded leaderboard (task 3's tree, measured by the judge): the reference's tree (task 3
        # of the half-done), a correct builder with other bins close to it, a median split far worse; no
        # entry without task 3.
        boards["reference"] = {e["name"]: e["value"] for e in (half_done or {}).get("leaderboard", [])}
        tree = "BVH cost per ray: nodes + 10 x triangle tests (scan-like mesh)"
        ref_value = boards["reference"].get(tree)
        print(f"leaderboard ({tree}): " + ", ".join(f"{k} {v.get(tree, '-')}" for k, v in boards.items()))
        if ref_value is None or not 30 < ref_value < 45:
            failures.append(f"reference: leaderboard {boards['reference']}, expected {tree!r} near 36.7")
        elif not (abs(boards["alternates-eight-bins"].get(tree, 0) / ref_value - 1) < 0.05
                  and boards["mutants-median-split"].get(tree, 0) > 2 * ref_value
                  and boards["mutants-half-pixel-offset"] == {}):
            failures.append(f"leaderboard: {boards}")

    # Nothing outside the scratch folder: the real /autograder is untouched.
    if snapshot(REAL) != real_before:
        failures.append(f"{REAL} was {'created' if real_before is None else 'changed'}: a path is hard-coded")
    return finish("gradescope-zip", failures, work, keep, start, "ok")


if __name__ == "__main__":
    sys.exit(main())
