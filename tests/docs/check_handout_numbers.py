#!/usr/bin/env python3
"""Every number and pixel a handout quotes from the program's output is
re-measured here, so the handouts cannot drift from what the build prints.
Each check finds its sentence in the handout (a reworded sentence fails
loudly: update the pattern with it), runs the command the handout names, and
compares.

usage: check_handout_numbers.py REPO_DIR PATHLAB_BINARY"""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

root, pathlab = Path(sys.argv[1]), sys.argv[2]
failures = []
NUMBER = r"(\d+(?:\.\d+)?)"  # a number, without a sentence's full stop


def quoted(handout: str, pattern: str):
    text = re.sub(r"\s+", " ", (root / handout).read_text())
    m = re.search(pattern, text)
    if not m:
        failures.append(f"{handout}: the sentence /{pattern}/ is gone (reworded? update this check)")
    return m


def debug(*args) -> str:
    with tempfile.TemporaryDirectory() as tmp:
        p = subprocess.run([pathlab, "debug", *args, "-o", f"{tmp}/view.png"], capture_output=True, text=True,
                           cwd=root, timeout=300)
    if p.returncode != 0:
        failures.append(f"pathlab debug {' '.join(args)} exited {p.returncode}: {p.stderr.strip()[:300]}")
    return p.stdout + p.stderr


def near(what: str, quoted_value: float, measured: float, tolerance: float):
    ok = abs(measured - quoted_value) <= tolerance * abs(quoted_value)
    print(f"{'ok  ' if ok else 'FAIL'} {what}: handout {quoted_value:g}, measured {measured:g}")
    if not ok:
        failures.append(f"{what}: the handout says {quoted_value:g}, the build prints {measured:g}")


# Task 4: the shadow-rays pixel of the picture, and its caption's counts.
command = quoted("tasks/04-direct-lighting/README.md", r"--view shadow-rays --pixel (\d+) (\d+)")
caption = quoted("tasks/04-direct-lighting/README.md", r"(\d+) reach the light, (\d+) are blocked")
if command and caption:
    out = debug("--task", "4", "--view", "shadow-rays", "--pixel", command.group(1), command.group(2))
    blocked, samples = out.count("BLOCKED"), out.count("light sample")
    near(f"task 4 pixel ({command.group(1)}, {command.group(2)}) rays blocked", float(caption.group(2)), blocked, 0)
    near("task 4 pixel rays reaching the light", float(caption.group(1)), samples - blocked, 0)

# Task 3: the heat map's numbers on media/scenes/scan.json.
out = debug("--task", "3", "--view", "heatmap", "media/scenes/scan.json")
stats = re.search(r"per ray: ([\d.]+) box tests .*?, ([\d.]+) primitive tests", out)
tree = re.search(r"BVH: (\d+) nodes, \d+ leaves, depth (\d+), SAH cost ([\d.]+)", out)
if not stats or not tree:
    failures.append("pathlab debug --task 3 --view heatmap no longer prints its statistics")
else:
    intro = quoted("tasks/03-bvh/README.md", r"does about ([\d.]+) box tests and ([\d.]+) triangle tests")
    legend = quoted("tasks/03-bvh/README.md", r"per ray — about ([\d.]+) for the scan.json view")
    shape = quoted("tasks/03-bvh/README.md", r"about (\d+)k nodes, depth about (\d+), .*? SAH cost about (\d+(?:\.\d+)?)")
    if intro:
        near("task 3 box tests per ray (intro)", float(intro.group(1)), float(stats.group(1)), 0.1)
        near("task 3 triangle tests per ray (intro)", float(intro.group(2)), float(stats.group(2)), 0.15)
    if legend:
        near("task 3 box tests per ray (legend)", float(legend.group(1)), float(stats.group(1)), 0.1)
    score = quoted("tasks/03-bvh/README.md", r"10 × triangle tests per ray, lower is better — about ([\d.]+) for the scan")
    measured_score = re.search(r"walked by the framework.*?\n\s*([\d.]+) = ", out)
    if score and measured_score:
        near("task 3 tree score (nodes + 10 x tests)", float(score.group(1)), float(measured_score.group(1)), 0.1)
    elif score:
        failures.append("pathlab debug --task 3 --view heatmap no longer prints the tree's score")
    if shape:
        near("task 3 nodes (thousands)", float(shape.group(1)), int(tree.group(1)) / 1000.0, 0.1)
        near("task 3 depth", float(shape.group(2)), float(tree.group(2)), 0.15)
        near("task 3 SAH cost", float(shape.group(3)), float(tree.group(3)), 0.1)

# Task 5: the mean radiance after each bounce of the default scene.
means = quoted("tasks/05-path-tracing/README.md", r"for the default scene about " + ", ".join([NUMBER] * 5))
if means:
    out = debug("--task", "5", "--view", "bounces")
    printed = re.search(r"mean radiance per bounce: 0: ([\d.]+) 1: ([\d.]+) 2: ([\d.]+) 3: ([\d.]+) 4: ([\d.]+)", out)
    if not printed:
        failures.append("pathlab debug --task 5 --view bounces no longer prints the mean per bounce")
    else:
        for k in range(5):
            near(f"task 5 mean after {k} bounces", float(means.group(k + 1)), float(printed.group(k + 1)), 0.1)

for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
