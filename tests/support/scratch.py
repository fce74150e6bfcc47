"""What the tests that work in a scratch folder share (the Gradescope zip, the
grading platforms, a course's own task, a student's check): the working
tree copied there, and the end: the time, every failure, and the scratch
folder kept to look at when one failed (or with --keep), removed when all
passed."""
import shutil
import subprocess
import sys
import time
from pathlib import Path


def copy_worktree(root: Path, into: Path) -> None:
    """The working tree as every packager packages it (tools/package-tree: tracked and new files,
    .gitignore respected, as they are now)."""
    subprocess.run([sys.executable, str(root / "tools/package-tree"), str(into)], check=True,
                   stderr=subprocess.DEVNULL)


def step_runner(default_cwd: Path, failures: list):
    """run(argv, ...): runs a step (in default_cwd unless told), prints its exit and seconds, and records
    a failure, with the end of its output, when it exits non-zero (check=False: the caller judges)."""
    def run(argv, timeout=900, cwd=None, env=None, check=True, what=None):
        started = time.time()
        p = subprocess.run([str(a) for a in argv], cwd=cwd or default_cwd, env=env, capture_output=True, text=True,
                           timeout=timeout)
        print(f"  {what or ' '.join(map(str, argv))[:110]}: exit {p.returncode}, {time.time() - started:.0f} s",
              flush=True)
        if check and p.returncode != 0:
            failures.append(f"{what or argv}: exit {p.returncode}\n{(p.stdout + p.stderr)[-2500:]}")
        return p
    return run


def expectation(failures: list):
    """expect(condition, message): records the message when the condition is false; returns the condition."""
    def expect(condition, message):
        if not condition:
            failures.append(message)
        return condition
    return expect


def finish(name: str, failures: list, scratch: Path, keep: bool, started: float, passed: str) -> int:
    if started:
        print(f"total: {time.time() - started:.0f} s")
    for failure in failures:
        print("FAIL:", failure)
    if failures:
        print(f"scratch kept: {scratch}")
        return 1
    if not keep:
        shutil.rmtree(scratch, ignore_errors=True)
    print(f"{name}: {passed}")
    return 0
