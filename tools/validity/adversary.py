"""The generated adversary: hostile candidates made mechanically from the
wire schema, each of which must score no more than the stub (docs/adversary.md).

  tools/adversary [--build-dir build] [--tasks 1,2] [--sample N] [--seed S|commit]
                  [--jobs J] [--grade N] [--list] [--report]

For each task, the adversary is the stub with a proxy in front of its server
(tools/validity/adversary_proxy.inc): the proxy rewrites the stub's answers by
one strategy, reading each answer through its call's wire schema
(`candidate-NN-name --wire-schema`, grader/wire/wire_schema.h). The
strategies, for every call and every field of its answer:
  leaf    each number set to NaN, ±inf, 0, -0, ±1e30, 1e-30, ±1 (floats);
          0, 1, the most, all ones, 2^40 (integers); 0, 1, 2 (booleans)
  flag    each optional flipped (present <-> absent), or given a flag byte of 2
  count   each list's count one more, one less, zero, or 2^40 with the
          elements kept (forged sizes)
  spike   noise concentrated in a list: 1e30 in its first element, in one
          element in 4 or in 16, or ±1e15 in 7 of every 16 (an image's
          variance in one pixel per block, one sample in a batch)
  echo    every float of the answer taken from the request's floats, or from
          the judge's last reply to an ask (answers replayed from the judge's
          own data)
  bytes   the answer a byte short or a byte long
Each strategy runs the test cases that make its call (learnt once per task
from the stub); a test case that passes survives (the stub passes none).
A survivor is a hole in a judge, or an equivalence reviewed in
grader/tests/adversary-equivalences.txt; any other makes the run fail.

--sample N draws N strategies per task (--seed commit: a new draw for every
commit, as CI runs it); without it every strategy runs (a few minutes per
task). --grade N also grades N drawn strategies with tools/grade in both
sandbox modes (as root), and one task file whose object carries sections a
toolchain acts on (GCC's LTO IR, a linker warning, an interpreter, init
functions, debug links): each must score what the stub scores, 0.
--report writes the table of docs/adversary.md."""
import argparse
import collections
import concurrent.futures
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from tools.validity import adversary_lab as adversary
from tools import pathlab_tasks
from tools.docs.sections import replace_section  # noqa: E402
from tools.validity.mutation_lab import read_reviewed  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
REVIEWED = ROOT / "grader" / "tests" / "adversary-equivalences.txt"
DOC = ROOT / "docs" / "adversary.md"


def drawn(items, count, seed):
    rng = pathlab_tasks.commit_random("adversary", ROOT) if seed == "commit" else random.Random(seed)
    return sorted(rng.sample(items, min(count, len(items))))


def judge_all(arena, tasks, sample, seed, jobs):
    """{task: [(strategy, description, passed test cases)]} for the strategies run."""
    runs = []
    for task in tasks:
        every = adversary.strategies(arena.schemas[task])
        chosen = drawn(every, sample, f"{seed}:{task}") if sample else every
        runs += [(task, strategy, description) for strategy, description in chosen]
    results = collections.defaultdict(list)
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(arena.judge, task, strategy, arena.tests_making(task, strategy)): (task, strategy, text)
                   for task, strategy, text in runs}
        for future in concurrent.futures.as_completed(futures):
            task, strategy, text = futures[future]
            results[task].append((strategy, text, future.result()))
    return results


def grade_through_sandboxes(arena, tasks, count, seed, work):
    """Problems: a drawn strategy, and the sections file, graded by tools/grade in bwrap and in uid."""
    problems = []
    cases = []
    for task in tasks:
        cases += [(task, s, d) for s, d in adversary.strategies(arena.schemas[task])]
    chosen = drawn(cases, count, f"{seed}:grade")
    task = drawn(sorted(tasks), 1, f"{seed}:sections")[0]
    sections = adversary.toolchain_sections_source(task, arena.build, work / "sections-ir")
    for mode in ("bwrap", "uid"):
        for task_, strategy, text, source in [(t, s, d, adversary.adversary_source(t, arena.schemas[t], s))
                                              for t, s, d in chosen] + [(task, "sections", "an object file "
                                                                         "with toolchain sections", sections)]:
            folder, file_name = pathlab_tasks.tasks()[task_]
            submission = work / f"grade-{mode}-{task_}-{abs(hash(strategy)) % 10**8}"
            submission.mkdir(parents=True)
            (submission / file_name).write_text(source)
            out = submission / "results.json"
            subprocess.run([sys.executable, str(ROOT / "tools/grade"), str(submission), "--tasks", str(task_),
                            "--out", str(out), "--build-dir", str(arena.build), "--sandbox", mode, "--timeout", "20"],
                           capture_output=True, text=True, timeout=1800)
            score = json.loads(out.read_text())["score"] if out.exists() else None
            print(f"  graded in {mode}: task {task_} {text}: {score if score is not None else 'no results.json'}")
            if score != 0:
                problems.append(f"task {task_}, {mode}: '{strategy}' ({text}) scored {score} through tools/grade")
    return problems


def write_report(results, seconds):
    rows = ["| task | calls | strategies | survivors |", "| --- | ---: | ---: | ---: |"]
    for task in sorted(results):
        calls = {s.split()[0] for s, _, _ in results[task]}
        rows.append(f"| {task} | {len(calls)} | {len(results[task])} | "
                    f"{sum(1 for _, _, passed in results[task] if passed)} |")
    total = sum(len(r) for r in results.values())
    body = "\n".join(rows) + (f"\n\n{total} strategies judged in {seconds / 60:.0f} min "
                              f"(`tools/adversary --report`, {time.strftime('%Y-%m-%d')}).")
    replace_section(DOC, "adversary-results", body)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build-dir", default=str(ROOT / "build"))
    parser.add_argument("--tasks", default=",".join(map(str, pathlab_tasks.tasks())))
    parser.add_argument("--sample", type=int, default=0)
    parser.add_argument("--seed", default="1")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--grade", type=int, default=0)
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--report", action="store_true")
    args = parser.parse_args()
    tasks = pathlab_tasks.parse_task_list(args.tasks, pathlab_tasks.tasks())
    build = Path(args.build_dir).resolve()
    work = Path(tempfile.mkdtemp(prefix="pathlab-adversary-"))
    start = time.time()
    arena = adversary.Arena(build, work)
    try:
        for task in tasks:
            arena.prepare(task)
            if args.list:
                for strategy, description in adversary.strategies(arena.schemas[task]):
                    print(f"task {task}  {strategy:45s} {description}")
        if args.list:
            return 0
        results = judge_all(arena, tasks, args.sample, args.seed, args.jobs)
        reviewed = read_reviewed(REVIEWED, item="strategy", verdicts=("equivalent",))
        problems = []
        for task in tasks:
            survivors = [(s, d, p) for s, d, p in results[task] if p]
            print(f"task {task}: {len(results[task])} strategies, {len(survivors)} survivors")
            for strategy, text, passed in survivors:
                key = f"{task}: {strategy}"
                if key not in reviewed:
                    problems.append(f"task {task}: '{strategy}' ({text}) passes {len(passed)} test cases the stub "
                                    f"fails: {'; '.join(passed)[:400]}")
        if args.grade:
            problems += grade_through_sandboxes(arena, tasks, args.grade, args.seed, work)
        if args.report:
            write_report(results, time.time() - start)
        for p in problems:
            print("SURVIVOR:", p)
        print(f"{sum(len(r) for r in results.values())} strategies in {time.time() - start:.0f} s; "
              f"{len(problems)} unreviewed survivors")
        return 1 if problems else 0
    finally:
        shutil.rmtree(work, ignore_errors=True)
