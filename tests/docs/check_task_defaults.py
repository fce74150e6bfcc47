#!/usr/bin/env python3
"""Task 11's settings have one home, AdaptiveSettings and the views'
constants in framework/tasks/adaptive_sampling.h, and every place that
quotes or uses them agrees with it: the handout's "(default N)" for
--min-spp and --batch and its sentence on the views, the command line's
help text, and the debugger views, which must take the header's values
(no number of their own). In a student release that does not hand task 11
out, its handout is cut to its recipe: only the program's text is checked.

usage: check_task_defaults.py REPOSITORY"""
import re
import sys
from pathlib import Path


def main() -> int:
    root = Path(sys.argv[1])
    sys.path.insert(0, str(root))  # the repository: the import root (docs/architecture.md)
    from tools import pathlab_tasks
    handed_out = 11 in pathlab_tasks.handed_out(root)
    header = (root / "framework/tasks/adaptive_sampling.h").read_text()
    struct = re.search(r"struct AdaptiveSettings \{(.*?)\};", header, re.S).group(1)
    defaults = {name: value for _, name, value in re.findall(r"(double|uint32_t) (\w+) = ([\d.]+);", struct)}
    found = re.search(r"kAdaptiveViewTolerance = ([\d.]+);", header), re.search(r"kAdaptiveViewMaxSpp = (\d+);", header)
    if not all(found):
        print("task-defaults: adaptive_sampling.h defines no kAdaptiveViewTolerance and kAdaptiveViewMaxSpp")
        return 1
    view_tolerance, view_max = found[0].group(1), found[1].group(1)
    handout = " ".join((root / "tasks/11-adaptive-sampling/README.md").read_text().split())
    cli = (root / "apps/pathlab/cli.cpp").read_text()
    views = (root / "tasks/11-adaptive-sampling/debugger.cpp").read_text()
    problems = []
    for flag, name in (("--min-spp", "minSpp"), ("--batch", "batch")):
        if handed_out and f"`{flag}` (default {defaults[name]})" not in handout:
            problems.append(f"the handout does not say {flag} (default {defaults[name]})")
        if not re.search(rf'"{flag}".*\(default {defaults[name]}\b', cli):
            problems.append(f"pathlab's help does not say {flag} (default {defaults[name]})")
    if handed_out and f"tolerance {view_tolerance} and a maximum of {view_max}" not in handout:
        problems.append(f"the handout does not give the views' tolerance {view_tolerance} and maximum {view_max}")
    body = re.search(r"AdaptiveSettings viewSettings\(\) \{(.*?)\n\}", views, re.S)
    if not body or re.search(r"=\s*[\d.]+", body.group(1)) or "kAdaptiveViewTolerance" not in body.group(1):
        problems.append("the debugger's viewSettings() must take the header's values, with no number of its own")
    if re.search(r"std::min\((32|64), most\)", cli):
        problems.append("pathlab's --adaptive spells a default as a number instead of reading AdaptiveSettings")
    for p in problems:
        print("task-defaults:", p)
    print(f"task 11's defaults {defaults}, views {view_tolerance}/{view_max}: {len(problems)} problems"
          + ("" if handed_out else " (not handed out: its handout not checked)"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
