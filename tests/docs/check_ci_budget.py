#!/usr/bin/env python3
"""CI's time budget (docs/ci.md) is the one .ci/run enforces.

CI itself cannot run here as it runs on a fresh machine, so this checks what
can be checked: the stages .ci/run times (`stage NAME BASE COMMAND...`) are
docs/ci.md's budget table, row for row (name, base, command); a stage's
share is its base plus the seconds every task's tasks/NN-name/task.json
allows it under "ci" (each a stage .ci/run has); the shares add up within
the ceiling of 60 minutes (CI's own limit is 90 minutes; its machines have
run stages up to 1.6 times slower than the shares), with room for one more
task of the template's allowance (tools/task-template: a course's own task);
and .ci/run's stage function, run here on stand-in commands, passes a stage
within its share and fails one over twice it, with its time printed. The
target, 30 minutes for the seven core tasks and 2 more for each extension,
is printed against the shares: a run over it is a known weakness
(docs/ci.md), not hidden.

    check_ci_budget.py REPO              the check (and the shares printed)
    check_ci_budget.py REPO --self-test  the check must fail on altered copies
"""
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the repository: the import root (docs/architecture.md)
from tools import pathlab_tasks  # noqa: E402  (the task list: the tasks/NN-name folders)

CEILING = 60 * 60


def target(task_count):
    """30 minutes for the seven core tasks, 2 more for each extension."""
    return 30 * 60 + max(0, task_count - 7) * 120


def stages(ci_run):
    """[(name, base, command)] of .ci/run's stage lines (a command may continue on '\\' lines)."""
    text = ci_run.replace("\\\n", " ")
    return [(m.group(1), int(m.group(2)), " ".join(m.group(3).split()))
            for m in re.finditer(r"^stage +(\S+) +(\d+) +(.+)$", text, re.M)]


def table(doc):
    """[(name, base, command)] and the total row's base, from docs/ci.md's budget table."""
    block = re.search(r"<!-- ci-budget:begin -->(.*?)<!-- ci-budget:end -->", doc, re.S)
    rows, total = [], None
    for line in (block.group(1) if block else "").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 3 or not re.fullmatch(r"\d+ s", cells[1]):
            continue
        if cells[0] == "total":
            total = int(cells[1].split()[0])
            continue
        rows.append((cells[0].strip("`"), int(cells[1].split()[0]), " ".join(cells[2].strip("`").split())))
    return rows, total


def allowances(repo):
    """({task number: {stage: seconds}}, the template's {stage: seconds}) from the task.json files."""
    tasks = {n: pathlab_tasks.manifest(n, repo)["ci"] for n in pathlab_tasks.tasks(repo)}
    template = repo / "tools" / "task-template" / "tasks" / "task.json"
    return tasks, json.loads(template.read_text()).get("ci", {}) if template.is_file() else {}


def shares(ci_run, tasks):
    """{stage: base + the tasks' allowances}."""
    return {name: base + sum(t.get(name, 0) for t in tasks.values()) for name, base, _ in stages(ci_run)}


def stage_function(ci_run):
    return ci_run[ci_run.index("summary=()"):ci_run.index("\n}\n") + 3]


def run_stage(function, share, seconds, name="stand-in"):
    script = f"set -euo pipefail\n{function}\nstage {name} {share} sleep {seconds}\necho STAGE-PASSED\n"
    with tempfile.NamedTemporaryFile("w", suffix=".sh") as f:
        f.write(script)
        f.flush()
        # In the repository, as .ci/run runs: the stand-in stage adds the tasks' allowances (none) to its share.
        return subprocess.run(["bash", f.name], capture_output=True, text=True, timeout=60,
                              cwd=Path(__file__).resolve().parents[2])


def check(ci_run, doc, tasks, template, run_function=True):
    problems = []
    ci, (rows, total) = stages(ci_run), table(doc)
    if not ci:
        problems.append(".ci/run times no stage (stage NAME BASE COMMAND...)")
    if rows != ci:
        problems.append(f"docs/ci.md's budget table {[(n, b) for n, b, _ in rows]} is not .ci/run's stages "
                        f"{[(n, b) for n, b, _ in ci]} (name, base and command, in order)")
    if total != sum(b for _, b, _ in rows):
        problems.append(f"docs/ci.md's total {total} s is not the sum of its bases {sum(b for _, b, _ in rows)} s")
    names = {name for name, _, _ in ci}
    for n, allowance in sorted(tasks.items()) + [("the template", template)]:
        unknown = sorted(set(allowance) - names)
        if unknown:
            problems.append(f"task {n}'s task.json allows time in {unknown}, which .ci/run has no stage for")
    total_share = sum(shares(ci_run, tasks).values())
    if total_share > CEILING:
        problems.append(f"the shares add up to {total_share} s, over the ceiling of {CEILING} s")
    elif total_share + sum(template.values()) > CEILING:
        problems.append(f"the shares add up to {total_share} s: a task more of the template's allowance "
                        f"({sum(template.values())} s) would pass the ceiling of {CEILING} s")
    if run_function:
        function = stage_function(ci_run)
        within, over = run_stage(function, 1, 0), run_stage(function, 1, 3)  # 0 s of 1 s; 3 s of 1 s (> 2 s)
        if within.returncode != 0 or "STAGE-PASSED" not in within.stdout or \
                not re.search(r"[01] s of its share 1 s", within.stdout):
            problems.append(f"a stage within its share did not pass with its time printed: {within.stdout[-300:]}")
        if over.returncode == 0 or "STAGE-PASSED" in over.stdout or "over twice its share" not in over.stderr:
            problems.append(f"a stage over twice its share did not fail: {over.stdout[-300:]} {over.stderr[-300:]}")
        # A stage the tasks give time to (the test stage), on a base of 0 s: its share is theirs.
        # (The repository's own task.json files, as .ci/run reads them.)
        test = pathlab_tasks.ci_allowance("test")
        granted = run_stage(function, 0, 0, "test")
        if f"of its share {test} s" not in granted.stdout:
            problems.append(f"the test stage's share on a base of 0 s is not the tasks' {test} s: {granted.stdout[-300:]}")
    return problems


def main():
    repo = Path(sys.argv[1]).resolve()
    ci_run, doc = (repo / ".ci/run").read_text(), (repo / "docs/ci.md").read_text()
    tasks, template = allowances(repo)
    problems = check(ci_run, doc, tasks, template)
    if "--self-test" in sys.argv:
        if problems:
            print("\n".join(problems))
            return 1
        first = stages(ci_run)[0]
        a_task = {**tasks, 1: dict(tasks[1], nosuchstage=5)}
        altered = {
            "a base changed in .ci/run": (re.sub(r"^(stage +\S+ +)(\d+)", lambda m: m[1] + str(int(m[2]) + 1),
                                                 ci_run, count=1, flags=re.M), doc, tasks, template),
            "a stage dropped from .ci/run": (re.sub(r"^stage +asan .*$", "", ci_run, flags=re.M), doc, tasks, template),
            "a command changed in .ci/run": (ci_run.replace("tools/quickstart.sh test", "tools/quickstart.sh render"),
                                             doc, tasks, template),
            "the shares over the ceiling": (  # the first stage's base raised in .ci/run and in the table
                re.sub(rf"^(stage +{first[0]} +){first[1]}\b", rf"\g<1>{first[1] + CEILING}", ci_run, count=1, flags=re.M),
                re.sub(r"^\| total \| (\d+) s", lambda m: f"| total | {int(m[1]) + CEILING} s", doc.replace(
                    f"| `{first[0]}` | {first[1]} s |", f"| `{first[0]}` | {first[1] + CEILING} s |", 1), flags=re.M),
                tasks, template),
            "a task's allowances over the ceiling": (ci_run, doc, {**tasks, 1: {"test": CEILING}}, template),
            "no room for a task of the template's allowance": (ci_run, doc, tasks, {"test": CEILING}),
            "a task's allowance for a stage .ci/run has not": (ci_run, doc, a_task, template),
            "no failure over twice the share": (ci_run.replace("took > 2 * share", "took > 20 * share"), doc, tasks,
                                                template),
            "the tasks' allowances left out of the stage's share": (
                ci_run.replace('share=$((share + $(python3 tools/pathlab_tasks.py ci-allowance "$name")))', ":"),
                doc, tasks, template),
        }
        # The stage timer is run again only where it was altered (its runs sleep).
        missed = [name for name, (c, d, t, m) in altered.items()
                  if (c, d, t, m) == (ci_run, doc, tasks, template)
                  or not check(c, d, t, m, stage_function(c) != stage_function(ci_run))]
        for name in missed:
            print(f"self-test: not caught (or not applied): {name}")
        print(f"ci-budget self-test: {len(altered) - len(missed)} of {len(altered)} alterations caught")
        return 1 if missed else 0
    for p in problems:
        print(f"ci-budget: {p}")
    stage_shares = shares(ci_run, tasks)
    total = sum(stage_shares.values())
    goal = target(len(tasks))
    for name, base, _ in stages(ci_run):
        print(f"ci-budget: {name:<10} base {base:>5} s + the {len(tasks)} tasks' {stage_shares[name] - base:>4} s "
              f"= share {stage_shares[name]:>5} s")
    room = (CEILING - total) // max(1, sum(template.values()))
    against = f"within the target of {goal} s" if total <= goal else \
        f"OVER the target of {goal} s by {total - goal} s (docs/ci.md)"
    print(f"ci-budget: {len(stage_shares)} stages, {total} s of shares, {against}, ceiling {CEILING} s "
          f"(room for {room} more tasks of the template's {sum(template.values())} s): "
          f"{'ok' if not problems else f'{len(problems)} problem(s)'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
