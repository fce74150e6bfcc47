#!/usr/bin/env python3
"""Every program the grading path runs outside the sandbox is listed in
docs/threat-model.md, and none of them acts on the submission's bytes.

Grades, under strace (every execve, and the clones that say whose child a
process is), a submission of two tasks: task 1 a file whose object carries
GCC's LTO IR (the linker-plugin attack: a host linker's plugin would compile
it), task 2 the reference (compiled, linked and run: the whole path). A
process is in the sandbox from the moment it runs setpriv (the grader runs
as root: every sandbox mode starts there) and so are its children. Every
other program run must be one the page's table names, and of those only the
launchers (which start the sandbox and read nothing they are given) may name
a file where the submission's bytes live (its folder, the grade's scratch
folder). What CMake and Ninja run (configure steps, compilers) belongs to the
grader's build: only the last rule applies to it.

usage: test_host_programs.py REPO_ROOT WORK_DIR GRADE_BUILD_DIR --sandbox bwrap|uid"""
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

root, work, build = (Path(a).resolve() for a in sys.argv[1:4])
sandbox = sys.argv[sys.argv.index("--sandbox") + 1] if "--sandbox" in sys.argv else "bwrap"
sys.dont_write_bytecode = True
sys.path.insert(0, str(root))  # the repository: the import root (docs/architecture.md)
from tools import pathlab_tasks
from tools.validity.adversary_lab import compile_argv, lto_sections  # noqa: E402

PAGE = root / "docs" / "threat-model.md"
HEADING = "## Programs the grading path runs outside the sandbox"
# They start the sandbox: they exec the command they are given and read none of its files.
LAUNCHERS = {"choom", "prlimit", "setpriv", "sh", "launch-N"}
# The grader's build (the table's second row): whatever they run (CMake's configure steps, the compilers) is
# theirs, checked only for the submission's files.
BUILD_TOOLS = {"cmake", "ninja"}


def documented():
    """The programs the page's table names: every `name` in its first column."""
    text = PAGE.read_text()
    if HEADING not in text:
        raise SystemExit(f"FAIL: {PAGE} has no section '{HEADING}'")
    table = text.split(HEADING, 1)[1].split("\n## ", 1)[0]
    names = set()
    for line in table.splitlines():
        if line.startswith("| ") and not line.startswith(("| program", "| ---")):
            names |= set(re.findall(r"`([^`]+)`", line.split("|")[1]))
    return names


def host_programs(trace: str):
    """[(program, argv, run by the build)] of every execve that succeeded outside the sandbox: not in a
    process that ran setpriv before it, nor in a child of one (a clone's return may be printed after the
    child's execve, so the parents are read first); "run by the build": a descendant of CMake or Ninja."""
    parent, execs = {}, []  # execs: (pid, path, argv), in order
    pending = {}
    for line in trace.splitlines():
        match = re.match(r"(\d+) +(?:<\.\.\. )?(clone3?|fork|vfork|execve)\b(.*)$", line)
        if not match:
            continue
        pid, call, rest = int(match.group(1)), match.group(2), match.group(3)
        if call != "execve":
            # (--pidns-translation: a child in a new pid namespace, as bubblewrap's, "= 2 /* 1234 in strace's PID NS */")
            child = re.search(r"= (\d+)(?: /\* (\d+) in strace's PID NS \*/)?$", rest)
            if child:
                parent[int(child.group(2) or child.group(1))] = pid
            continue
        started = re.match(r'\("([^"]*)", \[(.*?)\](?:, | <unfinished)', rest)
        if started:
            pending[pid] = (started.group(1), re.findall(r'"((?:[^"\\]|\\.)*)"', started.group(2)))
        if re.search(r"= 0$", rest) and pid in pending:
            execs.append((pid, *pending.pop(pid)))
    confined = set()  # pids that ran setpriv
    program = {}  # pid: the program it runs (its last execve so far)
    found = []
    for pid, path, argv in execs:
        ancestors, ancestor = [], parent.get(pid)
        while ancestor:
            ancestors.append(ancestor)
            ancestor = parent.get(ancestor)
        if pid in confined or confined.intersection(ancestors):
            continue
        name = re.sub(r"^launch-\d+$", "launch-N", re.sub(r"^test-\d+-[\w-]+$", "test-NN-name", os.path.basename(path)))
        program[pid] = name
        # What the grader's build runs (CMake's configure steps, Ninja's compilers) is that build's.
        built = any(program.get(a) in BUILD_TOOLS for a in ancestors)
        found.append((name, argv, built))
        if name == "setpriv":
            confined.add(pid)  # what it runs next is the sandbox uid's
    return found


def main() -> int:
    scratch = work / f"host-programs-{sandbox}"
    shutil.rmtree(scratch, ignore_errors=True)
    submission = scratch / "submission"
    submission.mkdir(parents=True)
    tasks = pathlab_tasks.tasks()
    (folder1, file1), (folder2, file2) = tasks[1], tasks[2]
    ir = (root / "tasks" / folder1 / file1).read_text() + "\n" + \
        (root / "grader/tests/attacks/lto-ir.inc").read_text().replace("@ROOT@", str(root))
    (submission / file1).write_text(lto_sections(ir, compile_argv(build, 1), scratch / "ir"))
    shutil.copy(root / "solutions" / folder2 / file2, submission / file2)
    out, trace = scratch / "results.json", scratch / "trace.txt"
    grade = subprocess.run(["strace", "-f", "-qq", "--pidns-translation", "-s", "4096", "-e", "trace=execve,clone,clone3,fork,vfork",
                            "-e", "signal=none", "-o", str(trace), sys.executable, str(root / "tools/grade"),
                            str(submission), "--tasks", "1,2", "--out", str(out), "--build-dir", str(build),
                            "--sandbox", sandbox], capture_output=True, text=True, timeout=1200)
    problems = []
    results = json.loads(out.read_text()) if out.exists() else None
    if not results:
        problems.append(f"no results.json (exit {grade.returncode}): {grade.stderr[-500:]}")
    else:
        earned = {n: sum(t["score"] for t in results["tests"] if t["name"].startswith(f"Task {n}:")) for n in (1, 2)}
        full = sum(t["max_score"] for t in results["tests"] if t["name"].startswith("Task 2:"))
        if earned[1] != 0 or earned[2] != full:
            problems.append(f"scores {earned}: expected 0 for the IR-carrying task 1, {full} for the reference's task 2")
    allowed = documented()
    programs = host_programs(trace.read_text())
    # Where the submission's bytes are: its folder, the grade's scratch (compiled, linked, run), and the
    # build's submission-objects/ (where the object went when the host linked it).
    submission_files = re.compile(rf"/pathlab-grade-[^/]+/|{re.escape(str(submission))}|(^|/)submission-objects/")
    for index, (name, argv, built) in enumerate(programs):
        if name not in allowed and not built:
            problems.append(f"{name} ran outside the sandbox and is not in {PAGE.name}'s table: {' '.join(argv)[:300]}")
        elif index > 0 and name not in LAUNCHERS and any(submission_files.search(a) for a in argv[1:]):
            problems.append(f"{name} ran outside the sandbox on a file of the submission's: {' '.join(argv)[:300]}")
    seen = sorted({name for name, _, built in programs if not built})
    print(f"{sandbox}: {len(programs)} programs run outside the sandbox: {', '.join(seen)}")
    for p in problems:
        print("FAIL:", p)
    if problems:
        print(f"(kept: {scratch})")
        return 1
    shutil.rmtree(scratch, ignore_errors=True)
    print(f"PASS: every program outside the sandbox is in {PAGE.name}'s table, and none names the submission's files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
