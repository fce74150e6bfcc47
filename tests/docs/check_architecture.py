#!/usr/bin/env python3
"""docs/architecture.md held to the code.

"The folders": the tree names only folders that exist (NN-name: the
numbered task folders), and names every folder of the repository's top
level and of framework/, grader/, apps/, tests/, media/ and docs/. A folder whose
line says "not in the student release", and the folders in it, may be
missing where solutions/ is not; one that says "only in the student
release" may be missing where solutions/ is.

The Python code's imports: the repository is the import root, set only by
a file Python starts, in one line marked "# the repository: the import
root"; no module another file imports edits sys.path, and no file imports
a module of tools/ or grader/ by its bare name (the old sys.path habit).
A Python command in tools/ (a platform's in its folder there too) holds no
code of its own: it starts the main() of its module in one of tools/'s
packages, or in grader/ (the driver's, the platforms' adapters).

"A camera ray, from main() to the pixel": every row's file exists and
defines the function the row names (Class::name: a definition written
Class::name(...) { ... }, or name(...) { ... } inside the class in a
header), so a rename or a move fails here until the walk follows it.

usage: check_architecture.py REPOSITORY"""
import re
import subprocess
import sys
from pathlib import Path

LISTED_IN_FULL = ("framework", "grader", "apps", "tests", "media", "docs")


def section(text: str, heading: str) -> str:
    start = text.find(f"\n## {heading}\n")
    if start < 0:
        raise SystemExit(f"check_architecture: docs/architecture.md has no section '## {heading}'")
    end = text.find("\n## ", start + 1)
    return text[start:end if end > 0 else len(text)]


def tree_folders(block: str):
    """(path, line) for every folder line of the tree: 'name/' after two spaces per level."""
    stack = []
    for line in block.splitlines():
        m = re.match(r"( *)(\S+/)(?:\s|$)", line)
        if not m:
            continue
        depth = len(m.group(1)) // 2
        stack = stack[:depth] + [m.group(2).rstrip("/")]
        yield "/".join(stack), line


def check_tree(root: Path, text: str, problems: list):
    block = re.search(r"```\n(.*?)```", section(text, "The folders"), re.S)
    if not block:
        raise SystemExit("check_architecture: 'The folders' has no tree (a ``` block)")
    listed, release_only = {}, []
    for path, line in tree_folders(block.group(1)):
        listed[path] = line
        if "not in the student release" in line:
            release_only.append(path)
        matches = [p for p in root.glob(path.replace("NN-name", "[0-9][0-9]-*")) if p.is_dir()]
        release = not (root / "solutions").exists() and any(path == r or path.startswith(r + "/") for r in release_only)
        made_for_release = "only in the student release" in line and (root / "solutions").exists()
        if not matches and not release and not made_for_release:
            problems.append(f"The folders: {path}/ does not exist")
    numbered = {re.sub(r"(^|/)[0-9][0-9]-[^/]+", r"\1NN-name", p) for p in listed}

    def present(rel: str) -> bool:
        return rel in listed or re.sub(r"(^|/)[0-9][0-9]-[^/]+", r"\1NN-name", rel) in numbered

    def ignored(paths) -> set:
        """The folders git ignores (a tool's output, e.g. try-platform/): not the repository's."""
        asked = subprocess.run(["git", "-C", str(root), "check-ignore", "--stdin"], input="\n".join(map(str, paths)),
                               capture_output=True, text=True)
        return {Path(line) for line in asked.stdout.splitlines()}

    def folders(base: Path):
        found = [p for p in base.iterdir() if p.is_dir() and not p.name.startswith(("build", "__pycache__"))
                 and (not p.name.startswith(".") or p.name == ".ci") and any(p.rglob("*.*"))]
        return sorted(set(found) - ignored(found))

    for folder in folders(root):
        if not present(folder.name):
            problems.append(f"The folders: {folder.name}/ is in the repository but not in the tree")
        if folder.name in LISTED_IN_FULL:
            for sub in folders(folder):
                rel = f"{folder.name}/{sub.name}"
                if not present(rel):
                    problems.append(f"The folders: {rel}/ is in the repository but not in the tree")


def strip_comments(code: str) -> str:
    return re.sub(r"//[^\n]*|/\*.*?\*/", " ", code, flags=re.S)


def closing_paren(code: str, start: int) -> int:
    depth = 0
    for i in range(start, len(code)):
        if code[i] == "(":
            depth += 1
        elif code[i] == ")":
            depth -= 1
            if depth == 0:
                return i
    return -1


def defines(code: str, function: str, header: bool) -> bool:
    """True if `code` holds a definition of `function` (name or Class::name)."""
    owner, _, name = function.rpartition("::")
    prefixes = [re.escape(owner) + r"\s*::\s*"] if owner else [""]
    if owner and header and re.search(rf"\b(class|struct)\s+{re.escape(owner)}\b", code):
        prefixes.append("")  # defined inside the class body
    for prefix in prefixes:
        for m in re.finditer(rf"(?<![\w.>:~]){prefix}{re.escape(name)}\s*\(", code):
            end = closing_paren(code, m.end() - 1)
            if end < 0:
                continue
            rest = code[end + 1:]
            # After the parameters: qualifiers, a trailing return type, then the body
            # (or a constructor's member initialisers, then the body).
            q = re.match(r"\s*(?:(?:const|noexcept|override|final)\b\s*)*(?:->[^;{]*)?(\{|:(?!:))", rest)
            if q:
                return True
    return False


def check_walk(root: Path, text: str, problems: list):
    rows = re.findall(r"^\|\s*\d+\s*\|\s*`([^`]+)`\s*\|\s*`([^`]+)`\s*\|", section(text, "A camera ray, from main() to the pixel"),
                      re.M)
    if len(rows) < 10:
        problems.append(f"A camera ray: found {len(rows)} rows of | step | `file` | `function` | (the table's layout changed?)")
    for file, function in rows:
        path = root / file
        if not path.is_file():
            if file.startswith("solutions/") and not (root / "solutions").exists():
                continue
            problems.append(f"A camera ray: {file} does not exist")
        elif not defines(strip_comments(path.read_text()), function, path.suffix == ".h"):
            problems.append(f"A camera ray: {file} does not define {function}")
    return len(rows)


IMPORT_ROOT_LINE = re.compile(r"^\s*sys\.path\.insert\(0, str\([^\n]*\)\)  # the repository: the import root\b")
PACKAGE_IMPORT = re.compile(r"^\s*from ((?:tools|grader|tests)(?:\.\w+)*) import ([\w, ]+)", re.M)
PATH_EDIT = re.compile(r"sys\.path\.(?:insert|append|extend)\(|sys\.path\s*(?:\+)?=|sys\.path\[")
BARE_IMPORT = re.compile(r"^\s*(?:import|from) (pathlab_\w+|writeup_page|cycles_bridge)\b", re.M)


def python_files(root: Path) -> list:
    """Every tracked Python file: *.py, and the commands whose first line starts python3."""
    listed = subprocess.run(["git", "-C", str(root), "ls-files"], capture_output=True, text=True).stdout.split()
    files = []
    for name in listed:
        path = root / name
        if not path.is_file() or name.startswith("tools/task-template/"):
            continue
        if name.endswith(".py"):
            files.append(path)
        elif "." not in path.name:
            with path.open("rb") as f:
                first = f.readline()
            if first.startswith(b"#!") and b"python" in first:
                files.append(path)
    return files


def check_imports(root: Path, problems: list) -> int:
    files = python_files(root)
    imported = set()
    for path in files:
        for package, names in PACKAGE_IMPORT.findall(path.read_text()):
            base = root / package.replace(".", "/")
            for name in (n.split()[0] for n in names.split(",") if n.strip()):
                imported.update(p for p in (base.with_suffix(".py"), base / f"{name}.py") if p.is_file())
    for path in files:
        text, rel = path.read_text(), path.relative_to(root)
        edits = [line for line in text.splitlines() if PATH_EDIT.search(line)]
        marked = [line for line in edits if IMPORT_ROOT_LINE.match(line)]
        if len(edits) != len(marked) or len(marked) > 1:
            problems.append(f"Imports: {rel} edits sys.path other than by one marked import-root line")
        if marked and path in imported:
            problems.append(f"Imports: {rel} is a module others import, yet it edits sys.path")
        for bare in BARE_IMPORT.findall(text):
            problems.append(f"Imports: {rel} imports {bare} by its bare name (from tools import {bare})")
        if rel.parts[0] == "tools" and path.suffix == "" and re.search(r"^(def|class) ", text, re.M):
            problems.append(f"Imports: {rel} is a command with code of its own: move it into a module (of tools/'s "
                            f"packages, or grader/platforms/ for a platform's) and start its main() (as tools/check "
                            f"starts grader/driver/check.py)")
    return len(files)


def main() -> int:
    root = Path(sys.argv[1]).resolve()
    text = (root / "docs" / "architecture.md").read_text()
    problems = []
    check_tree(root, text, problems)
    rows = check_walk(root, text, problems)
    scripts = check_imports(root, problems)
    for p in problems:
        print(p)
    print(f"docs/architecture.md: the tree, {rows} hops of the camera ray's walk and the imports of {scripts} Python "
          f"files: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
