#!/usr/bin/env python3
"""Grading is reproducible: the same submission graded twice (the second
time reusing the first build) gives the same results.json, test by test —
scores, statuses and every line of output — apart from the run times.

usage: test_same_grade.py REPO GRADE_BUILD_DIR FIRST_RESULTS.json"""
import json
import re
import subprocess
import sys
from pathlib import Path


def comparable(results: dict) -> dict:
    results = dict(results)
    results.pop("execution_time", None)
    # Lines that report seconds are the only ones allowed to differ.
    seconds = re.compile(r"\d+(\.\d+)? ?s\b")
    results["output"] = "\n".join(l for l in results.get("output", "").splitlines() if not seconds.search(l))
    # Each test's measured time (extra_data) likewise.
    results["tests"] = [{k: v for k, v in t.items() if k != "extra_data"} for t in results.get("tests", [])]
    return results


def main() -> int:
    repo, build, first = Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
    second = first.parent / "grade-solutions-again.json"
    subprocess.run([str(repo / "tools/grade"), str(repo / "solutions"), "--out", str(second),
                    "--build-dir", str(build)], check=True, stdout=subprocess.DEVNULL)
    a, b = comparable(json.loads(first.read_text())), comparable(json.loads(second.read_text()))
    if a["tests"] != b["tests"] or a["score"] != b["score"]:
        for x, y in zip(a["tests"], b["tests"]):
            if x != y:
                print(f"differs: {x['name']}\n  first:  {x}\n  second: {y}")
        return 1
    print(f"same grade twice: {a['score']} points, {len(a['tests'])} tests identical")
    return 0


if __name__ == "__main__":
    sys.exit(main())
