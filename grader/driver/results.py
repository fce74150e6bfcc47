"""The grader's results in each grading platform's own format.

tools/grade is the one thing that decides points: it writes results.json in
Gradescope's schema (a test per test case: name "Task N: ...", score,
max_score, output), which is Gradescope's adapter. The other platforms'
adapters (tools/autolab, tools/prairielearn, tools/classroom) reshape that
file here and decide nothing: every point is copied from a grader's test,
and each converter is checked against the results it came from (the tests
under grader/tests/ compare them test by test). A test whose visibility is
not "visible" is never shown there (shown()), but its points still count."""
import base64
import json
import re
from pathlib import Path

RESULTS_BYTES = 16 << 20  # the largest results.json read back: tools/grade clips every output (grading.py)


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


HIDDEN = "hidden tests"  # what a task's hidden tests are shown as, together: "Task 3: hidden tests"


def shown(visibility) -> bool:
    """Whether Autolab, PrairieLearn and GitHub Classroom show a test to students, by its visibility (results.json's
    field, or a judge_manifest case's third item). Only "visible", or none (the grader's default), is: these
    platforms cannot release one test later as Gradescope does, so "after_due_date" and "after_published" stay
    hidden there like "hidden" (and so does anything unknown). A hidden test's points still count, unnamed."""
    return visibility in (None, "visible")


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
    name), as the TA chooses. Per test, a task's hidden tests are one problem, "Task 3: hidden tests", worth
    their sum: students see the problems' names."""
    if per == "task":
        return [(f"Task {n}", sum(case[1] for case in cases)) for n, cases in sorted(manifests.items())]
    problems = []
    for n, cases in sorted(manifests.items()):
        problems += [(f"Task {n}: {name}", points) for name, points, visibility in cases if shown(visibility)]
        hidden = [points for _, points, visibility in cases if not shown(visibility)]
        if hidden:
            problems.append((f"Task {n}: {HIDDEN}", sum(hidden)))
    return problems


def autolab(results: dict, problems: list, per: str, board_columns: list) -> dict:
    """Autolab's autoresult: {"scores": {problem: points}, "scoreboard": [...]}, the last line of the output.
    Every problem of the assessment gets a score (0 where the grader has no test of that name); the
    scoreboard's columns are board_columns: "total", or the name of a grader leaderboard entry (its
    value; 0 where the grader gave none, e.g. task 3 not done)."""
    if per == "task":
        earned = {f"Task {n}": e for n, (e, _) in per_task(results, [int(p.split()[1]) for p, _ in problems]).items()}
    else:  # a hidden test scores in its task's "hidden tests" problem (autolab_problems)
        earned = {}
        for t in results["tests"]:
            name = t["name"] if shown(t.get("visibility")) else f"Task {task_of(t)}: {HIDDEN}"
            earned[name] = earned.get(name, 0) + t["score"]
    scores = {name: earned.get(name, 0) for name, _ in problems}
    board = {e["name"]: e["value"] for e in results.get("leaderboard", [])}
    scoreboard = [sum(scores.values()) if column == "total" else board.get(column, 0) for column in board_columns]
    return {"scores": scores, "scoreboard": scoreboard}


# ---------------------------------------------------------------- PrairieLearn

PRAIRIELEARN_BYTES = 1 << 20  # PrairieLearn's limit on results.json


def prairielearn(results: dict, pictures_folder: Path, limit: int = PRAIRIELEARN_BYTES) -> dict:
    """PrairieLearn's results.json: score in [0, 1], a test per visible grader test (points, max_points,
    message, output), and the failure pictures inlined as data URLs while the file stays under `limit` bytes
    (outputs are clipped first if even the text would not fit). The hidden tests (shown()) count in the score
    and are one last test, "hidden tests", with their points summed and nothing else of theirs. gradable is
    false when the grader found no task file or failed itself: PrairieLearn then does not count the attempt."""
    possible = sum(t["max_score"] for t in results["tests"])
    earned = sum(t["score"] for t in results["tests"])
    visible = [t for t in results["tests"] if shown(t.get("visibility"))]
    hidden = [t for t in results["tests"] if not shown(t.get("visibility"))]
    tests = []
    for t in visible:
        hints = [line for line in t.get("output", "").splitlines() if line.startswith("HINT")]
        tests.append({"name": t["name"], "points": t["score"], "max_points": t["max_score"],
                      "message": "passed" if t["score"] >= t["max_score"] else "\n".join(hints) or "failed",
                      "output": t.get("output", "")})
    if hidden:  # so that the tests still add up to the score
        tests.append({"name": HIDDEN, "points": sum(t["score"] for t in hidden),
                      "max_points": sum(t["max_score"] for t in hidden), "output": "",
                      "message": f"Tests not shown: {len(hidden)}. Their points count in the score."})
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
    for test, source in zip(report["tests"], visible):  # a hidden test's pictures never: "hidden tests" is last
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
    """What GitHub Classroom records and shows (tools/classroom/report): per task its points and most, and
    a line per visible test with its points; a task's hidden tests (shown()) are one line, "Task N: hidden
    tests", their points summed, no output. {"tasks": [{"task", "score", "max_score", "tests": [{"name",
    "score", "max_score", "passed", "output"}]}], "score", "max_score", "passed"}."""
    passed = lambda t: t["score"] >= t["max_score"]
    report = {"tasks": [], "score": 0, "max_score": 0, "passed": True}
    for n in tasks:
        mine = [t for t in results["tests"] if task_of(t) == n]
        hidden = [t for t in mine if not shown(t.get("visibility"))]
        lines = [{"name": t["name"], "score": t["score"], "max_score": t["max_score"], "passed": passed(t),
                  "output": "" if passed(t) else t.get("output", "")[-2000:]}
                 for t in mine if shown(t.get("visibility"))]
        if hidden:
            lines.append({"name": f"Task {n}: {HIDDEN}", "score": sum(t["score"] for t in hidden),
                          "max_score": sum(t["max_score"] for t in hidden), "passed": all(map(passed, hidden)),
                          "output": ""})
        task = {"task": n, "score": sum(t["score"] for t in mine), "max_score": sum(t["max_score"] for t in mine),
                "tests": lines}
        report["tasks"].append(task)
        report["score"] += task["score"]
        report["max_score"] += task["max_score"]
        report["passed"] = report["passed"] and all(map(passed, mine))
    return report
