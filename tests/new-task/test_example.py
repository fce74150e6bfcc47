#!/usr/bin/env python3
"""The worked example a course starts its own task from
(tools/task-examples/cone-light: `tools/new-task 13 NAME --from cone-light`),
made in a scratch copy of the repository, built and tested as the course
would test its own task (docs/own-task.md):

  1. its suite passes on the reference and fails on the stub; each of its
     six mutants loses points and each of its three alternates keeps them
     all (CTest, the validity matrix's tests of the copy);
  2. the sampling lab accepts the reference's and the alternates' cone
     warp and rejects the stub's and the theta-uniform mutant's
     (tests/lab/check_lab.py --task);
  3. tools/grade gives the stub 0 and the reference every point, 14;
  4. its handout's test table is its suite's (tools/handout-tables --check
     --tasks 13), every check has its hint (tools/hint-catalogue --check),
     and the student release of tasks 2 and 13 reads as a complete course
     and passes its own build-free CTests (tests/docs/check_release_text.py);
  5. its debugger view and its lab warp draw (the pictures are kept in
     WORK_DIR/task-example/ for a person to look at).

usage: test_example.py REPO_ROOT WORK_DIR [--keep]"""
import json
import os
import re
import shutil
import sys
import time
from pathlib import Path

root, work_dir = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
keep = "--keep" in sys.argv[3:]
sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the repository: the import root (docs/architecture.md)
from tests.support.scratch import copy_worktree, expectation, finish, step_runner  # noqa: E402
work = work_dir / "task-example"
copy = work / "repo"
build = copy / "build"
N, NAME, FOLDER = 13, "cone-light", "13-cone-light"
WARP = f"{NAME}-cone"
failures = []
started = time.time()
run = step_runner(copy, failures)  # each step: its exit and seconds printed, a failure recorded
expect = expectation(failures)


def build_and_test():
    """1-2. The build, the suite, its mutants and alternates, and the lab's cases."""
    run(["cmake", "--preset", "release", "-DPATHLAB_BUILD_VALIDITY=ON"], what="configure (release preset)")
    targets = run(["cmake", "--build", build, "--target", "help"], what="the build's targets").stdout
    labs = re.findall(rf"^(pathlab-lab-\w+-{FOLDER}-\S+):", targets, re.M)
    expect(len(labs) == 4, f"not one lab program for each of the 4 lab cases: {labs}")
    built = run(["cmake", "--build", build, "--parallel", str(os.cpu_count() or 2), "--target", "pathlab",
                 f"validity-{FOLDER}", *labs], timeout=1500, what="build pathlab, the judge, its candidates and labs")
    warnings = [line for line in built.stdout.splitlines() if "warning:" in line and FOLDER in line]
    expect(not warnings, f"warnings in the example's files: {warnings[:3]}")
    tests = run(["ctest", "--test-dir", build, "-R", FOLDER, "--output-on-failure"], timeout=900,
                what=f"ctest -R {FOLDER}")
    passed = set(re.findall(r"Test +#\d+: (\S+) \.+\s+Passed", tests.stdout))
    mutants = {f"mutants/{FOLDER}/{m}" for m in ("sine-not-cosine", "inside-is-zero", "theta-uniform",
                                                 "pdf-without-two", "axis-reversed", "pdf-outside-the-cone")}
    alternates = {f"alternates/{FOLDER}/{a}" for a in ("cos-from-the-edge", "own-frame", "distance-first")}
    expected = {FOLDER, f"{FOLDER}-fails-on-stub", *mutants, *alternates}
    expect(expected <= passed, f"ctest -R {FOLDER} did not pass {sorted(expected - passed)}")
    run([sys.executable, copy / "tests/lab/check_lab.py", build / "pathlab", build / "tests", copy / "tests",
         "--task", FOLDER], what=f"check_lab.py --task {FOLDER}")


def grade():
    """3. The stub 0, the reference every point."""
    env = dict(os.environ, PATHLAB_SANDBOX_UID=os.environ.get("PATHLAB_SANDBOX_UID", "64997"))
    for kind, want in (("tasks", 0), ("solutions", 14)):
        out = work / f"grade-{kind}.json"
        run([sys.executable, copy / "tools/grade", copy / kind, "--tasks", str(N), "--build-dir", build, "--out", out],
            env=env, check=kind == "solutions", what=f"tools/grade {kind} --tasks {N}")
        report = json.loads(out.read_text()) if out.exists() else {"tests": []}
        points = sum(t["max_score"] for t in report["tests"])
        expect(report.get("score") == want and points == 14,
               f"tools/grade {kind}: {report.get('score')} of {points}, not {want} of 14")


def text_and_pictures():
    """4-5. The handout's table, the hints, the debugger's view and the lab's warp."""
    run([sys.executable, copy / "tools/handout-tables", build, "--check", "--tasks", str(N)],
        what=f"handout-tables --check --tasks {N}")
    run([sys.executable, copy / "tools/hint-catalogue", "--check"], what="hint-catalogue --check")
    # The release of tasks 2 and 13 reads as a complete course and passes its own build-free tests.
    run([sys.executable, copy / "tests/docs/check_release_text.py", copy, "--tasks", f"2,{N}"],
        what=f"check_release_text.py (the release of tasks 2 and {N})")
    view = run([build / "pathlab", "debug", "--task", str(N), "--view", "cone", "-o", work / "cone-view.png"],
               what=f"pathlab debug --task {N} --view cone")
    expect("0 outside the cone, 0 with a pdf other than" in view.stdout,
           f"the cone view reports directions outside the cone or a wrong pdf: {view.stdout[-400:]}")
    lab = run([build / "pathlab", "lab", WARP, "-o", work / "lab.png"], what=f"pathlab lab {WARP}")
    expect("ACCEPTED" in lab.stdout, f"the lab did not accept the reference's cone: {lab.stdout[-400:]}")


def main() -> int:
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    copy_worktree(root, copy)
    git = ["git", "-c", "user.name=PathLab", "-c", "user.email=pathlab@example.invalid"]
    for argv in (["init", "-q"], ["add", "-A"], ["commit", "-q", "-m", "the course before its own task"]):
        run(git + argv, what="git " + argv[0])  # the packagers package a git checkout's working tree
    made = run([sys.executable, copy / "tools/new-task", str(N), NAME, "--from", "cone-light", "--title",
                "Cone sampling", "--label", "Cone light"], what=f"tools/new-task {N} {NAME} --from cone-light")
    if made.returncode == 0:
        for step in (build_and_test, grade, text_and_pictures):
            step()
    return finish("task-example", failures, copy, keep, started,
                  "the worked example built, its mutants caught, its alternates passed, graded and drawn")


if __name__ == "__main__":
    sys.exit(main())
