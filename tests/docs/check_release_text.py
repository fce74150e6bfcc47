#!/usr/bin/env python3
"""Every subset of the tasks is a complete course, as its student release
reads: for each subset below, tools/make-student-release --text-only makes
the release (no build), and then

  - the pages a student reads name only paths the release holds
    (check_doc_paths.py, strict for those pages in a release), every
    relative link in the README, the docs and the handouts resolves, and
    no page keeps a "course repository only" or "student release only"
    marker (tools/make-student-release resolves them);
  - the README's task table has a row per task, linking its handout, and
    says "not handed out" exactly for the tasks the course withholds; its
    layout lists only folders and tools the release holds;
  - a handout that builds on another task ("task 4's shadow ray", "as in
    task 5") finds that task's recipe in the release: the other task is
    handed out, or its handout keeps "## The recipe" (its maths);
  - the recipes the extension tasks lean on are there whole: task 4's
    shadow-ray contract and task 5's Russian roulette.
And the release's own CTests that need no build pass there (task-defaults,
docs-paths, ...), and docs/submitting.md's rule for a task's file holds for
every task.

usage: check_release_text.py REPOSITORY [--tasks 5,9 ...]"""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

SUBSETS = ["1,2,3,4,5,6,7", "8,9,10,11,12", "5,9", "1,12", "3,9,12", "1,2,3,4,5,9"]
RECIPE_MUST_HOLD = {4: ["offsetRayOrigin", "1 − 10⁻⁴"], 5: ["Russian roulette", "divide the throughput by q"]}
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")


def handouts(release: Path):
    """{task number: handout path}."""
    return {int(p.parent.name[:2]): p for p in sorted(release.glob("tasks/[0-9][0-9]-*/README.md"))}


def own_build_free_tests(release: Path) -> list:
    """The release's own CTests that need no build (a script of tests/docs/ given only the source
    folder), run there as its ctest runs them: a student's ctest shows no failure that is no task's."""
    problems = []
    for name, script in registered_build_free_tests(release):
        ran = subprocess.run([sys.executable, str(release / "tests" / script), str(release)], capture_output=True,
                             text=True, cwd=release, timeout=300)
        if ran.returncode != 0:
            problems.append(f"the release's own CTest {name} fails: {(ran.stdout + ran.stderr).strip()[-400:]}")
    return problems


def registered_build_free_tests(release: Path) -> list:
    """(name, script) of each such test tests/CMakeLists.txt registers in the release: inside an
    if(EXISTS ${CMAKE_SOURCE_DIR}/PATH) only where PATH is there (other conditions taken as true)."""
    found, enclosing = [], []
    test = re.compile(r"add_test\(NAME ([\w-]+) COMMAND \$\{Python3_EXECUTABLE\}\s+"
                      r"\$\{CMAKE_CURRENT_SOURCE_DIR\}/(docs/[\w-]+\.py)\s+\$\{CMAKE_SOURCE_DIR\}\s*\)")
    lines = (release / "tests" / "CMakeLists.txt").read_text().splitlines()
    for i, line in enumerate(lines):
        stripped = line.strip()
        if stripped.startswith("if("):
            paths = re.findall(r"EXISTS \$\{CMAKE_SOURCE_DIR\}/(\S+?)\)?(?:\s|$)", stripped)
            enclosing.append(all((release / path).exists() for path in paths))
        elif stripped.startswith("endif("):
            enclosing.pop()
        match = test.match(stripped + " " + " ".join(l.strip() for l in lines[i + 1:i + 2]))
        if match and all(enclosing):
            found.append((match.group(1), match.group(2)))
    return found


def check_subset(repo: Path, subset: str, scratch: Path) -> list:
    release = scratch / f"release-{subset.replace(',', '-')}"
    made = subprocess.run([str(repo / "tools" / "make-student-release"), "--text-only", "--worktree", str(release),
                           "--tasks", subset], capture_output=True, text=True)
    if made.returncode != 0:
        return [f"make-student-release --tasks {subset} failed: {made.stderr.strip()[-400:]}"]
    problems = []
    handed_out = {int(n) for n in subset.split(",")}

    paths = subprocess.run([sys.executable, str(Path(__file__).with_name("check_doc_paths.py")), str(release)],
                           capture_output=True, text=True)
    if paths.returncode != 0:
        problems += [line for line in paths.stdout.splitlines() if "does not exist" in line]

    problems += own_build_free_tests(release)

    pages = [release / "README.md"] + sorted((release / "docs").glob("*.md")) + list(handouts(release).values())
    for page in pages:
        if "course repository only" in page.read_text() or "student release only" in page.read_text():
            problems.append(f"{page.relative_to(release)}: a course/release marker is left in the release")
        if re.search(r"@[A-Z_]+@", page.read_text()):
            problems.append(f"{page.relative_to(release)}: a placeholder left unfilled: "
                            f"{re.search(r'@[A-Z_]+@', page.read_text()).group(0)}")
        prose = re.sub(r"`[^`\n]*`", "", re.sub(r"^```.*?^```", "", page.read_text(), flags=re.S | re.M))
        for target in LINK.findall(prose):  # links outside code
            if re.match(r"[a-z]+:", target) or target.startswith("#"):
                continue
            if not (page.parent / target.split("#")[0]).exists():
                problems.append(f"{page.relative_to(release)}: the link {target} leads nowhere")

    readme = (release / "README.md").read_text()
    for number, handout in handouts(release).items():
        folder = handout.parent.name
        row = re.search(rf"^\| {number} [^|]*\| \[`tasks/{folder}/`\]\(tasks/{folder}/README.md\) \| ([^|]*)\|$",
                        readme, re.M)
        if not row:
            problems.append(f"README.md: no task-table row linking tasks/{folder}/README.md")
        elif ("not handed out" in row.group(1)) == (number in handed_out):
            problems.append(f"README.md: task {number}'s row says {row.group(1).strip()!r}")
    layout = readme[readme.index("```\n", readme.index("## Layout")) + 4:]
    layout = layout[:layout.index("```\n")]
    for folder in re.findall(r"^(\S+/)", layout, re.M):
        if not (release / folder).exists():
            problems.append(f"README.md's layout lists {folder}, which the release has not")
    tools_entry = re.search(r"^tools/ +(.*(?:\n {13}.*)*)", layout, re.M)
    for name in re.findall(r"(?:^|, )([\w.-]+/?)", " ".join(tools_entry.group(1).split()) if tools_entry else ""):
        if not (release / "tools" / name).exists():
            problems.append(f"README.md's layout lists tools/{name}, which the release has not")

    for number, handout in handouts(release).items():
        text = handout.read_text()
        if number not in handed_out:
            recipe = text.split("## The recipe", 1)
            if len(recipe) < 2 or len(recipe[1].strip()) < 200:
                problems.append(f"{handout.relative_to(release)}: a task not handed out keeps no recipe")
            for phrase in RECIPE_MUST_HOLD.get(number, []):
                if phrase not in text:
                    problems.append(f"{handout.relative_to(release)}: its recipe lacks {phrase!r}")
            continue
        for other in sorted({int(n) for n in re.findall(r"\btasks? (\d+)(?!\.\d)", text)} - {number}):
            target = handouts(release).get(other)
            if target is None:
                problems.append(f"{handout.relative_to(release)}: names task {other}, which the release has not")
            elif other not in handed_out and "## The recipe" not in target.read_text():
                problems.append(f"{handout.relative_to(release)}: builds on task {other}, whose handout keeps "
                                f"no recipe in this release")
    return [f"[tasks {subset}] {p}" for p in problems]


def check_submitting_page(repo: Path) -> list:
    """docs/submitting.md's rule for a task's file holds for every task, and its example is a real task's."""
    sys.path.insert(0, str(repo))  # the repository: the import root (docs/architecture.md)
    from tools import pathlab_tasks
    page = (repo / "docs" / "submitting.md").read_text()
    problems = []
    if "`tasks/NN-name/name.cpp`" not in page:
        problems.append("docs/submitting.md no longer states the rule `tasks/NN-name/name.cpp`")
    for n, (folder, name) in pathlab_tasks.tasks(repo).items():
        if name != folder[3:].replace("-", "_") + ".cpp" or not (repo / "tasks" / folder / name).is_file():
            problems.append(f"docs/submitting.md: task {n}'s file is not tasks/{folder}/{name}, as its rule says")
    for folder, name, submitted in re.findall(r"`tasks/(\d\d-[a-z0-9-]+)/([\w.]+)`, submitted as\s+`([\w.]+)`", page):
        if not (repo / "tasks" / folder / name).is_file() or submitted != name:
            problems.append(f"docs/submitting.md: its example tasks/{folder}/{name} (submitted as {submitted}) "
                            "is not a task's file")
    if not re.search(r"`tasks/\d\d-[a-z0-9-]+/[\w.]+`, submitted as", page):
        problems.append("docs/submitting.md: its example of the rule is gone")
    return problems


def main() -> int:
    repo = Path(sys.argv[1]).resolve()
    subsets = sys.argv[sys.argv.index("--tasks") + 1:] if "--tasks" in sys.argv else SUBSETS
    problems = check_submitting_page(repo)
    with tempfile.TemporaryDirectory() as scratch:
        for subset in subsets:
            problems += check_subset(repo, subset, Path(scratch))
    for p in problems:
        print(p)
    print(f"{len(subsets)} course subsets ({'; '.join(subsets)}): {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
