"""Makes PrairieLearn questions that grade PathLab tasks, one per task, in
the layout of a PrairieLearn course (docs/ta-prairielearn.md):

  tools/prairielearn/make-course OUT_DIR --tasks 1,2,3 [--image IMAGE] [--timeout SECONDS]

writes, for each task, OUT_DIR/questions/pathlab/NN-name/:

  info.json     an externally graded question: the image (tools/prairielearn/
                Dockerfile's, pushed where PrairieLearn pulls it), the
                entrypoint /opt/pathlab/tools/prairielearn/run, the timeout,
                no network
  question.html the upload of the task's one file, and the grader's results
  tests/        pathlab-question.json: the task and the timeout, for the entrypoint

A TA copies OUT_DIR/questions/pathlab/ into the course's questions/ and adds
the questions to an assessment. The timeout is PrairieLearn's (30 s by
default, at most 600): by default 60 s plus twice the task's grade as
measured at half a CPU (its task.json's "grade")."""
import argparse
import json
import uuid
from pathlib import Path

from tools import pathlab_tasks

ENTRYPOINT = "/opt/pathlab/tools/prairielearn/run"
PRAIRIELEARN_MAX_TIMEOUT = 600

QUESTION_HTML = """<pl-question-panel>
  <p>Task {n}, {title}: hand in your <code>{file}</code>, the file
  tasks/{folder}/{file} of your PathLab tree. It is graded with the course's
  reference for every other task, by the same tests your own ctest and
  tools/check run.</p>
</pl-question-panel>

<pl-file-upload file-names="{file}"></pl-file-upload>

<pl-submission-panel>
  <pl-external-grader-results></pl-external-grader-results>
  <pl-file-preview></pl-file-preview>
</pl-submission-panel>
"""


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out")
    parser.add_argument("--tasks", required=True, help="one question per task, e.g. 1,2,3")
    parser.add_argument("--image", default="pathlab/grader-prairielearn",
                        help="the image PrairieLearn pulls (built from tools/prairielearn/Dockerfile)")
    parser.add_argument("--timeout", type=int, help="PrairieLearn's timeout in seconds (default: 60 + twice the "
                        "task's measured grade)")
    args = parser.parse_args()
    every = pathlab_tasks.tasks()
    tasks = pathlab_tasks.parse_task_list(args.tasks, every)
    if args.timeout is not None and not 10 <= args.timeout <= PRAIRIELEARN_MAX_TIMEOUT:
        raise SystemExit(f"make-course: --timeout must be 10 to {PRAIRIELEARN_MAX_TIMEOUT} seconds (PrairieLearn's most)")
    for n in tasks:
        folder, file = every[n]
        title = pathlab_tasks.title(n)
        # The task's grade as measured at half a CPU (its task.json), twice, and a minute to start and link.
        timeout = args.timeout or min(PRAIRIELEARN_MAX_TIMEOUT, 60 + 2 * pathlab_tasks.manifest(n)["grade"]["seconds"])
        question = Path(args.out).resolve() / "questions" / "pathlab" / folder
        (question / "tests").mkdir(parents=True, exist_ok=True)
        info = {
            "uuid": str(uuid.uuid5(uuid.NAMESPACE_URL, f"pathlab:question:{folder}")),
            "title": f"PathLab task {n}: {title}",
            "topic": "PathLab",
            "tags": ["pathlab", f"task{n}"],
            "type": "v3",
            "singleVariant": True,
            "gradingMethod": "External",
            "externalGradingOptions": {"enabled": True, "image": args.image, "entrypoint": ENTRYPOINT,
                                       "timeout": timeout, "enableNetworking": False},
        }
        (question / "info.json").write_text(json.dumps(info, indent=2) + "\n")
        (question / "question.html").write_text(QUESTION_HTML.format(n=n, title=title, file=file, folder=folder))
        (question / "tests" / "pathlab-question.json").write_text(json.dumps({"task": n, "timeout": timeout}) + "\n")
        print(f"make-course: wrote questions/pathlab/{folder}/ (task {n}, {file}, timeout {timeout} s)")
    return 0
