"""Makes an Autolab assessment that grades PathLab tasks (docs/ta-autolab.md):

  tools/autolab/make-autograder OUT_DIR --tasks 1,2,3 [--per task|test] [--name NAME]
                                [--timeout SECONDS] [--image IMAGE] [--build-dir DIR]

writes OUT_DIR/NAME/ and OUT_DIR/NAME.tar (the same folder, for Autolab's
"Install assessment > Import from tarball"):

  NAME.yml            the assessment: its problems (one per task, "Task 3",
                      or one per test case, as the grader names them, a
                      task's hidden tests one: "Task 3: hidden tests") with
                      their points from the judges, the handin file, the
                      autograder's image, timeout and scoreboard
  autograde-Makefile  what Tango runs (as Makefile) in each job: unpacks
                      autograde.tar and calls the image's pathlab-autolab-grade
  autograde.tar       pathlab-autolab.json: the tasks, the problems, the
                      timeout, the handin's name, the scoreboard's columns

The handin is the task's file (camera_rays.cpp) for one task, a .zip of the
task files for several. The scoreboard ranks by the total, and by the BVH's
cost per ray (the grader's leaderboard, lower is better) where task 3 is
graded. The image is tools/autolab/Dockerfile's, built from the same tree.
The judges' test lists come from BUILD_DIR (default: build-grade, made with
the "grade" preset if missing)."""
import argparse
import io
import json
import subprocess
import tarfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
from grader.driver import results as results_format
from tools import pathlab_tasks
from grader.driver.grading import judge_manifest

BVH_BOARD = "BVH cost per ray: nodes + 10 x triangle tests (scan-like mesh)"  # the grader's leaderboard entry
# A job's timeout: two minutes to start, compile and link, and twice each task's grade as measured
# at half a CPU (its task.json's "grade"). (Autolab's own default is 180 s.)
BASE_SECONDS = 120


def yaml_string(text: str) -> str:
    return json.dumps(text)  # a JSON string is a YAML string


def assessment_yml(name, tasks, problems, handin, timeout, image, colspec) -> str:
    titles = ", ".join(f"{n} {pathlab_tasks.title(n)}" for n in tasks)
    lines = ["---", "general:", f"  name: {name}", f"  display_name: {yaml_string('PathLab: ' + titles)}",
             "  description: ''", "  category_name: PathLab", f"  handin_filename: {yaml_string(handin)}",
             "  handin_directory: handin", "  max_grace_days: 0", "  max_submissions: -1",
             "  disable_handins: false", "  max_size: 2", "  has_svn: false", "problems:"]
    for problem, points in problems:
        lines += [f"- name: {yaml_string(problem)}", "  description: ''", f"  max_score: {float(points)}",
                  "  optional: false"]
    lines += ["autograder:", f"  autograde_timeout: {timeout}", f"  autograde_image: {yaml_string(image)}",
              "  release_score: true", "scoreboard:", "  banner: ''", f"  colspec: {yaml_string(json.dumps(colspec))}"]
    return "\n".join(lines) + "\n"


MAKEFILE = """# PathLab on Autolab (docs/ta-autolab.md). Tango copies the handin, this
# file (as Makefile) and autograde.tar into the job folder and runs `make`
# there as its grading user. The grader, built into the image, runs as root
# through pathlab-autolab-grade (setuid), so that the student's code runs as
# a uid of its own; it prints the feedback, then the scores as the last line.
# (The variables are for grader/tests/test_platforms.py, which runs jobs as
# Tango does beside other graders: Tango's environment sets none of them.)
PATHLAB_AUTOLAB_GRADE ?= /usr/local/bin/pathlab-autolab-grade
PATHLAB_SANDBOX ?= auto
PATHLAB_SANDBOX_UID ?=

all:
\t@tar xf autograde.tar
\t@$(PATHLAB_AUTOLAB_GRADE) --sandbox $(PATHLAB_SANDBOX) $(if $(PATHLAB_SANDBOX_UID),--sandbox-uid $(PATHLAB_SANDBOX_UID))

clean:
\trm -f pathlab-autolab.json
"""


def judges(build: Path, tasks) -> dict:
    """{task: [(test name, points, visibility)]} from the judges' own listings, built where missing."""
    if not (build / "CMakeCache.txt").exists():
        subprocess.run(["cmake", "--preset", "grade", "-B", str(build)], cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    folders = pathlab_tasks.tasks()
    targets = [f"test-{folders[n][0]}" for n in tasks]
    subprocess.run(["cmake", "--build", str(build), "--target", *targets], check=True, stdout=subprocess.DEVNULL)
    return {n: judge_manifest(build, n) for n in tasks}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out")
    parser.add_argument("--tasks", required=True, help="the tasks this assessment grades, e.g. 1,2,3")
    parser.add_argument("--per", choices=["task", "test"], default="task", help="one problem per task or per test")
    parser.add_argument("--name", help="the assessment's name (default: pathlab-tasks-1-2-3)")
    parser.add_argument("--timeout", type=int, help=f"Autolab's autograder timeout in seconds (default: {BASE_SECONDS} + "
                        "twice each task's measured grade)")
    parser.add_argument("--image", default="pathlab-autolab", help="the Docker image Tango grades in")
    parser.add_argument("--build-dir", default=str(ROOT / "build-grade"))
    args = parser.parse_args()
    every = pathlab_tasks.tasks()
    tasks = pathlab_tasks.parse_task_list(args.tasks, every)
    name = args.name or "pathlab-tasks-" + "-".join(map(str, tasks))
    if not name.replace("-", "").replace("_", "").isalnum():
        raise SystemExit(f"make-autograder: --name '{name}': letters, digits, '-' and '_' only")
    timeout = args.timeout or BASE_SECONDS + sum(2 * pathlab_tasks.manifest(n)["grade"]["seconds"] for n in tasks)
    if not 60 <= timeout <= 3600:
        raise SystemExit("make-autograder: --timeout must be 60 to 3600 seconds")
    handin = every[tasks[0]][1] if len(tasks) == 1 else "handin.zip"
    problems = results_format.autolab_problems(judges(Path(args.build_dir).resolve(), tasks), args.per)
    columns = ["total"] + ([BVH_BOARD] if 3 in tasks else [])
    colspec = {"scoreboard": [{"hdr": "Total"}] + ([{"hdr": "BVH cost per ray", "asc": 1}] if 3 in tasks else [])}
    settings = {"tasks": tasks, "per": args.per, "problems": problems, "timeout": timeout, "handin": handin,
                "scoreboard": columns}

    folder = Path(args.out).resolve() / name
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"{name}.yml").write_text(assessment_yml(name, tasks, problems, handin, timeout, args.image, colspec))
    (folder / "autograde-Makefile").write_text(MAKEFILE)
    data = json.dumps(settings, indent=1).encode()
    with tarfile.open(folder / "autograde.tar", "w") as tar:
        info = tarfile.TarInfo("pathlab-autolab.json")
        info.size, info.mode, info.mtime = len(data), 0o644, int(time.time())
        tar.addfile(info, io.BytesIO(data))
    with tarfile.open(folder.parent / f"{name}.tar", "w") as tar:
        tar.add(folder, arcname=name)
    print(f"make-autograder: wrote {folder}/ and {folder.parent / (name + '.tar')}: {len(problems)} problems "
          f"({sum(p for _, p in problems):g} points), handin {handin}, timeout {timeout} s, image {args.image}")
    return 0
