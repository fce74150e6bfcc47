"""The grader's results in each grading platform's own format.

tools/grade is the one thing that decides points: it writes results.json in
Gradescope's schema (a test per test case: name "Task N: ...", score,
max_score, output), which is Gradescope's adapter. The other platforms'
adapters (tools/autolab, tools/prairielearn, tools/classroom) reshape that
file here and decide nothing: every point is copied from a grader's test,
and each converter is checked against the results it came from (the tests
under tests/grader/ compare them test by test)."""
import base64
import json
import re
from pathlib import Path

RESULTS_BYTES = 16 << 20  # the largest results.json read back: tools/grade clips every output (pathlab_grading)


def load(path: Path) -> dict:
    """A grader's results.json, read with a bound and its shape checked."""
    with open(path, "rb") as f:
        data = f.read(RESULTS_BYTES + 1)
    if len(data) > RESULTS_BYTES:
        raise ValueError(f"{path}: over {RESULTS_BYTES} bytes: not a grader's results")
    results = json.loads(data)
    tests = results.get("tests") if isinstance(results, dict) else None
    if not isinstance(tests, list) or not all(
            isinstance(t, dict) and isinstance(t.get("name"), str) and task_of(t) and
            isinstance(t.get("score"), (int, float)) and isinstance(t.get("max_score"), (int, float)) for t in tests):
        raise ValueError(f"{path}: not a grader's results (tests with name 'Task N: ...', score, max_score)")
    return results


def task_of(test: dict) -> int:
    """3 for "Task 3: T3.1 ..." (0 when the name has no task)."""
    match = re.match(r"Task (\d+): ", test["name"])
    return int(match.group(1)) if match else 0


def per_task(results: dict, tasks) -> dict:
    """{task: (points earned, points possible)} for each of `tasks`, 0 of 0 where it has no test."""
    totals = {n: [0, 0] for n in tasks}
    for test in results["tests"]:
        if task_of(test) in totals:
            totals[task_of(test)][0] += test["score"]
            totals[task_of(test)][1] += test["max_score"]
    return {n: (earned, possible) for n, (earned, possible) in totals.items()}


def graded(results: dict) -> bool:
    """False when the grader found no task file or failed itself: every test is its 0-point 'submission' entry."""
    return any(t["max_score"] > 0 for t in results["tests"])


def pictures(test: dict, folder: Path):
    """The failure pictures a test's output names ("pictures: DIR/a.png, DIR/b.png (...)"), as found on disk."""
    found = []
    for line in test.get("output", "").splitlines():
        if line.startswith("pictures: "):
            for name in re.findall(r"([\w./-]+\.png)", line):
                path = folder / name
                if path.is_file() and path.resolve().is_relative_to(folder.resolve()):
                    found.append(path)
    return found


# ---------------------------------------------------------------- Autolab

def autolab_problems(manifests: dict, per: str) -> list:
    """[(problem name, max score)] of an assessment, from the judges' manifests {task: judge_manifest(...)}
    ((test name, points, visibility) each): one problem per task ("Task 3"), or per test (the grader's test
    name), as the TA chooses."""
    if per == "task":
        return [(f"Task {n}", sum(case[1] for case in cases)) for n, cases in sorted(manifests.items())]
    return [(f"Task {n}: {name}", points) for n, cases in sorted(manifests.items()) for name, points, *_ in cases]


def autolab(results: dict, problems: list, per: str, board_columns: list) -> dict:
    """Autolab's autoresult: {"scores": {problem: points}, "scoreboard": [...]}, the last line of the output.
    Every problem of the assessment gets a score (0 where the grader has no test of that name); the
    scoreboard's columns are board_columns: "total", or the name of a grader leaderboard entry (its
    value; 0 where the grader gave none, e.g. task 3 not done)."""
    if per == "task":
        earned = {f"Task {n}": e for n, (e, _) in per_task(results, [int(p.split()[1]) for p, _ in problems]).items()}
    else:
        earned = {t["name"]: t["score"] for t in results["tests"]}
    scores = {name: earned.get(name, 0) for name, _ in problems}
    board = {e["name"]: e["value"] for e in results.get("leaderboard", [])}
    scoreboard = [sum(scores.values()) if column == "total" else board.get(column, 0) for column in board_columns]
    return {"scores": scores, "scoreboard": scoreboard}


# ---------------------------------------------------------------- PrairieLearn

PRAIRIELEARN_BYTES = 1 << 20  # PrairieLearn's limit on results.json


def prairielearn(results: dict, pictures_folder: Path, limit: int = PRAIRIELEARN_BYTES) -> dict:
    """PrairieLearn's results.json: score in [0, 1], a test per grader test (points, max_points, message,
    output), and the failure pictures inlined as data URLs while the file stays under `limit` bytes
    (outputs are clipped first if even the text would not fit). gradable is false when the grader found
    no task file or failed itself: PrairieLearn then does not count the attempt."""
    possible = sum(t["max_score"] for t in results["tests"])
    earned = sum(t["score"] for t in results["tests"])
    tests = []
    for t in results["tests"]:
        hints = [line for line in t.get("output", "").splitlines() if line.startswith("HINT")]
        tests.append({"name": t["name"], "points": t["score"], "max_points": t["max_score"],
                      "message": "passed" if t["score"] >= t["max_score"] else "\n".join(hints) or "failed",
                      "output": t.get("output", "")})
    report = {"gradable": graded(results), "score": earned / possible if possible else 0.0,
              "message": results.get("output", "").splitlines()[0] if results.get("output") else "",
              "output": results.get("output", ""), "tests": tests}
    size = lambda: len(json.dumps(report).encode())
    room = 200  # for the line that says what was left out
    # Text first: the longest output halved (its start kept) until the text fits.
    while size() > limit - room:
        longest = max(report["tests"], key=lambda test: len(test["output"]))
        if len(longest["output"]) < 200:
            raise ValueError("PrairieLearn's results would not fit even with every output clipped")
        longest["output"] = longest["output"][:len(longest["output"]) // 2] + "\n[... clipped to fit PrairieLearn's 1 MB]"
    # Then pictures, test by test, each while it fits.
    left_out = 0
    for test, source in zip(report["tests"], results["tests"]):
        for path in pictures(source, pictures_folder):
            images = test.setdefault("images", [])
            images.append({"label": path.name,
                           "url": "data:image/png;base64," + base64.b64encode(path.read_bytes()).decode()})
            if size() > limit - room:
                images.pop()
                left_out += 1
            if not images:
                del test["images"]
    if left_out:
        report["output"] += f"\n({left_out} failure pictures left out: PrairieLearn's results are limited to 1 MB)"
    return report


# ---------------------------------------------------------------- GitHub Classroom

def classroom(results: dict, tasks) -> dict:
    """{"taskN": base64 JSON} for GitHub Classroom's grading reporter (classroom-resources/
    autograding-grading-reporter): one runner per task, its max_score the task's points and a test per
    grader test with its score; the reporter adds the runners' scores up and reports them to the classroom."""
    out = {}
    for n in tasks:
        mine = [t for t in results["tests"] if task_of(t) == n]
        payload = {"version": 1, "max_score": sum(t["max_score"] for t in mine),
                   "status": "pass" if all(t["score"] >= t["max_score"] for t in mine) else "fail",
                   "tests": [{"name": t["name"], "status": "pass" if t["score"] >= t["max_score"] else "fail",
                              "score": t["score"], "message": "" if t["score"] >= t["max_score"] else
                              t.get("output", "")[-2000:]} for t in mine]}
        out[f"task{n}"] = base64.b64encode(json.dumps(payload).encode()).decode()
    return out
