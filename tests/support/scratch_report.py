"""The end of a test that works in a scratch folder (the Gradescope zip, the
grading platforms, a course's own task): its time, every failure, and the
scratch folder kept to look at when one failed (or with --keep), removed
when all passed."""
import shutil
import time
from pathlib import Path


def finish(name: str, failures: list, scratch: Path, keep: bool, started: float, passed: str) -> int:
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
