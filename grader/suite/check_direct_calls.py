#!/usr/bin/env python3
"""Every call a suite makes to its own task's functions goes to the
candidate: the judge links the reference, so a plain intersectTriangle(...)
in tests/02-intersection would test the reference, not the student. This
check fails on any call of a task function in a suite's test files that is
not written candidate::name(...) (comments and strings are ignored), on
a suite that judges a mean by the candidate's own noise without a ceiling
(MeanEstimate::judgeByOwnNoise, which is for the framework's own tests),
and on any test file that includes doctest other than through
grader/suite/doctest_strings.h (without it a C string in a message prints as
an address).

usage: check_direct_calls.py TESTS_DIR FRAMEWORK_DIR"""
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the repository: the import root (docs/architecture.md)
from tools import pathlab_tasks  # noqa: E402  (the task list: the tasks/NN-name folders)
from tools.cpp_tokens import blank_comments_and_literals as code_only  # noqa: E402

SUITES = {folder: file.replace(".cpp", ".h") for folder, file in pathlab_tasks.tasks().values()}


def task_functions(header: Path) -> set:
    code = code_only(header.read_text())
    # Declarations at namespace level: "Type name(" at the start of a line.
    return set(re.findall(r"^[A-Za-z_][\w:<>, ]*?[\s*&]([a-z]\w*)\(", code, re.M))


def main() -> int:
    tests, framework = Path(sys.argv[1]), Path(sys.argv[2])
    problems = []
    for suite, header in SUITES.items():
        names = task_functions(framework / "tasks" / header)
        if not names:
            problems.append(f"{header}: found no function declarations (has its layout changed?)")
        for source in sorted((tests / suite).glob("test_*.cpp")):
            code = code_only(source.read_text())
            for number, line in enumerate(code.splitlines(), 1):
                if re.search(r"\bjudgeByOwnNoise\s*\(", line):
                    problems.append(f"{source.relative_to(tests)}:{number}: judgeByOwnNoise() judges the "
                                    "candidate's mean by its own noise; give it a ceiling (limitNoise)")
                for name in names:
                    for m in re.finditer(rf"(?<![\w.>:])({name})\s*\(", line):
                        problems.append(f"{source.relative_to(tests)}:{number}: {name}(...) runs the judge's "
                                        f"reference; write candidate::{name}(...)")
    for source in sorted(tests.rglob("*.[ch]*")):
        if source.name == "doctest_strings.h" or source.suffix not in (".cpp", ".h"):
            continue
        for number, line in enumerate(source.read_text(errors="replace").splitlines(), 1):
            if re.match(r'\s*#\s*include\s*[<"]doctest/doctest\.h[>"]', line):
                problems.append(f"{source.relative_to(tests)}:{number}: include \"suite/doctest_strings.h\", not doctest "
                                "itself (a C string in a message would print as an address)")
    for p in problems:
        print(p)
    print(f"{len(SUITES)} suites checked: {len(problems)} problems (direct calls of task functions, uncapped means, "
          "doctest included directly)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
