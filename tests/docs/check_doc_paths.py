#!/usr/bin/env python3
"""Every path the repository's text names exists: the README, the docs, the
handouts, and the comments and strings of the code and scripts. A moved or
renamed file fails this check until every mention follows it.

What counts as a path: a word starting with one of the repository's
top-level folders (framework/core/scene.h, tasks/03-bvh/README.md), and a
framework header named the way an #include names it (core/scene.h is
framework/core/scene.h). Placeholders stand for any name: NN-name (a task
folder), NN, name, NAME, FILE, LAYER, <...>, {...} (one word), a shell
variable ($d) and *; {a,b} is either. A path that is not found from the repository's root is tried
from the folder of the file that names it (CMake's paths are relative).

A generated file counts when its template (the same name + .in) exists. A
file that names a made-up tree (a test's fixture) says so in a comment
line holding "check_doc_paths: not checked", and is skipped.

In a student release (no solutions/) a path inside a folder or file the
release leaves out (solutions/, tests/mutants/, tools/grade, ...), or a
task folder's file that only the withheld tasks may have
(tests/NN-name/reference-variances.txt where no suite handed out has
one), is not checked in code and scripts, but the pages a student reads (STUDENT_PAGES:
the README, the docs, the handouts, the task files and their API
headers) must name only what the release holds; in the course
repository, a file only a release has (RELEASE_ONLY: its course's task
list) counts as there.

usage: check_doc_paths.py REPOSITORY"""
import itertools
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the repository: the import root (docs/architecture.md)
from tools import pathlab_tasks

RELEASE_ONLY = {pathlab_tasks.HANDED_OUT_FILE}  # written by tools/make-student-release
TOP = ("framework", "apps", "tasks", "solutions", "tests", "tools", "media", "docs", "cmake", ".ci")
LAYER_HEADER = re.compile(r"(?<![\w./-])((?:util|core|tasks|scene|render|debug)/\w+\.(?:h|h\.in|cpp))\b")
PATH = re.compile(r"(?<![\w./$-])((?:%s)/(?:\{[^}\s]*\}|\$\w+|[\w.*<>+-]|/)*)" % "|".join(re.escape(t) for t in TOP))
TEXT = {".md", ".h", ".cpp", ".in", ".py", ".sh", ".txt", ".json", ".cmake", ""}
SKIP = ("build", ".git", "__pycache__")
STUDENT_PAGES = ("README.md", "docs/*.md", "tasks/*/README.md", "tasks/*/*.cpp", "framework/tasks/*.h")
PLACEHOLDER = {"NN-name": "[0-9][0-9]-*", "NN": "[0-9][0-9]*", "name": "*", "NAME": "*", "FILE": "*",
               "LAYER": "*", "...": "*"}


def texts(root: Path):
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root)
        if rel.parts[0].startswith(SKIP) or not path.is_file():
            continue
        if rel.parts[:2] in (("tests", "inputs"), ("tests", "fuzz")) and path.suffix != ".cpp":
            continue  # malformed inputs and fuzz seeds: data, not prose
        if path.suffix in TEXT and (path.suffix or path.stat().st_size < 200_000):
            try:
                yield rel, path.read_text()
            except UnicodeDecodeError:
                continue


def patterns(mention: str):
    """The globs a mention stands for ({a,b} expanded, placeholders as wildcards)."""
    mention = mention.rstrip(".,:;")
    parts = re.split(r"(\{[^}]*\})", mention)
    choices = [p[1:-1].split(",") if p.startswith("{") and "," in p else
               ["*"] if p.startswith("{") else [p] for p in parts]
    for combo in itertools.product(*choices):
        path = "".join(combo)
        components = []
        for c in path.split("/"):
            c = re.sub(r"<[^>]*>|\$\w+|\.\.\.", "*", c)
            stem, dot, ext = c.partition(".")
            if stem in PLACEHOLDER:
                c = PLACEHOLDER[stem] + dot + ext
            components.append(PLACEHOLDER.get(c, c))
        yield "/".join(components).rstrip("/") or "."


def exists(base: Path, pattern: str) -> bool:
    if any(ch in pattern for ch in "*?["):
        return any(base.glob(pattern)) or any(base.glob(pattern + ".in"))
    return (base / pattern).exists() or (base / (pattern + ".in")).exists()


def left_out_of_release(root: Path, pattern: str) -> bool:
    """True in a student release when the mention is inside something the release removed,
    or names a file that only some task folders hold (tests/NN-name/reference-variances.txt)
    and the release withheld every suite that has one."""
    if (root / "solutions").exists():
        return False
    parts = pattern.split("/")
    if any(not exists(root, "/".join(parts[:n])) for n in (1, 2) if len(parts) >= n):
        return True
    task = PLACEHOLDER["NN-name"]
    return task in parts and len(pathlab_tasks.handed_out(root)) < len(pathlab_tasks.tasks(root))


def main() -> int:
    root = Path(sys.argv[1]).resolve()
    problems, count = [], 0
    for rel, text in texts(root):
        if re.search(r"^\s*(#|//).*check_doc_paths: not checked", text, re.M):
            continue
        shown = any(rel.match(page) and len(rel.parts) == page.count("/") + 1 for page in STUDENT_PAGES)
        for number, line in enumerate(text.splitlines(), 1):
            if re.match(r"\s*#\s*include", line):
                continue  # the layers test checks includes
            # tasks/bvh.h is a task API as an #include names it: LAYER_HEADER's.
            mentions = [m for m in PATH.findall(line) if not re.fullmatch(r"tasks/\w+\.h", m.rstrip(".,:;"))]
            mentions += ["framework/" + m for m in LAYER_HEADER.findall(line)]
            for mention in mentions:
                globs = list(patterns(mention))
                count += 1
                found = all(exists(root, g) or exists(root / rel.parent, g) or g in RELEASE_ONLY for g in globs)
                if not found and (shown or not any(left_out_of_release(root, g) for g in globs)):
                    problems.append(f"{rel}:{number}: {mention.rstrip('.,:;')} does not exist")
    for p in problems:
        print(p)
    print(f"{count} path mentions: {len(problems)} name nothing")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
