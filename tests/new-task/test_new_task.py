#!/usr/bin/env python3
"""A course's own task 13, from tools/new-task to every tool, in a scratch
copy of the repository (docs/own-task.md): nothing but the new task's
folders is edited, and then

  0. a second graded call is added as docs/own-task.md says (T13.2, a call
     of three arguments asked in a batch, worth 3 of the task's 7 points);
  1. `git status` lists only the task's folders (tasks/, solutions/, tests/,
     writeup/; its mutants and alternates are made by the build), its API header
     framework/tasks/NAME.h, and one generated row of README.md's task table;
  2. it configures and builds, without a warning in the task's files; its
     CTest tests pass: the suite on the reference, the suite failing on the
     stub, its mutant losing points, its alternate keeping them; and the
     lab's cases: its warp accepted, the stub and the mutant rejected, the
     alternate accepted (tests/lab/check_lab.py --task);
  3. `tools/grade --tasks 13` gives the stub 0 and the reference full marks,
     and `tools/check --tasks 13` grades the stub the same as tools/grade;
     the generated adversary finds its calls and no strategy of 12 drawn
     scores more than the stub (`tools/adversary --tasks 13`);
  4. `make-student-release --tasks 13` holds its files and hands it out, and
     reads as a complete course (tests/docs/check_release_text.py);
     `make-zip.sh --tasks 13` packs its folders for Gradescope, and the
     other platforms' adapters take it (an Autolab assessment with its
     problem and handin, a PrairieLearn question, a Classroom runner);
     and every platform grades it as it runs a job (tools/try-platform all):
     the stub 0, the reference every point, a wrong handin (T13.1 wrong,
     T13.2 right: 3 of 7) the same points on each, which are tools/check's;
  5. the GUI shows its panel button, whole, labelled from its task.json, and
     draws its panel (a screenshot, kept in WORK_DIR/new-task/); the lab
     lists its warp and accepts the reference's; `pathlab debug --task 13`
     draws its view;
  6. the write-up makes its page, with its figure and its question;
  7. CI's budget gives it the share its task.json asks for, and the copy's
     own CTest checks of what every task declares pass (task-manifests,
     hint-catalogue, mutants-generated, ci-budget, layers, docs-paths,
     docs-architecture).

usage: test_new_task.py REPO_ROOT WORK_DIR [--keep]"""
import json
import os
import re
import shutil
import subprocess
import sys
import time
import zipfile
from pathlib import Path

root, work_dir = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
keep = "--keep" in sys.argv[3:]
sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the repository: the import root (docs/architecture.md)
from tests.support.scratch import copy_worktree, expectation, finish, step_runner  # noqa: E402
work = work_dir / "new-task"
copy = work / "repo"
build = copy / "build"
N, NAME, FOLDER, STEM, LABEL = 13, "textures", "13-textures", "textures", "Textures"
failures = []
started = time.time()
run = step_runner(copy, failures)  # each step: its exit and seconds printed, a failure recorded
expect = expectation(failures)


def copy_repository():
    """The working tree's files (tracked and untracked, .gitignore respected), committed in a new repository."""
    copy_worktree(root, copy)
    git = ["git", "-c", "user.name=PathLab", "-c", "user.email=pathlab@example.invalid"]
    for argv in (["init", "-q"], ["add", "-A"], ["commit", "-q", "-m", "the course before its own task"]):
        run(git + argv, what="git " + argv[0])
    return git


# A second graded call, as docs/own-task.md says to add one (a call of several arguments, asked in a batch):
# (file, the piece of the template it follows, what is added after it).
SECOND_CALL = [
    (f"framework/tasks/{STEM}.h", "Point2 sampleTriangle(Vec2 u);\n",
     "\n// T13.2: the area of the triangle a, b, c, whichever way round it winds.\n"
     "float triangleArea(Point2 a, Point2 b, Point2 c);\n"),
    (f"tasks/{FOLDER}/{STEM}.cpp", "  return Point2(0.0f);\n}\n",
     "\n// T13.2 — The area of the triangle a, b, c: half the length of the cross\n"
     "// product of two edges, |(b - a) x (c - a)| / 2, whichever way it winds.\n"
     "float triangleArea(Point2 a, Point2 b, Point2 c) {\n"
     "  // TODO(T13.2): the triangle's area.\n  PATHLAB_TODO(\"T13.2\");\n"
     "  (void)a;\n  (void)b;\n  (void)c;\n  return 0.0f;\n}\n"),
    (f"solutions/{FOLDER}/{STEM}.cpp", "  return Point2(1.0f - s, s * u.y);\n}\n",
     "\nfloat triangleArea(Point2 a, Point2 b, Point2 c) {\n"
     "  const Vec2 e1 = b - a, e2 = c - a;\n  return 0.5f * std::abs(e1.x * e2.y - e1.y * e2.x);\n}\n"),
    (f"tests/{FOLDER}/calls.h", "std::vector<Point2>(std::vector<Vec2>));\n",
     "PATHLAB_REMOTE_CALL(TriangleArea, 2, shape::Fixed, float(Point2, Point2, Point2));\n"),
    (f"tests/{FOLDER}/serve.cpp", "    return points;\n  });\n",
     f"  server.serve<calls::TriangleArea>(&{STEM}::triangleArea);\n"),
    (f"tests/{FOLDER}/test_{STEM}.cpp", "  CHECK(r.pValue > kChiSquareP);\n}\n",
     "\nTEST_CASE(\"T13.2 area: random triangles of either winding, asked in one batch\" *\n"
     "          grading(3, \"half the length of the cross product of two edges, and its absolute value: a \"\n"
     "                     \"triangle wound clockwise has a positive area too\")) {\n"
     "  const std::vector<Vec2> us = uniformPoints(3000, 2);\n"
     "  std::vector<calls::TriangleArea::Args> triangles;\n  std::vector<double> areas;\n"
     "  for (size_t i = 0; i + 2 < us.size(); i += 3) {\n"
     "    const Point2 a = us[i] * 4.0f - 2.0f, b = us[i + 1] * 4.0f - 2.0f, c = us[i + 2] * 4.0f - 2.0f;\n"
     "    triangles.push_back({a, b, c});\n"
     "    areas.push_back(0.5 * std::abs(double(b.x - a.x) * double(c.y - a.y) - double(b.y - a.y) * double(c.x - a.x)));\n"
     "  }\n"
     "  const std::vector<float> got = remote::callMany<calls::TriangleArea>(triangles);\n"
     "  HINT(\"a guard of the test itself: one area comes back for each triangle asked\");\n"
     "  REQUIRE(got.size() == triangles.size());\n  int wrong = 0;\n"
     "  for (size_t i = 0; i < got.size(); ++i) wrong += !(std::abs(double(got[i]) - areas[i]) <= 1e-4 * (1.0 + areas[i]));\n"
     "  INFO(wrong << \" of \" << got.size() << \" areas wrong\");\n"
     "  HINT(\"each area must be |(b - a) x (c - a)| / 2, of either winding\");\n  CHECK(wrong == 0);\n}\n"),
]


def second_graded_call():
    """A second graded call added to the new task as a course adds one (docs/own-task.md): the header,
    the stub's TODO, the reference, the call, its server and its test; then its hints' catalogue
    made again (the build makes the mutants again from the new reference)."""
    for rel, after, added in SECOND_CALL:
        path = copy / rel
        text = path.read_text()
        if expect(text.count(after) == 1, f"{rel}: the template no longer has {after.strip()!r} once"):
            path.write_text(text.replace(after, after + added))
    run([sys.executable, copy / "tools/hint-catalogue"], what="tools/hint-catalogue")


def status_lists_only_the_task():
    """1. What new-task changed: the task's folders, its header and one README row."""
    own = (f"tasks/{FOLDER}/", f"solutions/{FOLDER}/", f"tests/{FOLDER}/", f"writeup/{FOLDER}.md",
           f"framework/tasks/{STEM}.h")
    status = run(["git", "status", "--porcelain", "-uall"], what="git status").stdout.splitlines()
    paths = [line[3:] for line in status]
    others = [p for p in paths if not p.startswith(own) and p != "README.md"]
    expect(not others, f"new-task changed files outside the task's folders: {others}")
    for folder in own:
        expect(any(p.startswith(folder) for p in paths), f"new-task wrote nothing in {folder}")
    diff = run(["git", "diff", "-U0", "README.md"], what="git diff README.md").stdout
    changed = [line for line in diff.splitlines() if line[:1] in "+-" and not line.startswith(("+++", "---"))]
    expect(changed == [f"+| {N} {NAME} | [`tasks/{FOLDER}/`](tasks/{FOLDER}/README.md) | "
                       "student file, reference, debugger view, tests, lab warp (a course's own task) |"],
           f"README.md: not one added task-table row for task {N}: {changed}")
    print(f"  git status: {len(paths)} paths, all the task's own or README.md's one row")


def build_and_test():
    """2. The build, and the task's CTest tests (suite, stub, mutant, alternate) and lab cases."""
    run(["cmake", "--preset", "release"], what="configure (release preset)")
    targets = run(["cmake", "--build", build, "--target", "help"], what="the build's targets").stdout
    labs = re.findall(rf"^(pathlab-lab-\w+-{FOLDER}-\S+):", targets, re.M)
    expect(len(labs) == 3, f"not one lab program for each of the 3 lab cases: {labs}")
    built = run(["cmake", "--build", build, "--parallel", str(os.cpu_count() or 2), "--target", "pathlab",
                 "pathlab-gui", f"validity-{FOLDER}", *labs], timeout=1500,
                what="build pathlab, pathlab-gui, the judge, its candidates and lab programs")
    warnings = [line for line in built.stdout.splitlines() if "warning:" in line and (FOLDER in line or STEM in line)]
    expect(not warnings, f"warnings in the task's files: {warnings[:3]}")
    # The handout's test table follows the suite, T13.2 included (tools/handout-tables, as own-task.md says).
    run([sys.executable, copy / "tools/handout-tables", build, "--tasks", str(N)],
        what=f"tools/handout-tables --tasks {N}")
    expect("## Tests (7 points)" in (copy / f"tasks/{FOLDER}/README.md").read_text() and "T13.2" in
           (copy / f"tasks/{FOLDER}/README.md").read_text(), "the handout's table does not list T13.2 (7 points)")
    tests = run(["ctest", "--test-dir", build, "-R", FOLDER, "--output-on-failure"], timeout=900,
                what=f"ctest -R {FOLDER}")
    ran = re.findall(r"Test +#\d+: (\S+) \.+\s+Passed", tests.stdout)
    expected = {f"{FOLDER}-build", FOLDER, f"{FOLDER}-fails-on-stub", f"{FOLDER}-validity-build",
                f"mutants/{FOLDER}/slices-uniform", f"alternates/{FOLDER}/folded-square"}
    expect(expected <= set(ran), f"ctest -R {FOLDER} did not pass {sorted(expected - set(ran))} (passed: {ran})")
    run([sys.executable, copy / "tests/lab/check_lab.py", build / "pathlab", build / "tests", copy / "tests",
         "--task", FOLDER], what=f"check_lab.py --task {FOLDER} (its warp, the stub, the mutant, the alternate)")


def grade():
    """3. tools/grade and tools/check, on the stub and the reference."""
    env = dict(os.environ, PATHLAB_SANDBOX_UID=os.environ.get("PATHLAB_SANDBOX_UID", "64993"))  # its own uid
    scores = {}
    for kind in ("tasks", "solutions"):
        out = work / f"grade-{kind}.json"
        run([sys.executable, copy / "tools/grade", copy / kind, "--tasks", str(N), "--build-dir", build,
             "--out", out], env=env, check=kind == "solutions", what=f"tools/grade {kind} --tasks {N}")
        report = json.loads(out.read_text()) if out.exists() else {"tests": []}
        points = sum(t["max_score"] for t in report["tests"])
        names = {t["name"].split(":")[0] for t in report["tests"]}
        scores[kind] = (report.get("score"), points)
        expect(points > 0 and names == {f"Task {N}"}, f"tools/grade {kind}: tests {sorted(names)}, {points} points")
    expect(scores["tasks"][0] == 0, f"tools/grade: the stub scored {scores['tasks']}, not 0")
    expect(scores["solutions"][0] == scores["solutions"][1], f"tools/grade: the reference scored {scores['solutions']}")
    out = work / "check-tasks.json"
    run([sys.executable, copy / "tools/check", "--tasks", str(N), "--build-dir", build, "--out", out], check=False,
        what=f"tools/check --tasks {N}")
    checked = json.loads(out.read_text()) if out.exists() else {}
    expect(checked.get("score") == 0 and sum(t["max_score"] for t in checked.get("tests", [])) == scores["tasks"][1],
           f"tools/check --tasks {N} on the stub: {checked.get('score')} of "
           f"{sum(t['max_score'] for t in checked.get('tests', []))}, tools/grade: {scores['tasks']}")
    print(f"  grades: stub {scores['tasks'][0]}/{scores['tasks'][1]}, reference {scores['solutions'][0]}/"
          f"{scores['solutions'][1]}; tools/check on the stub {checked.get('score')}")
    # The generated adversary takes the task from its wire schema, as it does every task (docs/adversary.md).
    adversary = run([sys.executable, copy / "tools/adversary", "--build-dir", build, "--tasks", str(N), "--sample", "12"],
                    check=False, what=f"tools/adversary --tasks {N}")
    expect(adversary.returncode == 0 and f"task {N}: 12 strategies, 0 survivors" in adversary.stdout,
           f"tools/adversary --tasks {N}: {adversary.stdout[-1500:]}")


def zip_holds_the_task(archive, when):
    with zipfile.ZipFile(archive) as z:
        names = set(z.namelist())
        tasks_line = z.read("gradescope-tasks").decode().strip()
    for rel in (f"source/tasks/{FOLDER}/{STEM}.cpp", f"source/solutions/{FOLDER}/{STEM}.cpp",
                f"source/tests/{FOLDER}/test_{STEM}.cpp", f"source/framework/tasks/{STEM}.h"):
        expect(rel in names, f"the Gradescope zip made {when} has no {rel}")
    expect(tasks_line == str(N), f"the Gradescope zip made {when} grades tasks {tasks_line!r}, not {N}")


def release_and_zip(git):
    """4. The student release and the Gradescope zip: of the working tree, before the task is
    committed (every packager's rule, tools/package-tree) and after."""
    archive = work / "autograder-uncommitted.zip"
    made = run(["bash", copy / "tools/gradescope/make-zip.sh", archive, "--tasks", str(N)],
               what=f"make-zip.sh --tasks {N}, task {N} not committed")
    expect("uncommitted change" in made.stderr, f"make-zip.sh did not say the tree is uncommitted: {made.stderr}")
    if archive.exists():
        zip_holds_the_task(archive, "before the commit")
    run(git + ["add", "-A"], what="git add")
    run(git + ["commit", "-q", "-m", f"task {N}"], what="git commit")
    release = work / "release"
    shutil.rmtree(release, ignore_errors=True)
    run([copy / "tools/make-student-release", "--text-only", "--tasks", str(N), release],
        what=f"make-student-release --text-only --tasks {N}")
    for rel in (f"tasks/{FOLDER}/{STEM}.cpp", f"tasks/{FOLDER}/README.md", f"tests/{FOLDER}/test_{STEM}.cpp",
                f"framework/tasks/{STEM}.h", f"writeup/{FOLDER}.md"):
        expect((release / rel).is_file(), f"the student release has no {rel}")
    expect(not (release / "solutions").exists(), "the student release has solutions/")
    handed = release / "tasks/handed-out.txt"
    expect(handed.is_file() and re.sub(r"#.*", "", handed.read_text()).split() == [str(N)],
           f"the release's tasks/handed-out.txt does not hand out task {N} alone")
    run([sys.executable, copy / "tests/docs/check_release_text.py", copy, "--tasks", f"1,{N}"],
        what=f"check_release_text.py (the release of tasks 1 and {N})")
    # The other platforms' adapters: an Autolab assessment (its problems from task 13's judge), a
    # PrairieLearn question, GitHub Classroom's workflow.
    autolab = work / "autolab"
    run([sys.executable, copy / "tools/autolab/make-autograder", autolab, "--tasks", str(N), "--build-dir", build],
        what=f"autolab/make-autograder --tasks {N}")
    yml = autolab / f"pathlab-tasks-{N}" / f"pathlab-tasks-{N}.yml"
    expect(yml.is_file() and f'- name: "Task {N}"' in yml.read_text() and f'handin_filename: "{STEM}.cpp"' in
           yml.read_text(), f"the Autolab assessment has no problem 'Task {N}' handing in {STEM}.cpp")
    run([sys.executable, copy / "tools/prairielearn/make-course", work / "prairielearn", "--tasks", str(N)],
        what=f"prairielearn/make-course --tasks {N}")
    question = work / "prairielearn/questions/pathlab" / FOLDER
    expect((question / "info.json").is_file() and f'file-names="{STEM}.cpp"' in (question / "question.html").read_text(),
           f"the PrairieLearn question of task {N} is missing or uploads another file")
    workflow = run([sys.executable, copy / "tools/classroom/make-workflow", "--tasks", str(N)],
                   what=f"classroom/make-workflow --tasks {N}").stdout
    expect(f"tools/check --tasks {N} " in workflow and f"tools/classroom/report pathlab-results.json --tasks {N} "
           "--notify" in workflow, f"the GitHub Classroom workflow does not grade and report task {N}")
    archive = work / "autograder.zip"
    run(["bash", copy / "tools/gradescope/make-zip.sh", archive, "--tasks", str(N)], what=f"make-zip.sh --tasks {N}")
    if archive.exists():
        zip_holds_the_task(archive, "after the commit")


def every_platform():
    """4b. Every platform's package holds the task and grades it as that platform runs a job
    (tools/try-platform all): the stub 0, the reference every point, a wrong handin (the template's
    mutant, handed in as the task's file) the same points everywhere, which are tools/check's."""
    wrong = work / "wrong-handin"
    wrong.mkdir(exist_ok=True)
    shutil.copy(build / "tests" / "validity" / "mutants" / FOLDER / "slices-uniform.cpp", wrong / f"{STEM}.cpp")
    env = dict(os.environ, PATHLAB_SANDBOX_UID=os.environ.get("PATHLAB_SANDBOX_UID", "64993"),
               PATHLAB_PLATFORMS_UID=os.environ.get("PATHLAB_PLATFORMS_UID", "64996"))
    tried = run([sys.executable, copy / "tools/try-platform", "all", "--tasks", str(N), "stubs", "reference", wrong,
                 "--out", work / "try-platform", "--build-dir", build], env=env, timeout=1500, what=f"try-platform all --tasks {N}")
    got = {(platform, handin): (float(earned), float(possible)) for platform, handin, earned, possible in
           re.findall(rf"^(\w+) (\S+): ([\d.]+) of ([\d.]+) points \(task {N} ", tried.stdout, re.M)}
    platforms = ("gradescope", "autolab", "prairielearn", "classroom")
    expect(set(got) == {(p, h) for p in platforms for h in ("stubs", "reference", wrong.name)},
           f"try-platform did not grade each handin on each platform: {sorted(got)}\n{tried.stdout[-1500:]}")
    full = got.get(("gradescope", "reference"), (0, 0))[1]
    points = {got.get((p, wrong.name)) for p in platforms}
    expect(full > 0 and all(got.get((p, "reference")) == (full, full) and got.get((p, "stubs")) == (0, full)
                            for p in platforms), f"the stub or the reference graded differently: {got}")
    expect(len(points) == 1 and 0 < next(iter(points))[0] < full,
           f"the wrong handin got different points on the platforms, or kept them all: {got}")
    print(f"  every platform: stub 0, reference {full:g}/{full:g}, the wrong handin "
          f"{got.get(('classroom', wrong.name))} (tools/check's, the classroom's)")


def gui_lab_and_views():
    """5. The GUI's panel, the lab's warp and the debugger's view."""
    shot = work / f"gui-panel-{N}.png"
    script = work / "session.txt"
    script.write_text(f"panel {N}\nwait\nwait-panel\nscreenshot {shot}\npanels\nlab {NAME}-triangle\nwait-panel\n"
                      "lab-verdict\nquit\n")
    session = run([root / "tools" / "with-xvfb", build / "pathlab-gui", "--script", script, "--timeout", "300"],
                  what="pathlab-gui --script")
    log = session.stdout
    panels = next((line for line in log.splitlines() if line.startswith("script: panels -> ")), "")
    expect(re.search(rf"-> {N + 1} buttons in \d+ rows, 0 cut: ", panels) and
           (f": {N} {LABEL}" in panels or f"| {N} {LABEL}" in panels),
           f"the GUI has no whole button '{N} {LABEL}' among {N + 1}: {panels!r}")
    expect(re.search(r"lab-verdict -> .*ACCEPTED", log), f"the GUI's lab did not accept {NAME}-triangle: {log[-600:]}")
    expect(shot.is_file() and shot.stat().st_size > 20000, f"no screenshot of panel {N} ({shot})")
    listing = run([build / "pathlab", "lab", "--list"], what="pathlab lab --list").stdout
    expect(re.search(rf"^{NAME}-triangle\s+T{N}\.1", listing, re.M), f"pathlab lab --list has no {NAME}-triangle")
    lab = run([build / "pathlab", "lab", f"{NAME}-triangle", "-o", work / "lab.png"], what=f"pathlab lab {NAME}-triangle")
    expect("ACCEPTED" in lab.stdout, f"the lab did not accept the reference's warp: {lab.stdout[-400:]}")
    views = run([build / "pathlab", "debug", "--list"], what="pathlab debug --list").stdout
    expect(f"--task {N} --view triangle" in views, f"pathlab debug --list has no task {N} view")
    run([build / "pathlab", "debug", "--task", str(N), "--view", "triangle", "-o", work / "view.png"],
        what=f"pathlab debug --task {N} --view triangle")
    expect((work / "view.png").is_file(), f"pathlab debug --task {N} drew nothing")


def writeup():
    """6. The write-up's page for the task: its heading, its figure, its question."""
    out = work / "writeup"
    run([sys.executable, copy / "tools/writeup", "--build", build, "--tasks", str(N), "--no-pdf", "--no-convergence",
         "--out", out], timeout=600, what=f"tools/writeup --tasks {N}")
    pages = sorted(out.glob("*.html")) if out.is_dir() else []
    page = pages[0].read_text() if pages else ""
    question = next(re.sub(r"\*\*[^*]*\*\*\s*", "", line[1:]).strip()  # its words, without the bold number
                    for line in (copy / f"writeup/{FOLDER}.md").read_text().splitlines() if line.startswith(">"))
    expect(f"Task {N}" in page and "<img" in page and question[:40] in page,
           f"the write-up's page has no task {N} section with its figure and question ({pages})")
    # The template has no image test: that is said, not flagged as a comparison missing (which
    # make-student-release's check of a finished release would count as a failure).
    expect("has no image tests" in page and "No comparison" not in page,
           f"the write-up's page flags task {N}'s suite, which has no image tests, as missing a comparison")


def declared_checks():
    """7. CI's budget, and the copy's checks of what every task declares."""
    template = json.loads((copy / f"tasks/{FOLDER}/task.json").read_text())["ci"]
    share = lambda tree, stage: int(subprocess.run([sys.executable, tree / "tools/pathlab_tasks.py", "ci-allowance",
                                                    stage], capture_output=True, text=True).stdout or -1)
    for stage, seconds in template.items():
        expect(share(copy, stage) == share(root, stage) + seconds,
               f"CI's stage {stage}: the tasks' share is {share(copy, stage)} s, not {share(root, stage)} + {seconds}")
    # (release-text's five subsets are the built-in tasks': task 13's release was checked above.)
    checks = ["task-manifests", "hint-catalogue", "mutants-generated", "ci-budget", "layers", "docs-paths",
              "docs-architecture"]
    tests = run(["ctest", "--test-dir", build, "-R", f"^({'|'.join(checks)})$", "--output-on-failure"],
                what="the copy's checks: " + ", ".join(checks))
    passed = set(re.findall(r"Test +#\d+: (\S+) \.+\s+Passed", tests.stdout))
    expect(passed == set(checks), f"the copy's checks {sorted(set(checks) - passed)} did not pass")


def main() -> int:
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    git = copy_repository()
    made = run([sys.executable, copy / "tools/new-task", str(N), NAME, "--title", "Texture mapping", "--label", LABEL],
               what=f"tools/new-task {N} {NAME}")
    if made.returncode == 0:
        for step in (second_graded_call, status_lists_only_the_task, build_and_test, grade, lambda: release_and_zip(git),
                     every_platform, gui_lab_and_views, writeup, declared_checks):
            step()
    # (The copy alone is removed when all passed: the panel's screenshot stays, for a person to look at.)
    return finish("new-task", failures, copy, keep, started,
                  f"task {N} built, graded, released, zipped, shown and budgeted with no file outside its folders")


if __name__ == "__main__":
    sys.exit(main())
