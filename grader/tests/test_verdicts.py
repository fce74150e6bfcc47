"""CTest verdict-round-trip: what a judge writes, the grader reads back.

The judge (verdict_round_trip.cpp, linked with pathlab_judge) prints its
listing and writes its verdicts with the words of grader/suite/verdicts.json,
made into C++ by CMake; grader/driver/verdicts.py reads them with the same
file's words. Each test case is run alone as tools/grade runs one (selected by
verdict_format.test_case_filter, its verdict file named by the variable the
JSON names), then all at once; the grader must read back each one's name,
points, visibility, outcome and leaderboard entries exactly.

  test_verdicts.py JUDGE"""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the repository: the import root (docs/architecture.md)
from grader.driver import results as results_format
from grader.driver import verdicts as verdict_format

# (name, points, visibility, passes), in the judge's order.
EXPECTED = [
    ("R.1 passes, visible", 2, "visible", True),
    ("R.2 fails, hidden", 3, "hidden", False),
    ("R.3 records two leaderboard entries, after the due date", 1, "after_due_date", True),
    ("R.4 a name with a comma, a backslash \\ and a star * [in brackets], after publishing", 5, "after_published",
     True),
]
LEADERBOARD = {"rays per second": {"name": "rays per second", "value": 1.5e6, "order": "desc"},
               "error (lower is better)": {"name": "error (lower is better)", "value": 0.25, "order": "asc"}}


def run_judge(judge: str, names, verdict_file: Path):
    env = {k: v for k, v in os.environ.items() if not k.startswith("PATHLAB_")}
    env[verdict_format.VERDICT_FILE] = str(verdict_file)
    selection = ",".join(verdict_format.test_case_filter(name) for name in names)
    run = subprocess.run([judge, f"--test-case={selection}", "--no-version", "--no-intro"], env=env,
                         capture_output=True, text=True, timeout=60)
    return run.returncode, verdict_format.Verdicts.read(verdict_file)


def main() -> int:
    judge = sys.argv[1]
    problems = []
    listing = subprocess.run([judge, "--list-test-cases"], capture_output=True, text=True, timeout=60).stdout
    listed = verdict_format.parse_listing(listing)
    if listed != [(name, points, visibility) for name, points, visibility, _ in EXPECTED]:
        problems.append(f"the listing reads back as {listed}")
    for name, points, visibility, passes in EXPECTED:
        if visibility not in verdict_format.VISIBILITIES:
            problems.append(f"{name}: visibility {visibility} is not one of {verdict_format.VISIBILITIES}")
        if results_format.shown(visibility) != (visibility == verdict_format.VISIBLE):
            problems.append(f"{name}: the platforms would {'not ' * results_format.shown(visibility)}show it")
    with tempfile.TemporaryDirectory() as scratch:
        for index, (name, points, _, passes) in enumerate(EXPECTED):
            code, judged = run_judge(judge, [name], Path(scratch) / f"alone-{index}")
            if judged.ran != [(passes, points, name)] or not judged.finished or judged.passed_alone() != passes:
                problems.append(f"{name}, alone: read back as {judged.ran}, finished {judged.finished}")
            if (code == 0) != passes:
                problems.append(f"{name}, alone: the judge exited {code}")
            expected_board = LEADERBOARD if name.startswith("R.3 ") else {}
            if judged.leaderboard != expected_board:
                problems.append(f"{name}, alone: the leaderboard reads back as {judged.leaderboard}")
        code, judged = run_judge(judge, [name for name, *_ in EXPECTED], Path(scratch) / "all")
        if judged.ran != [(passes, points, name) for name, points, _, passes in EXPECTED] or not judged.finished:
            problems.append(f"all at once: read back as {judged.ran}, finished {judged.finished}")
    # The reader follows the JSON's words, not words of its own: with another listing word it finds nothing.
    verdict_format.SPEC["listing"] = "CASE"
    if verdict_format.parse_listing(listing):
        problems.append("the listing is read with a word verdicts.json does not give")
    for problem in problems:
        print("FAIL:", problem)
    print(f"verdict round trip: {len(EXPECTED)} test cases listed and judged alone and together, "
          f"{len(LEADERBOARD)} leaderboard entries: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
