"""GitHub Classroom's autograding workflow for a course's PathLab tasks
(docs/ta-classroom.md), printed (make-student-release --classroom installs it
as .github/workflows/classroom.yml):

  tools/classroom/make-workflow --tasks 1,2,3

On every push it installs the packages, grades the student's task files
with tools/check (the course's grader: the same suites, points and limits,
the compiled reference for the other tasks; its table goes to the run's
summary page) and hands the points to the classroom (tools/classroom/report
--notify: the log shows each task's and test's points and the total, and the
same total is posted where GitHub's grading reporter posts it). The workflow
and job names are those of GitHub Classroom's own template."""
import argparse
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
from tools import pathlab_tasks

WORKFLOW = """# GitHub Classroom's autograding for PathLab, tasks {listing} (docs/ta-classroom.md),
# written by tools/classroom/make-workflow: the course's grader (tools/check)
# decides the points; tools/classroom/report hands them to the classroom.
name: Autograding Tests
on: [push, repository_dispatch, workflow_dispatch]
permissions:
  checks: write
  actions: read
  contents: read
jobs:
  run-autograding-tests:
    runs-on: ubuntu-latest
    if: github.actor != 'github-classroom[bot]'
    steps:
      - uses: actions/checkout@v4
      - name: Install
        run: sudo apt-get update && sudo apt-get install -y {packages}
      - name: Grade with the course's grader (the table is on the run's summary page)
        run: python3 tools/check --tasks {tasks} --out pathlab-results.json --summary "$GITHUB_STEP_SUMMARY"
      - name: Points to the classroom
        if: always()
        env:
          GITHUB_TOKEN: ${{{{ github.token }}}}
        run: python3 tools/classroom/report pathlab-results.json --tasks {tasks} --notify
"""


def workflow(tasks) -> str:
    core = subprocess.run(["bash", "-c", 'source tools/packages.sh; echo "${pathlab_core[@]}"'], cwd=ROOT,
                          capture_output=True, text=True, check=True).stdout.split()
    return WORKFLOW.format(listing=", ".join(map(str, tasks)), packages=" ".join(core),
                           tasks=",".join(map(str, tasks)))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tasks", required=True)
    args = parser.parse_args()
    sys.stdout.write(workflow(pathlab_tasks.parse_task_list(args.tasks, pathlab_tasks.tasks())))
    return 0
