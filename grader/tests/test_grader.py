"""The grader under fire: a submission whose task 2 segfaults, whose task 3
never terminates, whose task 5 returns NaN and whose task 1 prints megabytes
must get a results.json where every other test is scored normally. Task 3's
tests that build a tree time out one by one (10 s each) until the task's
budget (40 s here) is used up, and the rest are reported as not run. Then a
judge past its own memory limit (PATHLAB_JUDGE_MEMORY at 24 MB, which task
1's image test needs more than, its other tests not) fails that test alone,
and says so.

usage: test_grader.py REPO_ROOT WORK_DIR GRADE_BUILD_DIR"""
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

root, build, grade_build = Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
submission = build / "broken-submission"
shutil.rmtree(submission, ignore_errors=True)
submission.mkdir(parents=True)
for source in (root / "solutions").glob("*/*.cpp"):
    shutil.copy(source, submission / source.name)


def mutate(name, old, new):
    path = submission / name
    text = path.read_text()
    assert old in text, (name, old)
    path.write_text(text.replace(old, new, 1))


# Task 1: correct, but floods stdout with 8 MB the first time it runs.
mutate("camera_rays.cpp", "Point2 pixelSamplePosition(IVec2 pixel, Vec2 u) { return Point2(pixel) + u; }",
       "Point2 pixelSamplePosition(IVec2 pixel, Vec2 u) {\n"
       "  static bool once = [] { for (int i = 0; i < 100000; ++i) std::puts(std::string(80, 'x').c_str()); return true; }();\n"
       "  (void)once;\n  return Point2(pixel) + u;\n}")
mutate("camera_rays.cpp", "#include <cmath>", "#include <cmath>\n#include <cstdio>\n#include <string>")
# Task 2: a segfault in the triangle test.
mutate("intersection.cpp", "  // Translate the vertices so the ray starts at the origin.",
       "  *static_cast<volatile int*>(nullptr) = 1;  // crash\n  // Translate the vertices so the ray starts at the origin.")
# Task 3: an endless loop in the build.
mutate("bvh.cpp", "Bvh buildBvh(std::span<const Aabb> primitiveBounds) {\n  Bvh bvh;",
       "Bvh buildBvh(std::span<const Aabb> primitiveBounds) {\n  Bvh bvh;\n  for (volatile bool forever = true; forever;) {\n  }")
# Task 5: NaN radiance.
mutate("path_tracing.cpp", "  return radiance;\n}", "  return radiance * std::nanf(\"\");\n}")

out = build / "broken-results.json"
grade = subprocess.run([sys.executable, str(root / "tools" / "grade"), str(submission), "--out", str(out),
                        "--build-dir", str(grade_build), "--timeout", "10", "--task-budget", "40"],
                       capture_output=True, text=True, timeout=1500)
print(grade.stdout[-2000:], grade.stderr[-2000:])
report = json.loads(out.read_text())
failures = []
by_task = {}
for test in report["tests"]:
    task = int(re.match(r"Task (\d+):", test["name"]).group(1))
    by_task.setdefault(task, []).append(test)
for task in (1, 4, 6, 7):  # unharmed: full marks despite the broken tasks around them
    lost = [t["name"] for t in by_task[task] if t["score"] != t["max_score"]]
    if lost:
        failures.append(f"task {task} lost points it should not: {lost[:2]}")


def expect(task, broken_prefixes, symptom, or_else=None):
    # Tests that reach the broken step lose their points and say why (the
    # symptom; or_else: what a test past the task's budget says instead, as
    # long as the first broken test shows the symptom); the task's other
    # steps (in their own processes) keep theirs.
    broken = [t for t in by_task[task] if any(t["name"].startswith(f"Task {task}: {p}") for p in broken_prefixes)]
    broken_prefix = "/".join(broken_prefixes)
    intact = [t for t in by_task[task] if t not in broken]
    said = lambda t: not symptom or symptom in t["output"] or (or_else and or_else in t["output"])
    if not broken or any(t["score"] > 0 or not said(t) for t in broken) or \
            (symptom and symptom not in broken[0]["output"]):
        failures.append(f"task {task}: the {broken_prefix} tests should score 0 and report {symptom or 'the failure'}")
    if not intact or any(t["score"] != t["max_score"] for t in intact):
        failures.append(f"task {task}: tests away from the broken step should keep their points")


expect(2, ["T2.1", "T2.3 image"], "SIGSEGV")      # the triangle test crashes (the image has triangles); spheres pass
expect(3, ["T3.2", "T3.3", "T3.4"], "timed out", "time budget of 40 s was used up")  # the build never ends; the slab test still passes
expect(5, ["T5.2"], "")                           # NaN radiance; the sampler still passes
if out.stat().st_size > 1_000_000:
    failures.append(f"results.json is {out.stat().st_size} bytes: output was not clipped")

limited = build / "judge-memory-results.json"
subprocess.run([sys.executable, str(root / "tools" / "grade"), str(root / "solutions"), "--tasks", "1", "--out",
                str(limited), "--build-dir", str(grade_build)], capture_output=True, text=True, timeout=600,
               env={**os.environ, "PATHLAB_JUDGE_MEMORY": str(24 << 20)})
tests = json.loads(limited.read_text())["tests"]
stopped = [t for t in tests if "the judge needed more than its 24 MB" in t["output"]]
if not stopped or any(t["score"] != 0 or "image" not in t["name"] for t in stopped) or \
        any(t["score"] != t["max_score"] for t in tests if "image" not in t["name"]):
    failures.append("with PATHLAB_JUDGE_MEMORY at 24 MB, task 1's image test should fail, saying the judge was "
                    f"stopped, and its other tests keep their points: {[(t['name'], t['score']) for t in tests]}")
checks = 11
for f in failures:
    print("FAIL:", f)
print(f"{checks - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
