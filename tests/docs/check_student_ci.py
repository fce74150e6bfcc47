#!/usr/bin/env python3
"""The students' GitHub workflow (tools/student-ci.yml) runs docs/setup.md's commands.

GitHub Actions cannot run here, so this checks the workflow against what
can be checked: every `run:` command is a line of a sh block in
docs/setup.md; the MSYS2 `install:` list is setup.md's pacman list; the
Ubuntu apt list is tools/packages.sh's pathlab_core (what the grader
builds with); the matrix is Ubuntu, macOS and Windows; it runs the check
before submitting (tools/check) into the job summary; every preset a
command names exists; tools/make-student-release installs the file; and
.vscode/launch.json debugs the student build's suites and renderer.

    check_student_ci.py REPO            the check
    check_student_ci.py REPO --self-test  the check must fail on altered copies
"""
import json
import re
import subprocess
import sys
from pathlib import Path


def sh_lines(markdown):
    """Every line inside ```sh blocks."""
    lines, inside = [], False
    for line in markdown.splitlines():
        if line.startswith("```"):
            inside = line.strip() == "```sh" if not inside else False
            continue
        if inside:
            lines.append(line.strip())
    return lines


def workflow_fields(text):
    runs = [m.group(1).strip() for m in re.finditer(r"^\s+run: (.+)$", text, re.M)]
    installs = [m.group(1).split() for m in re.finditer(r"^\s+install: (.+)$", text, re.M)]
    matrix = re.search(r"^\s+os: \[(.+)\]$", text, re.M)
    oses = [o.strip() for o in matrix.group(1).split(",")] if matrix else []
    return runs, installs, oses


def check(repo, workflow, setup, release_script):
    problems = []
    runs, installs, oses = workflow_fields(workflow)
    commands = sh_lines(setup)
    if oses != ["ubuntu-latest", "macos-latest", "windows-latest"]:
        problems.append(f"matrix is {oses}, not ubuntu-latest, macos-latest, windows-latest")
    if not runs:
        problems.append("no run: commands")
    for run in runs:
        if run not in commands:
            problems.append(f"run: '{run}' is not a command in docs/setup.md")
    pacman = [c for c in commands if c.startswith("pacman -S --needed mingw-w64")]
    if len(installs) != 1 or len(pacman) != 1 or installs[0] != pacman[0].split()[3:]:
        problems.append("the MSYS2 install: list is not docs/setup.md's pacman command")
    core = subprocess.run(["bash", "-c", 'source tools/packages.sh; echo "${pathlab_core[@]}"'],
                          cwd=repo, capture_output=True, text=True, check=True).stdout.split()
    apt = [r for r in runs if r.startswith("sudo apt-get install -y ")]
    if len(apt) != 1 or apt[0].split()[4:] != core:
        problems.append(f"the Ubuntu install is not tools/packages.sh's pathlab_core ({' '.join(core)})")
    presets = json.loads((repo / "CMakePresets.json").read_text())
    for kind, pattern in [("configurePresets", r"cmake --preset (\S+)"),
                          ("buildPresets", r"cmake --build --preset (\S+)"),
                          ("testPresets", r"ctest --preset (\S+)")]:
        names = {p["name"] for p in presets[kind]}
        for run in runs:
            for name in re.findall(pattern, run):
                if name not in names:
                    problems.append(f"'{run}' names {kind[:-1]} '{name}', which CMakePresets.json lacks")
    checks = [r for r in runs if r.startswith("python3 tools/check")]
    if len(checks) != 1 or "$GITHUB_STEP_SUMMARY" not in checks[0] or not (repo / "tools/check").exists():
        problems.append("the workflow does not run tools/check (the check before submitting) into the job summary")
    installed = repo / ".github/workflows/pathlab.yml"  # in a student release
    if installed.exists() and installed.read_text() != workflow:
        problems.append(".github/workflows/pathlab.yml differs from tools/student-ci.yml")
    if "tools/student-ci.yml" not in release_script or ".github/workflows/pathlab.yml" not in release_script:
        problems.append("tools/make-student-release does not install tools/student-ci.yml as .github/workflows/pathlab.yml")
    return problems + check_vscode(repo, presets)


def check_vscode(repo, presets):
    """.vscode/launch.json debugs what the student preset builds: the suite of
    the task whose file is open (its folder's name, NN-name, is the suite's:
    test-NN-name, for any task, with no list to keep), and the renderer."""
    problems = []
    student = next(p for p in presets["configurePresets"] if p["name"] == "student")
    build = student["binaryDir"].replace("${sourceDir}", "${workspaceFolder}")
    launch = json.loads((repo / ".vscode/launch.json").read_text())
    if "inputs" in launch:
        problems.append(".vscode/launch.json: an input list (the task folder's name is the suite's name)")
    programs = [c["program"] for c in launch["configurations"]]
    if f"{build}/tests/test-${{fileDirnameBasename}}" not in programs or f"{build}/pathlab" not in programs:
        problems.append(f".vscode/launch.json: programs {programs} are not the student build's suite and renderer")
    if "add_executable(test-${name}" not in (repo / "tests/CMakeLists.txt").read_text():
        problems.append("tests/CMakeLists.txt no longer names the suites test-NN-name (.vscode/launch.json does)")
    if json.loads((repo / ".vscode/settings.json").read_text()).get("cmake.useCMakePresets") != "always":
        problems.append(".vscode/settings.json: CMake Tools does not use the presets")
    return problems


def main():
    repo = Path(sys.argv[1]).resolve()
    workflow = (repo / "tools/student-ci.yml").read_text()
    setup = (repo / "docs/setup.md").read_text()
    release = repo / "tools/make-student-release"
    # A student release has no make-student-release (it made the release).
    release_script = release.read_text() if release.exists() else "tools/student-ci.yml .github/workflows/pathlab.yml"
    problems = check(repo, workflow, setup, release_script)
    if "--self-test" in sys.argv:
        if problems:
            print("\n".join(problems))
            return 1
        # Each alteration is a way the two could drift apart; each must be caught.
        altered = {
            "a command changed": (workflow.replace("cmake --build --preset student", "cmake --build build"), setup),
            "a package dropped from brew": (workflow.replace(" fast_float glfw\n", " glfw\n"), setup),
            "a package dropped from MSYS2": (workflow.replace(" mingw-w64-ucrt-x86_64-python\n", "\n"), setup),
            "a package added to apt": (workflow.replace("libpugixml-dev\n", "libpugixml-dev libfoo\n"), setup),
            "the docs' command changed": (workflow, setup.replace("brew install cmake", "brew install cmake gcc")),
            "windows dropped from the matrix": (workflow.replace(", windows-latest]", "]"), setup),
            "the check before submitting dropped": (workflow.replace("run: python3 tools/check", "run: true"), setup),
            "a preset that does not exist": (workflow.replace("ctest --preset student", "ctest --preset students"),
                                             setup.replace("ctest --preset student", "ctest --preset students")),
        }
        missed = [name for name, (w, s) in altered.items() if w == workflow and s == setup or
                  not check(repo, w, s, release_script)]
        for name in missed:
            print(f"self-test: not caught (or not applied): {name}")
        print(f"student-ci self-test: {len(altered) - len(missed)} of {len(altered)} alterations caught")
        return 1 if missed else 0
    for p in problems:
        print(f"student-ci: {p}")
    print(f"student-ci: {len(workflow_fields(workflow)[0])} workflow commands checked against docs/setup.md: "
          f"{'ok' if not problems else f'{len(problems)} problem(s)'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
