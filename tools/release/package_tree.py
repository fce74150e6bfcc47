"""The course tree every packager packages: the working tree as it is.

One rule for the Gradescope zip, the Autolab and PrairieLearn images, the
student release and GitHub Classroom's repository: the files of the working
tree, tracked and new (.gitignore respected), uncommitted edits included, so
that what a TA sees in the folder is what students and platforms get. A task
made with tools/new-task is packaged before it is committed. Standard error
says how the tree differs from HEAD, so a package of uncommitted work is
never made unknowingly.

  tools/package-tree DIR [--tasks LIST]   copy the tree into DIR (missing or empty)
  tools/package-tree - [--tasks LIST]     write it as a tar to standard output
                                          (tools/package-tree - | docker build -f ... -)
  --tasks LIST   refuse (exit 2), naming the task and the fix, unless each task
                 listed has all its folders in the tree: tasks/NN-name,
                 solutions/NN-name and tests/NN-name
"""
import os
import shutil
import subprocess
import sys
import tarfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
from tools import pathlab_tasks

TASK_FOLDERS = ("tasks", "solutions", "tests")


def tree_files(root: Path) -> list:
    """The working tree's files, tracked and untracked, without what .gitignore ignores."""
    listed = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                            capture_output=True, text=True)
    if listed.returncode != 0:
        raise SystemExit(f"package-tree: {root} is not a git checkout ({listed.stderr.strip()}): the packagers "
                         "package the course repository's working tree")
    # (A tracked file deleted in the tree is not packaged: the tree is what is packaged.)
    return sorted({f for f in listed.stdout.split("\0") if f and ((root / f).is_file() or (root / f).is_symlink())})


def uncommitted(root: Path) -> list:
    """`git status` of the tree, one entry per change ("M README.md", "?? a new task's folder/")."""
    status = subprocess.run(["git", "-C", str(root), "status", "--porcelain"], capture_output=True, text=True)
    return [line.strip() for line in status.stdout.splitlines() if line.strip()]


def missing_task_folders(files: list, chosen: list) -> list:
    """For each task of `chosen` lacking a folder in `files`, one line naming it and the fix."""
    top = {tuple(f.split("/")[:2]) for f in files if f.count("/") >= 2}
    problems = []
    for n in chosen:
        prefix = f"{n:02d}-"
        for kind in TASK_FOLDERS:
            if not any(a == kind and b.startswith(prefix) for a, b in top):
                problems.append(f"task {n}: {kind}/{prefix}* is not in the tree (no such folder, or every file in "
                                f"it ignored by .gitignore: `git check-ignore -v {kind}/{prefix}*` says which rule)")
    return problems


def describe(root: Path, files: list) -> str:
    head = subprocess.run(["git", "-C", str(root), "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    commit = head.stdout.strip() or "no commit yet"
    changes = uncommitted(root)
    if not changes:
        return f"package-tree: the working tree, {len(files)} files, as committed ({commit})"
    shown = ", ".join(changes[:6]) + (f", ... ({len(changes) - 6} more)" if len(changes) > 6 else "")
    return (f"package-tree: the working tree, {len(files)} files, with {len(changes)} uncommitted change"
            f"{'s' if len(changes) > 1 else ''} since {commit}: {shown}")


def write_tar(root: Path, files: list, out) -> None:
    with tarfile.open(fileobj=out, mode="w|") as tar:
        for f in files:
            tar.add(str(root / f), arcname=f, recursive=False)


def copy_files(root: Path, files: list, out: Path) -> None:
    for f in files:
        target = out / f
        target.parent.mkdir(parents=True, exist_ok=True)
        if (root / f).is_symlink():
            os.symlink(os.readlink(root / f), target)
        else:
            shutil.copy2(root / f, target)


def main(argv: list) -> int:
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip().split("\n\n", 2)[2], file=sys.stderr)
        return 2
    dest, rest = argv[0], argv[1:]
    chosen = None
    if rest[:1] == ["--tasks"] and len(rest) == 2:
        try:
            chosen = pathlab_tasks.parse_task_list(rest[1], pathlab_tasks.tasks(ROOT))
        except SystemExit as refused:
            print(f"package-tree: {refused}", file=sys.stderr)
            return 2
    elif rest:
        print(f"package-tree: unexpected {' '.join(rest)} (tools/package-tree --help)", file=sys.stderr)
        return 2
    files = tree_files(ROOT)
    if chosen:
        problems = missing_task_folders(files, chosen)
        if problems:
            print("package-tree: cannot package the tasks asked for:\n  " + "\n  ".join(problems), file=sys.stderr)
            return 2
    print(describe(ROOT, files), file=sys.stderr)
    if dest == "-":
        write_tar(ROOT, files, sys.stdout.buffer)
        return 0
    out = Path(dest)
    if out.exists() and any(out.iterdir()):
        print(f"package-tree: {out} exists and is not empty", file=sys.stderr)
        return 2
    out.mkdir(parents=True, exist_ok=True)
    copy_files(ROOT, files, out)
    return 0
