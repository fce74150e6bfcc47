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
