"""The task list, as every tool reads it: the folders tasks/NN-name/ (CMake
reads the same folders, cmake/PathLabTasks.cmake). Task NN's student file is
tasks/NN-name/name.cpp with the name's dashes as underscores; its API header
framework/tasks/name.h; its reference solutions/NN-name/name.cpp;
its suite tests/NN-name/. A student release lists the tasks its course
hands out in tasks/handed-out.txt (tools/make-student-release --tasks); the
others link the reference and have no suite there."""
import os
import random
import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def tasks(root: Path = ROOT) -> dict:
    """{number: (folder, file name)}, e.g. {1: ("01-camera-rays", "camera_rays.cpp"), ...}."""
    found = {}
    for folder in sorted((root / "tasks").iterdir()):
        match = re.fullmatch(r"(\d\d)-([a-z0-9-]+)", folder.name)
        if match and folder.is_dir():
            found[int(match.group(1))] = (folder.name, match.group(2).replace("-", "_") + ".cpp")
    if sorted(found) != list(range(1, len(found) + 1)):
        raise SystemExit(f"pathlab_tasks: tasks/ folders are not numbered 01 to {len(found):02d}: {sorted(found)}")
    return found


# The seven core tasks (camera rays to environment lighting): what a course
# grades unless it names its tasks (tools/grade, Gradescope's make-zip.sh).
# The extension tasks, 8 onwards, are each handed out or not.
CORE_TASK_COUNT = 7


def core_tasks() -> str:
    """The core tasks as --tasks takes them: "1,2,3,4,5,6,7"."""
    return ",".join(str(n) for n in range(1, CORE_TASK_COUNT + 1))


# A student release's course list (written by tools/make-student-release --tasks,
# read by CMake too: cmake/PathLabTasks.cmake). Absent in the course repository:
# there every task is handed out.
HANDED_OUT_FILE = "tasks/handed-out.txt"


def parse_task_list(text: str, known, what: str = "--tasks") -> list:
    """"1,2,8" -> [1, 2, 8]: sorted, each a known task number, at least one."""
    try:
        chosen = sorted({int(t) for t in text.split(",") if t.strip()})
    except ValueError:
        raise SystemExit(f"{what} '{text}': expected task numbers like 1,2,3")
    if not chosen:
        raise SystemExit(f"{what} '{text}': lists no task")
    if not set(chosen) <= set(known):
        raise SystemExit(f"{what} '{text}': the tasks are {min(known)} to {max(known)}")
    return chosen


def handed_out(root: Path = ROOT) -> list:
    """The tasks this tree's course hands out: tasks/handed-out.txt (lines after
    '#' are comments), or every task where there is no such file."""
    every = tasks(root)
    path = root / HANDED_OUT_FILE
    if not path.is_file():
        return sorted(every)
    text = ",".join(line.partition("#")[0] for line in path.read_text().splitlines())
    return parse_task_list(text, every, str(HANDED_OUT_FILE))


def not_handed_out(chosen, root: Path = ROOT):
    """Why `chosen` (task numbers) cannot be checked here: the first that the
    course does not hand out, said in one line; None when all are handed out."""
    withheld = [n for n in chosen if n not in handed_out(root)]
    if not withheld:
        return None
    return f"task {withheld[0]} is not handed out in this course ({HANDED_OUT_FILE}): it has no suite here"


def commit_sample(stage: str, count: int, variable: str, root: Path = ROOT) -> list:
    """The tasks whose suites a CI stage that samples them checks here: the
    environment variable `variable` names them ("1,5"), or `count` are drawn
    by the checked-out commit's hash and the stage's name, so that two stages
    draw differently on one commit and every task comes up within a few
    commits (CI's mutation sample draws likewise)."""
    every = handed_out(root)
    if os.environ.get(variable):
        return parse_task_list(os.environ[variable], every, variable)
    return sorted(commit_random(stage, root).sample(every, min(count, len(every))))


def commit_random(stage: str, root: Path = ROOT) -> random.Random:
    """A generator seeded by the checked-out commit's hash and a stage's name:
    every draw CI makes per commit (commit_sample, the grader's attacks'
    sandboxes, the Gradescope zip's mix) comes from one."""
    head = subprocess.run(["git", "-C", str(root), "rev-parse", "HEAD"], capture_output=True, text=True)
    commit = head.stdout.strip() if head.returncode == 0 else "0"
    return random.Random(f"{stage}:{commit}")


# Added to the compiler line of a task file graded as a submission (tools/grade,
# tools/mutate; tests/CMakeLists.txt's validity candidates likewise): libstdc++'s
# checks turn an empty std::optional dereferenced or an index past a vector's
# end into a stopped test instead of a read of whatever memory holds.
SUBMISSION_FLAGS = ["-D_GLIBCXX_ASSERTIONS"]


USAGE = ("usage: pathlab_tasks.py core | handed-out | check LIST | sample STAGE COUNT VARIABLE [--numbers | --others]"
         " | draw STAGE COUNT < LINES")

if __name__ == "__main__":  # for shell scripts
    import sys
    if sys.argv[1:] == ["core"]:
        print(core_tasks())
    elif sys.argv[1:] == ["handed-out"]:
        print(",".join(map(str, handed_out())))
    elif len(sys.argv) == 3 and sys.argv[1] == "check":
        print(",".join(map(str, parse_task_list(sys.argv[2], tasks()))))
    elif len(sys.argv) in (5, 6) and sys.argv[1] == "sample" and sys.argv[3].isdigit():
        drawn = commit_sample(sys.argv[2], int(sys.argv[3]), sys.argv[4])
        form = sys.argv[5] if len(sys.argv) == 6 else "folders"
        if form == "--numbers":  # "4;5;8;12", a CMake list
            print(";".join(map(str, drawn)))
        elif form in ("folders", "--others"):  # the drawn tasks' folders (or the others'), one per line
            for n, (folder, _) in tasks().items():
                if (n in drawn) == (form == "folders"):
                    print(folder)
        else:
            raise SystemExit(USAGE)
    elif len(sys.argv) == 4 and sys.argv[1] == "draw" and sys.argv[3].isdigit():
        # COUNT of the lines on standard input drawn by the commit (all if fewer), in their order.
        lines = sys.stdin.read().splitlines()
        drawn = set(commit_random(sys.argv[2]).sample(range(len(lines)), min(int(sys.argv[3]), len(lines))))
        print("\n".join(line for i, line in enumerate(lines) if i in drawn))
    else:
        raise SystemExit(USAGE)
