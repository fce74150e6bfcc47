"""What the tests that work in a scratch folder share (the Gradescope zip, the
grading platforms, a course's own task, a student's check): the working
tree copied there, and the end: the time, every failure, and the scratch
folder kept to look at when one failed (or with --keep), removed when all
passed."""
import shutil
import subprocess
import time
from pathlib import Path


def copy_worktree(root: Path, into: Path) -> None:
    """The files of the working tree (tracked and untracked, .gitignore respected), as they are now."""
    listed = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                            capture_output=True, check=True).stdout.decode().split("\0")
    for rel in filter(None, listed):
        if (root / rel).is_file():
            (into / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(root / rel, into / rel)


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
