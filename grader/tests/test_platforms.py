#!/usr/bin/env python3
"""Autolab and PrairieLearn grade PathLab as each runs it, here, with the
same points as tools/grade (docs/ta-autolab.md, docs/ta-prairielearn.md).
Each job is run by tools/release/platforms.py, as tools/try-platform runs a
TA's handin; this test checks what the jobs give.

No Docker engine runs here, so the images are made as their Dockerfiles make
them, in a scratch folder standing in for the image's root (IMAGE): the
working tree packaged in IMAGE/opt/pathlab, then tools/autolab/image-setup
(tools/install-grader's build, pathlab-autolab-grade installed setuid root
in IMAGE/usr/local/bin; PATHLAB_SKIP_APT=1: the packages must be here).

Two tasks other than 3 are drawn per commit (PATHLAB_PLATFORM_TASKS=A,B
names them). Autolab: tools/autolab/make-autograder makes an assessment of
task 3 (for the scoreboard) and A with a problem per task, and one of B with
a problem per test. Each job runs as Tango runs it: the handin (named as the
assessment's yml says), the autograde-Makefile as Makefile and autograde.tar
in a job folder owned by an unprivileged uid, `make` run as that uid with
Tango's limits (100 processes, 100 MB per file), no network, killed at the
assessment's timeout, and its output cut to Tango's 1,000 KB as autodriver
cuts it. Handins: the stubs (0 on every problem), the reference (every
problem's maximum), a half-done one (the reference for task 3, a mutant of
A: each problem equal to tools/grade's points for that task on the same
handin, the scoreboard its total and BVH cost), a missing handin (0
everywhere), and, per test, B's reference and a mutant (each problem
tools/grade's test). The last line must be Autolab's autoresult with
exactly the yml's problems, none over its maximum, and the scoreboard's
columns.

PrairieLearn: tools/prairielearn/make-course makes B's question; each job
runs as PrairieLearn runs it: /grade (here a scratch folder, PL_GRADE_ROOT)
with student/, tests/ (the question's), serverFilesCourse/, data/data.json
and results/, the question's entrypoint run as root with no network, killed
at its timeout. Submissions (every test named and worth what B's judge
lists): the stub (score 0, its failure pictures inlined as PNG data URLs,
each test tools/grade's; and its results kept within 20 KB, pictures and
outputs cut, with the same points, as they are within PrairieLearn's 1 MB),
the reference (score 1, every test its maximum), a mutant (each test's
points tools/grade's on the same file), a file that is no task file
("gradable": false, costing no attempt); results.json always under 1 MB
and valid against the format the test carries (RESULTS_SCHEMA).

usage: test_platforms.py REPO_ROOT WORK_DIR [--keep]   (its scratch is a new folder in TMPDIR,
outside the repository: the jobs' unprivileged uid must reach it while other grading tests make the
repository private; WORK_DIR is unused)"""
import base64
import functools
import json
import os
import runpy
import shutil
import sys
import tempfile
import time
from pathlib import Path

root = Path(sys.argv[1]).resolve()
keep = "--keep" in sys.argv[3:]
# Outside the repository: the jobs run as an unprivileged uid, which must reach the image's files, and the
# other grading tests make the repository private (mode 0700) while they grade.
work = Path(tempfile.mkdtemp(prefix="pathlab-platforms-"))
work.chmod(0o755)
sys.path.insert(0, str(root))  # the repository: the import root (docs/architecture.md)
from tools.release import platforms as platforms  # noqa: E402  (each platform's run, as tools/try-platform runs it)
from grader.driver import results as results_format
from tools import pathlab_tasks
from grader.driver.grading import judge_manifest
from tests.support.scratch import finish  # noqa: E402

TASKS = pathlab_tasks.tasks(root)
GRADING_UID = platforms.TANGO_UID  # PATHLAB_PLATFORMS_UID
failures = []
image = None  # the image's root (platforms.Image), made by main


def fail(message):
    failures.append(message)


def task_files(kinds: dict) -> list:
    """{task: "reference" | "stub" | path of a mutant} -> the files handed in."""
    files = []
    for n, kind in kinds.items():
        folder, name = TASKS[n]
        source = {"reference": root / "solutions" / folder / name, "stub": root / "tasks" / folder / name}.get(kind)
        files.append((name, Path(source or kind)))
    return files


def direct_grade(files, tasks, name) -> dict:
    """tools/grade on the same files, as root, the image's build, the sandbox the platform has (uid)."""
    folder = work / "direct" / name
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    for file, source in files:
        shutil.copy(source, folder / file)
    out = work / "direct" / f"{name}.json"
    graded = platforms.run([sys.executable, image.tree / "tools/grade", folder, "--tasks", ",".join(map(str, tasks)),
                            "--out", out, "--build-dir", image.tree / "build-grade", "--sandbox", "uid"],
                           f"tools/grade {name}")
    if not out.exists():
        raise SystemExit(f"FAIL: tools/grade wrote nothing for {name}:\n{graded.stderr[-2000:]}")
    return results_format.load(out)


# ---------------------------------------------------------------- Autolab

def assessment(out: Path, tasks, per: str) -> platforms.Assessment:
    made = platforms.autolab_assessment(image, out, tasks, per)
    yml = made.yml
    if not (yml["general"]["name"] == made.name and isinstance(made.timeout, int) and
            yml["autograder"]["autograde_image"] == "pathlab-autolab" and all(
                set(p) == {"name", "description", "max_score", "optional"} for p in yml["problems"])):
        fail(f"autolab: {made.name}.yml is not an assessment Autolab imports: {yml}")
    return made


def tango_job(made: platforms.Assessment, files, kind):
    """One job as Tango runs it; (the autoresult, the feedback)."""
    job = platforms.autolab_job(image, made, files, work / "autolab" / f"job-{kind}", GRADING_UID)
    if job.timed_out:
        fail(f"autolab {kind}: the job passed the assessment's timeout of {made.timeout} s")
        return None, ""
    if "WARNING" in job.feedback:  # e.g. the assessment's problems are not the image's judges' tests
        fail(f"autolab {kind}: the job warned:\n{job.feedback[:1000]}")
    print(f"  autolab {kind}: {job.seconds:.0f} s, {len(job.feedback.encode())} bytes of feedback "
          f"({job.feedback_file})", flush=True)
    if job.autoresult is None:
        last = job.feedback.rstrip("\n").rsplit("\n", 1)[-1]
        fail(f"autolab {kind}: the last line is not the autoresult: {last[:300]!r}\n{job.feedback[-1500:]}")
    return job.autoresult, job.feedback


def autoresult_problems(result, problems, columns, kind) -> bool:
    """Autolab's autoresult: exactly the assessment's problems, each a number within its maximum, and
    one number per scoreboard column."""
    scores = result.get("scores") if isinstance(result, dict) else None
    if not isinstance(scores, dict) or set(scores) != {name for name, _ in problems}:
        fail(f"autolab {kind}: scores {sorted(scores or {})[:4]} are not the assessment's problems")
        return False
    for name, maximum in problems:
        if not isinstance(scores[name], (int, float)) or not 0 <= scores[name] <= maximum:
            fail(f"autolab {kind}: {name} scored {scores[name]!r} of {maximum}")
            return False
    board = result.get("scoreboard")
    if not (isinstance(board, list) and len(board) == len(columns) and all(isinstance(v, (int, float)) for v in board)):
        fail(f"autolab {kind}: scoreboard {board!r} does not have the columns {columns}")
        return False
    return True


@functools.cache
def generated_variants():
    """Every mutant and alternate, made as the build makes them (tests/mutants/generate.py): nothing
    generated is in git."""
    return runpy.run_path(str(root / "tests/mutants/generate.py"))["variants"](root)


def generated_mutant(n, last=False):
    """Task n's first (or last) mutant by name, written into the scratch folder."""
    made = generated_variants()
    rel = sorted(r for r in made if r.startswith(f"mutants/{TASKS[n][0]}/"))[-1 if last else 0]
    path = work / "variants" / rel
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(made[rel])
    return path


def check_autolab(pair, single):
    out = work / "autolab"
    made = assessment(out, pair, "task")
    problems, columns = made.problems, made.columns
    if made.handin != "handin.zip" or [p for p, _ in problems] != [f"Task {n}" for n in pair]:
        fail(f"autolab: handin {made.handin}, problems {problems}: not a zip and one problem per task")
    maxima = dict(problems)
    mutant_task = next(n for n in pair if n != 3)
    mutant = generated_mutant(mutant_task)
    cases = {"stubs": {n: "stub" for n in pair}, "reference": {n: "reference" for n in pair},
             "half-done": {3: "reference", mutant_task: mutant}}
    for kind, kinds in cases.items():
        result, feedback = tango_job(made, task_files(kinds), kind)
        if result is None or not autoresult_problems(result, problems, columns, kind):
            continue
        scores = result["scores"]
        if kind == "stubs" and any(scores.values()):
            fail(f"autolab stubs: {scores}, not 0 everywhere")
        if kind == "reference" and scores != maxima:
            fail(f"autolab reference: {scores}, not every maximum {maxima}")
        if kind == "half-done":
            graded = direct_grade(task_files(kinds), pair, "autolab-half-done")
            want = {f"Task {n}": e for n, (e, _) in results_format.per_task(graded, pair).items()}
            board = {e["name"]: e["value"] for e in graded.get("leaderboard", [])}
            if scores != want:
                fail(f"autolab half-done: {scores}, tools/grade {want}")
            if result["scoreboard"][0] != sum(want.values()) or len(result["scoreboard"]) != 2 or \
                    abs(result["scoreboard"][1] - next(iter(board.values()), -1)) > 1e-9:
                fail(f"autolab half-done: scoreboard {result['scoreboard']}, tools/grade's total "
                     f"{sum(want.values())} and BVH cost {board}")
            print(f"  autolab half-done: {scores} = tools/grade's; scoreboard {result['scoreboard']}")
        for n in pair:
            if f"Task {n}: {scores[f'Task {n}']:g} of {maxima[f'Task {n}']:g} points" not in feedback:
                fail(f"autolab {kind}: the feedback does not say task {n}'s points:\n{feedback[:1500]}")
    result, feedback = tango_job(made, None, "missing-handin")
    if result is not None and autoresult_problems(result, problems, columns, "missing-handin") and \
            (any(result["scores"].values()) or "handin.zip" not in feedback):
        fail(f"autolab missing handin: {result}, not 0 everywhere with the reason:\n{feedback[-800:]}")

    # A problem per test, one task's file as the handin.
    made = assessment(out / "per-test", [single], "test")
    problems, columns = made.problems, made.columns
    if made.handin != TASKS[single][1] or len(problems) < 2 or \
            not all(p.startswith(f"Task {single}: ") for p, _ in problems):
        fail(f"autolab per test: handin {made.handin}, problems {problems[:2]}")
    mutant = generated_mutant(single, last=True)
    for kind, kinds in (("per-test-reference", {single: "reference"}), ("per-test-mutant", {single: mutant})):
        result, _ = tango_job(made, task_files(kinds), kind)
        if result is None or not autoresult_problems(result, problems, columns, kind):
            continue
        want = dict(problems) if kind.endswith("reference") else \
            {t["name"]: t["score"] for t in direct_grade(task_files(kinds), [single], kind)["tests"]}
        if result["scores"] != want:
            differ = [p for p in want if result["scores"].get(p) != want[p]]
            fail(f"autolab {kind}: {len(differ)} problems differ from tools/grade's tests, e.g. {differ[:2]}")
        else:
            print(f"  autolab {kind}: {len(want)} problems, each tools/grade's test's points")


# ---------------------------------------------------------------- PrairieLearn

# PrairieLearn's results.json (docs.prairielearn.com, "External grading"): key -> (types, required).
RESULTS_SCHEMA = {"gradable": (bool, False), "score": ((int, float), True), "message": (str, False),
                  "output": (str, False), "format_errors": ((str, list), False), "images": (list, False),
                  "tests": (list, False)}
TEST_SCHEMA = {"name": (str, True), "description": (str, False), "points": ((int, float), False),
               "max_points": ((int, float), False), "message": (str, False), "output": (str, False),
               "images": (list, False)}


def schema_problems(report: dict) -> list:
    problems = []
    for schema, item, where in [(RESULTS_SCHEMA, report, "results")] + \
            [(TEST_SCHEMA, t, f"test {t.get('name')!r}") for t in report.get("tests", []) if isinstance(t, dict)]:
        for key, value in item.items():
            if key not in schema:
                problems.append(f"{where}: unknown key {key!r}")
            elif not isinstance(value, schema[key][0]) or isinstance(value, bool) != (schema[key][0] is bool):
                problems.append(f"{where}: {key} is {type(value).__name__}")
        problems += [f"{where}: no {key}" for key, (_, required) in schema.items() if required and key not in item]
        for image in item.get("images", []):
            url = image.get("url", "") if isinstance(image, dict) else ""
            if not (url.startswith("data:image/png;base64,") and
                    base64.b64decode(url.split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"):
                problems.append(f"{where}: an image that is not a PNG data URL")
    if not 0 <= report.get("score", -1) <= 1:
        problems.append(f"score {report.get('score')} is not in [0, 1]")
    return problems


def pl_job(question: Path, files, kind):
    job = platforms.prairielearn_job(image, question, files, work / "prairielearn" / f"grade-{kind}")
    if job.timed_out:
        fail(f"prairielearn {kind}: the job passed the question's timeout")
        return None
    print(f"  prairielearn {kind}: {job.seconds:.0f} s, results.json {job.size} bytes", flush=True)
    if job.results is None:
        fail(f"prairielearn {kind}: results.json missing, not JSON or over 1 MB ({job.size} bytes)")
        return None
    problems = schema_problems(job.results)
    for p in problems[:5]:
        fail(f"prairielearn {kind}: {p}")
    return None if problems else job.results


def check_prairielearn(tasks):
    questions = platforms.prairielearn_course(image, work / "prairielearn", tasks)
    for n in tasks:
        question = questions[n]
        info = json.loads((question / "info.json").read_text())
        options = info.get("externalGradingOptions", {})
        if not (info.get("gradingMethod") == "External" and options.get("enabled") and
                options.get("entrypoint") == "/opt/pathlab/tools/prairielearn/run" and
                0 < options.get("timeout", 0) <= 600 and options.get("enableNetworking") is False and
                f'file-names="{TASKS[n][1]}"' in (question / "question.html").read_text()):
            fail(f"prairielearn task {n}: info.json or question.html is not an external-graded upload of "
                 f"{TASKS[n][1]}: {options}")
        mutant = generated_mutant(n)
        for kind, files in (("stub", task_files({n: "stub"})), ("reference", task_files({n: "reference"})),
                            ("mutant", task_files({n: mutant})),
                            ("not-a-task-file", [("notes.txt", root / "README.md")])):
            report = pl_job(question, files, f"task{n}-{kind}")
            if report is None:
                continue
            if kind == "not-a-task-file":
                if report.get("gradable") is not False or TASKS[n][1] not in report.get("message", ""):
                    fail(f"prairielearn task {n}: a submission with no task file is not 'gradable: false' with "
                         f"the file named: {report.get('gradable')}, {report.get('message')!r}")
                continue
            points = {t["name"]: (t["points"], t["max_points"]) for t in report["tests"]}
            total = sum(p for p, _ in points.values()) / max(1, sum(m for _, m in points.values()))
            if report.get("gradable") is not True or abs(report["score"] - total) > 1e-9:
                fail(f"prairielearn task {n} {kind}: gradable {report.get('gradable')}, score {report['score']} "
                     f"(its tests: {total})")
            if kind == "stub" and (report["score"] != 0 or not any(t.get("images") for t in report["tests"])):
                fail(f"prairielearn task {n} stub: score {report['score']}, or no failure picture inlined")
            if kind == "reference" and report["score"] != 1:
                fail(f"prairielearn task {n} reference: score {report['score']}")
            listed = {f"Task {n}: {name}": points for name, points, _ in judge_manifest(image.tree / "build-grade", n)}
            if {name: m for name, (_, m) in points.items()} != listed:
                fail(f"prairielearn task {n} {kind}: its tests are not the judge's, or not worth what it lists")
            if kind in ("stub", "mutant"):  # the stub's results are cut below; a mutant's points are partial
                graded = direct_grade(files, [n], f"prairielearn-task{n}-{kind}")
                want = {t["name"]: (t["score"], t["max_score"]) for t in graded["tests"]}
            else:
                want = {name: (m, m) for name, m in listed.items()}
            if points != want:
                fail(f"prairielearn task {n} {kind}: tests differ from tools/grade's: "
                     f"{[k for k in want if points.get(k) != want[k]][:3]}")
            else:
                print(f"  prairielearn task {n} {kind}: score {report['score']:.3f}, {len(want)} tests, each "
                      "tools/grade's points")
            if kind == "stub":  # PrairieLearn's 1 MB rule, on 20 KB (the stub's are about 70): within it, same points
                limit = 20_000
                small = results_format.prairielearn(graded, work / "direct", limit=limit)
                kept = {t["name"]: (t["points"], t["max_points"]) for t in small["tests"]}
                if len(json.dumps(small).encode()) > limit or kept != want or "left out" not in small["output"]:
                    fail(f"prairielearn task {n}: results cut to {limit} bytes came to "
                         f"{len(json.dumps(small).encode())}, or lost points, or did not say what was left out")


def main() -> int:
    start = time.time()
    global image
    print(f"scratch: {work}")
    try:
        image = platforms.make_image(root, work / "image")
    except platforms.PlatformError as error:
        raise SystemExit(f"FAIL: {error}")
    others = [n for n in TASKS if n != 3]
    if os.environ.get("PATHLAB_PLATFORM_TASKS"):
        drawn = pathlab_tasks.parse_task_list(os.environ["PATHLAB_PLATFORM_TASKS"], others, "PATHLAB_PLATFORM_TASKS")
    else:
        drawn = pathlab_tasks.commit_random("platforms", root).sample(others, 2)
    if len(drawn) != 2:
        raise SystemExit("PATHLAB_PLATFORM_TASKS: name two tasks other than 3")
    print(f"tasks: Autolab {sorted([3, drawn[0]])} (a problem per task) and {drawn[1]} (per test); "
          f"PrairieLearn {drawn[1]}")
    check_autolab(sorted([3, drawn[0]]), drawn[1])
    check_prairielearn([drawn[1]])
    return finish("platforms", failures, work, keep, start,
                  "Autolab and PrairieLearn gave tools/grade's points, in their own formats")


if __name__ == "__main__":
    sys.exit(main())
