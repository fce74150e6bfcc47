"""The points of a GitHub Classroom push (docs/ta-classroom.md): reads the
results.json tools/check wrote and prints, per task, its points and each
visible test's (a task's hidden tests as one line, "Task N: hidden tests",
no output: grader/driver/results.py), then "Total points: X/Y". With
--notify it also hands X/Y to the classroom as GitHub's grading reporter
does: on the workflow run's check run "Autograding Tests", the output
"Points X/Y" and its annotation. Every number is tools/check's, so what the
student reads in the log is what the classroom records. (GitHub's own
reporter shows the share of tests passed as points: 84.21/100 for a task-9
handin the classroom recorded as 27/31.)

  tools/classroom/report RESULTS.json --tasks 1,2,3 [--notify]

Without a readable RESULTS.json (the check could not run), every task is
reported with 0 points out of its handout's, and posted so: the classroom
records a 0, not nothing. Exit 0 when every point was earned and posted, 1
otherwise (the run shows a failure, as with GitHub's reporter).

--notify reads GITHUB_TOKEN, GITHUB_REPOSITORY, GITHUB_RUN_ID, GITHUB_JOB
and GITHUB_API_URL (https://api.github.com when unset), as GitHub Actions
sets them."""
import argparse
import json
import os
import sys
import urllib.error
import urllib.parse
import urllib.request
from pathlib import Path

from grader.driver import results as results_format
from tools import pathlab_tasks

CHECK_NAME = "Autograding Tests"  # where GitHub Classroom reads the points (its reporter's check run)


def could_not_run(tasks, why: str) -> dict:
    """The report of a check that wrote no results: 0 of each task's handout points."""
    report = {"tasks": [], "score": 0, "max_score": 0, "passed": False}
    for n in tasks:
        most = pathlab_tasks.handout_points(n)
        report["tasks"].append({"task": n, "score": 0, "max_score": most, "tests": [
            {"name": f"Task {n}: tools/check", "score": 0, "max_score": most, "passed": False, "output": why}]})
        report["max_score"] += most
    return report


def printed(report: dict) -> str:
    lines = []
    for task in report["tasks"]:
        n = task["task"]
        lines.append(f"Task {n} ({pathlab_tasks.title(n)}): {task['score']:g}/{task['max_score']:g} points")
        for test in task["tests"]:
            mark = "ok  " if test["passed"] else "FAIL"
            lines.append(f"  {mark} {test['score']:g}/{test['max_score']:g}  {test['name']}")
            if test["output"]:
                lines.extend("         " + line for line in test["output"].strip().splitlines()[-12:])
    lines.append(f"Total points: {report['score']:g}/{report['max_score']:g}")
    return "\n".join(lines) + "\n"


def github(method: str, url: str, token: str, body=None) -> dict:
    request = urllib.request.Request(url, method=method, data=None if body is None else json.dumps(body).encode(),
                                     headers={"Authorization": f"Bearer {token}",
                                              "Accept": "application/vnd.github+json",
                                              "X-GitHub-Api-Version": "2022-11-28",
                                              "Content-Type": "application/json"})
    with urllib.request.urlopen(request, timeout=30) as response:
        return json.loads(response.read(1 << 20) or b"{}")


def notify(score: float, most: float) -> str:
    """Posts "Points score/most" on this run's check run, as GitHub's grading reporter does; returns
    the check run's name, or raises RuntimeError saying why it could not."""
    env = os.environ
    token, repository, run_id = env.get("GITHUB_TOKEN", ""), env.get("GITHUB_REPOSITORY", ""), env.get("GITHUB_RUN_ID", "")
    if not (token and "/" in repository and run_id.isdigit()):
        raise RuntimeError("GITHUB_TOKEN, GITHUB_REPOSITORY and GITHUB_RUN_ID must be set (the workflow's step sets "
                           "GITHUB_TOKEN: ${{ github.token }})")
    api = env.get("GITHUB_API_URL", "https://api.github.com").rstrip("/") + "/repos/" + repository
    run = github("GET", f"{api}/actions/runs/{run_id}", token)
    suite = str(run.get("check_suite_id") or str(run.get("check_suite_url", "")).rsplit("/", 1)[-1])
    if not suite.isdigit():
        raise RuntimeError(f"workflow run {run_id} names no check suite")
    runs = github("GET", f"{api}/check-suites/{suite}/check-runs?per_page=100", token).get("check_runs", [])
    # The reporter's check run by name; else this job's (named by its id); else the suite's only one.
    named = [r for r in runs if r.get("name") == CHECK_NAME] or \
        [r for r in runs if r.get("name") == env.get("GITHUB_JOB")] or (runs if len(runs) == 1 else [])
    if len(named) != 1:
        raise RuntimeError(f"no single check run '{CHECK_NAME}' in check suite {suite} "
                           f"(found: {[r.get('name') for r in runs]})")
    text = f"Points {score:g}/{most:g}"
    github("PATCH", f"{api}/check-runs/{named[0]['id']}", token, {"output": {
        "title": "Autograding", "summary": text, "text": text,
        "annotations": [{"path": ".github", "start_line": 1, "end_line": 1, "annotation_level": "notice",
                         "message": text, "title": "Autograding complete"}]}})
    return named[0].get("name", "")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results")
    parser.add_argument("--tasks", required=True)
    parser.add_argument("--notify", action="store_true", help="post the points to the run's check run")
    args = parser.parse_args()
    tasks = pathlab_tasks.parse_task_list(args.tasks, pathlab_tasks.tasks())
    try:
        report = results_format.classroom(results_format.load(Path(args.results)), tasks)
    except (OSError, ValueError) as e:
        print(f"report: the check wrote no results ({e}): 0 points", file=sys.stderr)
        report = could_not_run(tasks, f"tools/check wrote no results: {str(e)[:400]}")
    sys.stdout.write(printed(report))
    posted = True
    if args.notify:
        try:
            name = notify(report["score"], report["max_score"])
            print(f"Posted Points {report['score']:g}/{report['max_score']:g} on check run '{name}'")
        except (RuntimeError, OSError, ValueError, urllib.error.URLError) as e:
            print(f"report: could not post the points to the classroom: {e}", file=sys.stderr)
            posted = False
    return 0 if report["passed"] and posted else 1
