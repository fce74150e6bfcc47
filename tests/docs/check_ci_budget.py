#!/usr/bin/env python3
"""CI's time budget (docs/ci.md) is the one .ci/run enforces.

CI itself cannot run here as it runs on a fresh machine, so this checks what
can be checked: the stages .ci/run times (`stage NAME SHARE COMMAND...`)
are docs/ci.md's budget table, row for row (name, share, command); the
shares add up to the table's total, within the ceiling of 60 minutes (CI's
own limit is 90 minutes; its machines have run stages up to 1.6 times
slower than the shares), today and with the extension tasks still to come (the table's
"per new task" column: tasks 8-12); and .ci/run's stage function, run here
on stand-in commands, passes a stage within its share and fails one over
twice it, with its time printed. The target, 30 minutes for
the seven core tasks and 40 with the five extensions, is printed against
the shares: a run over it is a known weakness (docs/ci.md), not hidden.

    check_ci_budget.py REPO              the check
    check_ci_budget.py REPO --self-test  the check must fail on altered copies
"""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import pathlab_tasks  # noqa: E402  (the task list: the tasks/NN-name folders)

# The target: 30 minutes for the seven core tasks, 40 with the five
# extensions (tasks 8-12), 2 minutes each. The ceiling the shares must keep:
# 60 minutes, so that a run on a machine one and a half times slower than
# the shares' still ends within CI's 90. (A stage fails at twice its share.)
EXTENSIONS = max(0, len(pathlab_tasks.tasks()) - 7)
TARGET, NEW_TASKS = 30 * 60 + EXTENSIONS * 120, 5 - EXTENSIONS
CEILING = 60 * 60


def stages(ci_run):
    """[(name, share, command)] of .ci/run's stage lines (a command may continue on '\\' lines)."""
    text = ci_run.replace("\\\n", " ")
    return [(m.group(1), int(m.group(2)), " ".join(m.group(3).split()))
            for m in re.finditer(r"^stage +(\S+) +(\d+) +(.+)$", text, re.M)]


def table(doc):
    """{name: (share, command, per new task)} and the total row, from docs/ci.md's budget table."""
    block = re.search(r"<!-- ci-budget:begin -->(.*?)<!-- ci-budget:end -->", doc, re.S)
    rows, total = [], None
    for line in (block.group(1) if block else "").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 4 or not re.fullmatch(r"\d+ s", cells[1]):
            continue
        share, per_task = int(cells[1].split()[0]), cells[3]
        if cells[0] == "total":
            total = share
            continue
        name, command = cells[0].strip("`"), cells[2].strip("`")
        rows.append((name, share, " ".join(command.split()), int(per_task.split()[0]) if per_task[:1].isdigit() else 0))
    return rows, total


def stage_function(ci_run):
    return ci_run[ci_run.index("summary=()"):ci_run.index("\n}\n") + 3]


def run_stage(function, share, seconds):
    script = f"set -euo pipefail\n{function}\nstage stand-in {share} sleep {seconds}\necho STAGE-PASSED\n"
    with tempfile.NamedTemporaryFile("w", suffix=".sh") as f:
        f.write(script)
        f.flush()
        return subprocess.run(["bash", f.name], capture_output=True, text=True, timeout=60)


def check(ci_run, doc, run_function=True):
    problems = []
    ci, (rows, total) = stages(ci_run), table(doc)
    if not ci:
        problems.append(".ci/run times no stage (stage NAME SHARE COMMAND...)")
    if [(n, s, c) for n, s, c, _ in rows] != ci:
        problems.append(f"docs/ci.md's budget table {[(n, s) for n, s, _, _ in rows]} is not .ci/run's stages "
                        f"{[(n, s) for n, s, _ in ci]} (name, share and command, in order)")
    shares = sum(s for _, s, _ in ci)
    if total != sum(s for _, s, _, _ in rows):
        problems.append(f"docs/ci.md's total {total} s is not the sum of its shares {sum(s for _, s, _, _ in rows)} s")
    if shares > CEILING:
        problems.append(f"the shares add up to {shares} s, over the ceiling of {CEILING} s")
    grown = shares + NEW_TASKS * sum(p for _, _, _, p in rows)
    if grown > CEILING:
        problems.append(f"with {NEW_TASKS} new tasks the shares would add up to {grown} s, over the ceiling of "
                        f"{CEILING} s")
    if run_function:
        function = stage_function(ci_run)
        within, over = run_stage(function, 1, 0), run_stage(function, 1, 3)  # 0 s of 1 s; 3 s of 1 s (> 2 s)
        if within.returncode != 0 or "STAGE-PASSED" not in within.stdout or \
                not re.search(r"[01] s of its share 1 s", within.stdout):
            problems.append(f"a stage within its share did not pass with its time printed: {within.stdout[-300:]}")
        if over.returncode == 0 or "STAGE-PASSED" in over.stdout or "over twice its share" not in over.stderr:
            problems.append(f"a stage over twice its share did not fail: {over.stdout[-300:]} {over.stderr[-300:]}")
    return problems


def main():
    repo = Path(sys.argv[1]).resolve()
    ci_run, doc = (repo / ".ci/run").read_text(), (repo / "docs/ci.md").read_text()
    problems = check(ci_run, doc)
    if "--self-test" in sys.argv:
        if problems:
            print("\n".join(problems))
            return 1
        first = stages(ci_run)[0]
        altered = {
            "a share changed in .ci/run": (re.sub(r"^(stage +\S+ +)(\d+)", lambda m: m[1] + str(int(m[2]) + 1),
                                                  ci_run, count=1, flags=re.M), doc),
            "a stage dropped from .ci/run": (re.sub(r"^stage +asan .*$", "", ci_run, flags=re.M), doc),
            "a command changed in .ci/run": (ci_run.replace("tools/quickstart.sh test", "tools/quickstart.sh render"), doc),
            "the shares over the ceiling": (  # the first stage's share raised in .ci/run and in the table
                re.sub(rf"^(stage +{first[0]} +){first[1]}\b", rf"\g<1>{first[1] + CEILING}", ci_run, count=1, flags=re.M),
                re.sub(r"^\| total \| (\d+) s", lambda m: f"| total | {int(m[1]) + CEILING} s", doc.replace(
                    f"| `{first[0]}` | {first[1]} s |", f"| `{first[0]}` | {first[1] + CEILING} s |", 1), flags=re.M)),
            # (Only while extension tasks are still to come: with all five in, the allowance counts for nothing.)
            **({"the per-task allowance over the ceiling": (ci_run, re.sub(
                r"(\| `bash tools/quickstart.sh test` \| )\d+", r"\g<1>9999", doc))} if NEW_TASKS > 0 else {}),
            "no failure over twice the share": (ci_run.replace("took > 2 * share", "took > 20 * share"), doc),
        }
        # The stage timer is run again only where it was altered (its runs sleep).
        missed = [name for name, (c, d) in altered.items()
                  if (c, d) == (ci_run, doc) or not check(c, d, stage_function(c) != stage_function(ci_run))]
        for name in missed:
            print(f"self-test: not caught (or not applied): {name}")
        print(f"ci-budget self-test: {len(altered) - len(missed)} of {len(altered)} alterations caught")
        return 1 if missed else 0
    for p in problems:
        print(f"ci-budget: {p}")
    ci = stages(ci_run)
    shares = sum(s for _, s, _ in ci)
    target = f"within the target of {TARGET} s" if shares <= TARGET else \
        f"OVER the target of {TARGET} s by {shares - TARGET} s (docs/ci.md)"
    print(f"ci-budget: {len(ci)} stages, {shares} s of shares, {target}, ceiling {CEILING} s: "
          f"{'ok' if not problems else f'{len(problems)} problem(s)'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
