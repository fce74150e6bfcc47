"""The task list, as every tool reads it: the folders tasks/NN-name/ (CMake
reads the same folders, cmake/PathLabTasks.cmake). Task NN's student file is
tasks/NN-name/name.cpp with the name's dashes as underscores; its API header
framework/tasks/name.h; its reference solutions/NN-name/name.cpp;
its suite tests/NN-name/. A student release lists the tasks its course
hands out in tasks/handed-out.txt (tools/make-student-release --tasks); the
others link the reference and have no suite there.

What the tools show of a task is its own too: its handout's first line is
its title, and tasks/NN-name/task.json (manifest()) holds the rest."""
import json
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


# tasks/NN-name/task.json: what the tools show of the task, kept with it.
#   label       the GUI's name for its panel (at most 14 characters)
#   summary     the task in a few words, lower case ("camera rays"): its row in README.md's task table
#   contents    what the task's folders hold, the row's last cell ("student file, reference, ...")
#   writeup     the figures of its write-up section (tools/writeup), in order:
#               {"kind": "render", "args": pathlab's arguments, "caption": ...} or
#               {"kind": "view", "args": `pathlab debug --task N`'s further arguments, "caption": ...}
#   screenshot  its panel in docs/images/gui-panel-<N>.png (tools/make-gui-screenshots):
#               {"scene": a scene file or "" (the built-in one), "script": pathlab-gui --script lines}
#   ci          the seconds it adds to each of CI's stages ({"test": 45, "asan": 10, ...}): its share of
#               CI's time budget (.ci/run adds every task's to a stage's base; docs/ci.md)
#   grade       what grading it takes: {"seconds": 12, "memory_mb": 144}, the reference's grade at half a
#               CPU and its peak memory (tools/gradescope/container-check --cases each-task); the grading
#               platforms' adapters set their timeouts from it (docs/ta-guide.md)
MANIFEST_KEYS = {"label": str, "summary": str, "contents": str, "writeup": list, "screenshot": dict, "ci": dict,
                 "grade": dict}
LABEL_MAX = 14


def manifest(number: int, root: Path = ROOT) -> dict:
    """Task `number`'s task.json, checked: every key known and of its type, every figure well formed."""
    folder = tasks(root)[number][0]
    path = root / "tasks" / folder / "task.json"
    where = f"tasks/{folder}/task.json"
    try:
        data = json.loads(path.read_text())
    except FileNotFoundError:
        raise SystemExit(f"pathlab_tasks: {where} is missing (every task folder has one: "
                         "docs/architecture.md, 'The task list')")
    except json.JSONDecodeError as e:
        raise SystemExit(f"pathlab_tasks: {where}: not JSON ({e})")
    if not isinstance(data, dict):
        raise SystemExit(f"pathlab_tasks: {where}: expected an object")
    for key, value in data.items():
        if key not in MANIFEST_KEYS:
            raise SystemExit(f"pathlab_tasks: {where}: unknown key '{key}' (known: {', '.join(MANIFEST_KEYS)})")
        if not isinstance(value, MANIFEST_KEYS[key]):
            raise SystemExit(f"pathlab_tasks: {where}: '{key}' should be a {MANIFEST_KEYS[key].__name__}")
    for key in MANIFEST_KEYS:
        if key not in data:
            raise SystemExit(f"pathlab_tasks: {where}: no '{key}'")
    if not 0 < len(data["label"]) <= LABEL_MAX or '"' in data["label"] or "\\" in data["label"]:
        raise SystemExit(f"pathlab_tasks: {where}: 'label' should be 1 to {LABEL_MAX} characters, no quotes")
    for key in ("summary", "contents"):  # cells of a Markdown table, on one line
        if not data[key].strip() or "|" in data[key] or "\n" in data[key]:
            raise SystemExit(f"pathlab_tasks: {where}: '{key}' should be one line of text, without '|'")
    for i, figure in enumerate(data["writeup"]):
        if not (isinstance(figure, dict) and set(figure) == {"kind", "args", "caption"} and
                figure["kind"] in ("render", "view") and all(isinstance(figure[k], str) for k in figure)):
            raise SystemExit(f"pathlab_tasks: {where}: writeup[{i}] should be "
                             '{"kind": "render" or "view", "args": "...", "caption": "..."}')
    if not all(re.fullmatch(r"[a-z0-9-]+", stage) and type(seconds) is int and 0 <= seconds <= 3600
               for stage, seconds in data["ci"].items()):
        raise SystemExit(f"pathlab_tasks: {where}: ci should be {{\"stage\": seconds, ...}}, whole seconds 0 to 3600")
    if not (set(data["grade"]) == {"seconds", "memory_mb"} and
            all(type(v) is int and 0 < v <= 100_000 for v in data["grade"].values())):
        raise SystemExit(f"pathlab_tasks: {where}: grade should be {{\"seconds\": N, \"memory_mb\": M}}, whole numbers")
    shot = data["screenshot"]
    if not (set(shot) == {"scene", "script"} and isinstance(shot["scene"], str) and isinstance(shot["script"], list)
            and all(isinstance(line, str) and "\n" not in line for line in shot["script"])):
        raise SystemExit(f"pathlab_tasks: {where}: screenshot should be "
                         '{"scene": "file or empty", "script": ["line", ...]}')
    return data


def title(number: int, root: Path = ROOT) -> str:
    """The handout's title: "Camera rays" from "# Task 1 — Camera rays"."""
    folder = tasks(root)[number][0]
    first = (root / "tasks" / folder / "README.md").read_text().split("\n", 1)[0]
    match = re.fullmatch(rf"# Task {number} — (.+)", first.strip())
    if not match:
        raise SystemExit(f"pathlab_tasks: tasks/{folder}/README.md should start \"# Task {number} — Title\"")
    return match.group(1)


def handout_points(number: int, root: Path = ROOT) -> int:
    """The points of task `number`'s suite as its handout states them ("## Tests (N points)", which
    tools/handout-tables keeps equal to the suite): what a grade that could not run is out of."""
    folder = tasks(root)[number][0]
    match = re.search(r"^## Tests \((\d+) points\)", (root / "tasks" / folder / "README.md").read_text(), re.M)
    if not match:
        raise SystemExit(f"pathlab_tasks: tasks/{folder}/README.md has no heading '## Tests (N points)'")
    return int(match.group(1))


def ci_allowance(stage: str, root: Path = ROOT) -> int:
    """The seconds every task's task.json adds to CI's stage `stage` (.ci/run; docs/ci.md)."""
    return sum(manifest(n, root)["ci"].get(stage, 0) for n in tasks(root))


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
    unknown = [n for n in chosen if n not in known]
    if unknown:
        raise SystemExit(f"{what} '{text}': there is no task {unknown[0]} in tasks/ (the tasks are {min(known)} to "
                         f"{max(known)}; a course's own task is made with tools/new-task)")
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


# README.md's task table: a row per task, from its task.json ("summary",
# "contents"), in task order. `pathlab_tasks.py readme-table` writes it; CTest task-manifests
# fails when it is not the task folders'. (A student release rewrites the
# last cell of the tasks its course withholds: tools/make-student-release.)
README_TABLE_HEADER = "| task | folder (its README.md is the handout) | status |"


def readme_task_table(root: Path = ROOT) -> str:
    rows = [README_TABLE_HEADER, "| --- | --- | --- |"]
    for n, (folder, _) in tasks(root).items():
        data = manifest(n, root)
        rows.append(f"| {n} {data['summary']} | [`tasks/{folder}/`](tasks/{folder}/README.md) | {data['contents']} |")
    return "\n".join(rows) + "\n"


def readme_with_task_table(text: str, root: Path = ROOT) -> str:
    """README.md's text with its task table (the header line and the table's lines under it) written anew."""
    start = text.find("\n" + README_TABLE_HEADER + "\n")
    if start < 0:
        raise SystemExit(f"pathlab_tasks: README.md has no task table (a line '{README_TABLE_HEADER}')")
    start += 1
    end = start
    while end < len(text) and text.startswith("|", end):
        end = text.index("\n", end) + 1
    return text[:start] + readme_task_table(root) + text[end:]


USAGE = ("usage: pathlab_tasks.py core | handed-out | manifest N KEY | check LIST | sample STAGE COUNT VARIABLE [--numbers | --others]"
         " | draw STAGE COUNT < LINES | readme-table | ci-allowance STAGE")

if __name__ == "__main__":  # for shell scripts
    import sys
    if sys.argv[1:] == ["core"]:
        print(core_tasks())
    elif sys.argv[1:] == ["handed-out"]:
        print(",".join(map(str, handed_out())))
    elif len(sys.argv) == 4 and sys.argv[1] == "manifest" and sys.argv[2].isdigit():
        if sys.argv[3] not in MANIFEST_KEYS:
            raise SystemExit(USAGE)
        value = manifest(int(sys.argv[2]))[sys.argv[3]]
        print(value if isinstance(value, str) else json.dumps(value))
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
    elif len(sys.argv) == 3 and sys.argv[1] == "ci-allowance":  # for .ci/run: the tasks' seconds in a stage
        print(ci_allowance(sys.argv[2]))
    elif sys.argv[1:] == ["readme-table"]:  # README.md's task table written anew from the task folders
        readme = ROOT / "README.md"
        readme.write_text(readme_with_task_table(readme.read_text()))
    else:
        raise SystemExit(USAGE)
