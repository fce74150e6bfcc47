"""Makes a new task's folders from tools/task-template/, so that it builds,
grades and shows in every tool at once (docs/own-task.md):

  tools/new-task NN NAME [--title TITLE] [--label LABEL] [--summary SUMMARY] [--from EXAMPLE]

NN is the next task number (the folders are numbered from 01 without gaps)
and NAME the folder's name after it, lower case with dashes (13 light-bvh:
the folder 13-light-bvh, the student's file light_bvh.cpp). It writes, with
NN-name the new folder and name.h its header:

  tasks/NN-name/          the handout, the student's file (one TODO and its
                          maths), the debugger view, the lab warp, task.json
  framework/tasks/name.h  the task's API (the name with underscores)
  solutions/NN-name/      the reference
  tests/NN-name/          the suite (one graded test), its calls, the
                          candidate's answers, the lab's cases, one mutant
                          and one alternate (validity.py)
  writeup/NN-name.md      the write-up's question
  tests/NN-name/hints.md  (tools/hint-catalogue)

and README.md's task table (made from every task.json); the build makes
the mutants and alternates from validity.py. The template
(tools/task-template) is a small worked example, a uniform point on a
triangle: one function, one graded test. --from cone-light starts from a
richer one (tools/task-examples/cone-light): a sphere light sampled by the
cone it subtends, three functions (one answering a struct), four graded
tests with a chi-square, six mutants and three alternates. Replace either
with the course's assignment, keeping the files' shapes. Nothing else in
the repository changes."""
import argparse
import re
import shutil
import subprocess
import tempfile
import sys
from pathlib import Path

from tools import pathlab_tasks

ROOT = pathlab_tasks.ROOT
# Where a task starts from: its folder, and the name of its lab warp after the task's name.
STARTS = {"template": (ROOT / "tools" / "task-template", "triangle"),
          "cone-light": (ROOT / "tools" / "task-examples" / "cone-light", "cone")}
CPP_KEYWORDS = {"and", "auto", "bool", "break", "case", "catch", "char", "class", "const", "default", "delete",
                "do", "double", "else", "enum", "export", "extern", "false", "float", "for", "friend", "goto", "if",
                "inline", "int", "long", "namespace", "new", "not", "operator", "or", "private", "protected",
                "public", "register", "return", "short", "signed", "sizeof", "static", "struct", "switch",
                "template", "this", "throw", "true", "try", "typedef", "typename", "union", "unsigned", "using",
                "virtual", "void", "volatile", "while", "xor", "pathlab", "std", "test", "lab", "calls",
                "candidate", "remote"}


def fail(message: str):
    raise SystemExit(f"new-task: {message}")


def write_task(template: Path, values: dict, places: dict, stem: str, folder: str, readme: Path) -> list:
    """The template's files with the task's values, its generated mutants and hints, README.md's table."""
    written = []
    for source in sorted(template.rglob("*")):
        if not source.is_file():
            continue
        part, name = source.relative_to(template).parts[0], source.name
        name = name.replace("STEM", stem).replace("FOLDER", folder)
        text = source.read_text()
        for key, value in values.items():
            text = text.replace(key, value)
        if re.search(r"@[A-Z]+@", text):
            fail(f"{source.relative_to(ROOT)}: a placeholder this script does not know")
        target = places[part] / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text)
        written.append(target.relative_to(ROOT))
    # Its mutants and alternates are made by the build (tests/mutants/generate.py); made here once in a scratch
    # folder, so that an edit that does not apply to the reference fails now, with nothing written.
    with tempfile.TemporaryDirectory() as scratch:
        subprocess.run([sys.executable, str(ROOT / "tests/mutants/generate.py"), scratch], check=True, cwd=ROOT,
                       stdout=subprocess.DEVNULL)
    subprocess.run([sys.executable, str(ROOT / "tools/hint-catalogue")], check=True, cwd=ROOT,
                   stdout=subprocess.DEVNULL)  # its hints' catalogue
    readme.write_text(pathlab_tasks.readme_with_task_table(readme.read_text(), ROOT))
    return written


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("number", help="the next task number, e.g. 13")
    parser.add_argument("name", help="the folder's name after the number, e.g. textures or light-bvh")
    parser.add_argument("--title", help="the handout's title (default: NAME in words)")
    parser.add_argument("--label", help=f"the GUI's button, at most {pathlab_tasks.LABEL_MAX} characters")
    parser.add_argument("--summary", help="the task in a few words, lower case, for README.md's task table")
    parser.add_argument("--from", dest="start", choices=sorted(STARTS), default="template",
                        help="the worked example to start from (default: the template, a point on a triangle)")
    args = parser.parse_args()

    existing = pathlab_tasks.tasks(ROOT)
    if not args.number.isdigit() or int(args.number) != len(existing) + 1:
        fail(f"the next task is {len(existing) + 1} (the tasks are numbered from 01 without gaps), not {args.number}")
    n = int(args.number)
    if not re.fullmatch(r"[a-z][a-z0-9]*(-[a-z0-9]+)*", args.name):
        fail(f"'{args.name}': a name is lower-case letters and digits, words joined by dashes (light-bvh)")
    folder, stem = f"{n:02d}-{args.name}", args.name.replace("-", "_")
    if stem in CPP_KEYWORDS:
        fail(f"'{args.name}' names the task's namespace (pathlab::{stem}), which C++ or the project already uses")
    words = args.name.replace("-", " ")
    title = args.title or words[0].upper() + words[1:]
    label = args.label or title[:pathlab_tasks.LABEL_MAX].rstrip()
    summary = args.summary or words
    labels = {pathlab_tasks.manifest(k, ROOT)["label"]: k for k in existing}
    if label in labels:
        fail(f"task {labels[label]} has the label '{label}' already: choose another with --label")
    if len(label) > pathlab_tasks.LABEL_MAX:
        fail(f"--label '{label}': {len(label)} characters, at most {pathlab_tasks.LABEL_MAX} (the GUI's button)")
    for text, what in ((title, "--title"), (label, "--label"), (summary, "--summary")):
        if any(c in text for c in '"\\|\n'):
            fail(f"{what} '{text}': no quotes, backslashes, '|' or line breaks")
    header = ROOT / "framework" / "tasks" / f"{stem}.h"
    targets = [ROOT / "tasks" / folder, ROOT / "solutions" / folder, ROOT / "tests" / folder,
               ROOT / "writeup" / f"{folder}.md", header]
    for target in targets:
        if target.exists():
            fail(f"{target.relative_to(ROOT)} exists already")

    values = {"@N@": str(n), "@FOLDER@": folder, "@STEM@": stem, "@TITLE@": title, "@LABEL@": label,
              "@SUMMARY@": summary, "@WARP@": f"{args.name}-{STARTS[args.start][1]}",
              "@NAME@": "".join(word[0].upper() + word[1:] for word in args.name.split("-"))}
    places = {"tasks": ROOT / "tasks" / folder, "solutions": ROOT / "solutions" / folder,
              "tests": ROOT / "tests" / folder, "framework": ROOT / "framework" / "tasks", "writeup": ROOT / "writeup"}
    readme = ROOT / "README.md"
    readme_before = readme.read_text()
    try:
        written = write_task(STARTS[args.start][0], values, places, stem, folder, readme)
    except BaseException as error:
        # Nothing half made: a failure leaves the tree as it was, so the same command can run again.
        for target in targets:
            if target.is_dir():
                shutil.rmtree(target)
            elif target.exists():
                target.unlink()
        readme.write_text(readme_before)
        if isinstance(error, subprocess.CalledProcessError):
            fail(f"{' '.join(map(str, error.cmd[1:]))} failed (exit {error.returncode}); nothing was written")
        raise
    for path in written:
        print(f"new-task: wrote {path}")
    print(f"new-task: wrote tests/{folder}/hints.md and README.md's task table (the build makes the mutants and "
          f"alternates of tests/{folder}/validity.py)\n"
          f"Next: build (cmake --build --preset release), then ctest --test-dir build -R {folder}: the stub fails, "
          f"and tools/grade solutions --tasks {n} --out results.json gives full marks. docs/own-task.md says what "
          "to replace and how to test it.")
