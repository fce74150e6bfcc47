"""Mutation testing of the task suites: generates mutants of each reference
solution mechanically, builds each as a candidate (that file for its task,
the reference elsewhere) and judges it with its task's suite.

  tools/mutate [--build-dir build] [--tasks 1,2] [--sample N] [--seed S]
               [--jobs J] [--list] [--show ID] [--report] [--keep-going]
               [--conventions K] [--conventions-only]

One mutant per site and operator (tools/mutate --list prints them all):
  relational  <  <=  >  >=  ==  !=   each to its boundary twin (< to <=, ...)
  logical     &&  ||                 swapped
  arithmetic  + - * / += -= *= /= ++ --   to their opposite
  sign        a unary minus removed
  minmax      min and max swapped (std::, glm::, fmin)
  abs         abs / fabs removed
  constant    integers +-1; floats 0 -> 1e-6, tiny -> 0, 1 -> 1 +- 0.01, x2, /2
              (not the operand of == or !=: that tests another point of measure zero)
  negate      the condition of an if, a while or a ?: negated
  delete      one statement, break, continue or conditional return deleted
  swap-args   two neighbouring arguments of a call or a braced initialiser swapped
  precision   float <-> double
and higher-order ones, each the slip of a whole formula:
  call        a call to another function of the same signature the file can
              see: a maths neighbour (sin <-> cos, floor <-> ceil, dot ->
              distance, ...) or a function the task's file or header declares
  operand     a variable read replaced by another of its type in scope
  component   .x -> .y -> .z -> .x where a vector's component is read
  refine      a refinement dropped: normalize(x), clamp(x, a, b), max(C, x)
              and min(C, x) with a constant C, each to x

A mutant that does not compile is discarded; one that makes a test fail or
runs past its time limit (--timeout-factor, 10: ten times the reference
suite's time, at least 60 s) is killed (the judge stops at the first failing
test); one that passes every test survived. Each survivor must appear in
tests/mutants/survivors.txt, the reviewed list, with the reason it is not a
mistake the suite should catch (equivalent: the same observable behaviour for
every input the framework can pass; or a correct variant the handout allows).
Any other survivor makes the run fail. Verdicts are cached in BUILD/mutate-cache
by the hash of the mutant's source, the judge and the candidate's other parts,
so a second run only judges what changed.

--sample N judges N compiling mutants per task, drawn with --seed (CI:
--seed commit, a new draw for every commit);
--report writes the mutation table of docs/mutation-testing.md (a full run).

Convention alternates (below, "Convention alternates") are the other side:
edits that keep the reference correct, each of which must get full marks.
--conventions K also judges K of them per task; --conventions-only judges
them all (or K) and no mutant, and with --report writes their table;
--conventions-only --list prints them."""
import argparse
import concurrent.futures
import os
import random
import shutil
import subprocess
import sys
import time
from pathlib import Path

from tools import pathlab_tasks  # noqa: E402  (the task list: the tasks/NN-name folders)
from tools.validity.conventions import generate_conventions  # noqa: E402
from tools.validity.mutants import Mutant, generate  # noqa: E402
from tools.validity.mutation_lab import REVIEWED, ROOT, Lab, read_reviewed  # noqa: E402

NOT_CORRECT = ROOT / "tests" / "mutants" / "conventions.txt"  # convention alternates that are not correct after all


# ---------------------------------------------------------------------------

def arguments():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build-dir", default=str(ROOT / "build"))
    parser.add_argument("--tasks", default=",".join(str(n) for n in pathlab_tasks.tasks(ROOT)))
    parser.add_argument("--sample", type=int, default=0, help="judge N compiling mutants per task (0: all)")
    parser.add_argument("--seed", default="1", help="an integer, or 'commit': drawn from the checked-out commit")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--timeout-factor", type=float, default=10.0, metavar="F",
                        help="a judge running F times the reference suite's time (at least F x 6 s) is stopped: "
                             "killed (default 10; CI's sample: 5)")
    parser.add_argument("--list", action="store_true", help="print the mutants and stop")
    parser.add_argument("--show", metavar="ID", help="print one mutant's diff and stop")
    parser.add_argument("--report", action="store_true", help="write the table in docs/mutation-testing.md")
    parser.add_argument("--conventions", type=int, default=0, metavar="K",
                        help="also judge K convention alternates per task (drawn with --seed)")
    parser.add_argument("--conventions-only", action="store_true",
                        help="judge the convention alternates (every one, or K with --conventions) and no mutant")
    parser.add_argument("--try", dest="try_file", metavar="FILE",
                        help="judge one hand-made variant of the task file (one task in --tasks) and stop")
    return parser.parse_args()


def main() -> int:
    args = arguments()
    tasks = pathlab_tasks.tasks(ROOT)
    chosen = [int(n) for n in args.tasks.split(",")]
    if args.try_file:
        return try_variant(args, tasks, chosen)
    reviewed = read_reviewed()  # read first: a malformed list fails before hours of judging
    mutants = {n: variants_of(n, tasks, args.conventions_only) for n in chosen}
    if args.list or args.show:
        return list_variants(mutants, chosen, args)
    args.seed = seed_of(args.seed)
    if args.sample:
        print(f"tools/mutate: {args.sample} mutants per task, seed {args.seed}", file=sys.stderr)
    lab = Lab(Path(args.build_dir).resolve(), args.timeout_factor)
    lab.prepare(chosen)
    # The mutants and the alternates of every task share one pool of jobs:
    # a task's last slow judge never holds the run up alone.
    draws = {}
    if args.conventions or args.conventions_only:
        alternates = {n: variants_of(n, tasks, conventions=True) for n in chosen}
        wanted = 0 if args.conventions_only and not args.conventions else args.conventions
        if wanted:
            print(f"tools/mutate: {wanted} convention alternates per task, seed {args.seed}", file=sys.stderr)
        # First: an alternate passes its whole suite, the longest judges.
        draws.update({("alternate", n): drawn(alternates[n], wanted, args.seed + 7, n) for n in reversed(chosen)})
    if not args.conventions_only:
        draws.update({("mutant", n): drawn(mutants[n], args.sample, args.seed, n) for n in reversed(chosen)})
    started = time.time()
    judged = judge_all(lab, draws, args.jobs)
    elapsed = time.time() - started
    conventions_failed = False
    if args.conventions or args.conventions_only:
        conventions_failed = report_conventions({n: judged[("alternate", n)] for n in chosen}, tasks, elapsed,
                                                args.jobs, args.report and args.conventions_only)
    shutil.rmtree(lab.work, ignore_errors=True)
    if args.conventions_only:
        return 1 if conventions_failed else 0
    results = {n: judged[("mutant", n)] for n in chosen if ("mutant", n) in judged}
    unreviewed = report_mutants(results, reviewed, chosen, tasks, elapsed, args)
    return 1 if unreviewed or conventions_failed else 0


def try_variant(args, tasks, chosen) -> int:
    """--try FILE: one hand-made variant of the task file judged, its verdict printed."""
    if len(chosen) != 1:
        raise SystemExit("tools/mutate --try needs exactly one task in --tasks")
    lab = Lab(Path(args.build_dir).resolve(), args.timeout_factor)
    lab.prepare(chosen)
    variant = Mutant(chosen[0], tasks[chosen[0]][0], "by hand", 0, 0, "", 0, "", args.try_file,
                     source=Path(args.try_file).read_text())
    result = lab.judge(variant)
    shutil.rmtree(lab.work, ignore_errors=True)
    print(result.get("output", ""))
    print(f"{result['verdict']} {result.get('test', '')} ({result['seconds']} s)".rstrip())
    return 0


def variants_of(n: int, tasks, conventions: bool) -> list:
    """Task n's mutants, or its convention alternates, generated from the reference."""
    folder, file_name = tasks[n]
    source = (ROOT / "solutions" / folder / file_name).read_text()
    if conventions:
        return generate_conventions(n, folder, source)
    header = ROOT / "framework" / "tasks" / Path(file_name).with_suffix(".h")
    return generate(n, folder, source, header.read_text() if header.exists() else "")


def list_variants(mutants, chosen, args) -> int:
    """--list, --show ID: the variants (or one, with its edited line), nothing judged."""
    for n in chosen:
        for m in mutants[n]:
            if args.show and m.id != args.show:
                continue
            print(f"{m.id}  {m.operator:10} line {m.line:3}: {m.description}\n      {m.site}\n  "
                  f"{'alternate' if args.conventions_only else 'mutant'}: {m.key}")
            if args.show:
                print("  ->  " + m.source.splitlines()[m.line - 1].strip())
    print(f"{sum(len(v) for v in mutants.values())} {'alternates' if args.conventions_only else 'mutants'}",
          file=sys.stderr)
    return 0


def seed_of(text: str) -> int:
    """--seed: an integer, or "commit" (the checked-out commit's first 8 hex digits; 1 outside git)."""
    if text == "commit":
        head = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "HEAD"], capture_output=True, text=True)
        return int(head.stdout.strip()[:8], 16) if head.returncode == 0 else 1
    return int(text)


def tally(results, chosen, reviewed):
    """Per task, its mutants' counts by verdict (a reviewed survivor as its review says), and the unreviewed
    survivors, the timeouts and the reviewed entries used."""
    rows, unreviewed, timeouts, used = [], [], [], set()
    for n in chosen:
        counts = dict(generated=len(results[n]), compile=0, killed=0, timeout=0, equivalent=0, correct=0, survived=0)
        for m, r in results[n]:
            verdict = r["verdict"]
            if verdict == "compile-error":
                counts["compile"] += 1
            elif verdict in ("killed", "timeout"):
                counts[verdict] += 1
                if verdict == "timeout":
                    timeouts.append(m)
                if m.key in reviewed:
                    print(f"note: {m.id} is killed now; its entry in {REVIEWED.name} can go: {m.key}")
            elif m.key in reviewed:
                counts[reviewed[m.key][0]] += 1
                used.add(m.key)
            else:
                counts["survived"] += 1
                unreviewed.append(m)
        judged = counts["killed"] + counts["timeout"] + counts["survived"]
        counts["score"] = 100.0 * (counts["killed"] + counts["timeout"]) / judged if judged else 100.0
        rows.append((n, counts))
    return rows, unreviewed, timeouts, used


def report_mutants(results, reviewed, chosen, tasks, elapsed, args) -> list:
    """The table, the timeouts and the unreviewed survivors printed (and written, --report); returns the
    unreviewed survivors."""
    rows, unreviewed, timeouts, used = tally(results, chosen, reviewed)
    print(f"{'task':16} {'mutants':>7} {'no build':>8} {'killed':>6} {'timeout':>7} {'equiv.':>6} {'correct':>7} "
          f"{'survived':>8} {'killed %':>8}")
    for n, c in rows:
        print(f"{tasks[n][0]:16} {c['generated']:7} {c['compile']:8} {c['killed']:6} {c['timeout']:7} "
              f"{c['equivalent']:6} {c['correct']:7} {c['survived']:8} {c['score']:7.1f}%")
    print(f"{elapsed:.0f} s with {args.jobs} jobs")
    # A timeout counts as killed, but a slow correct variant would pass on a
    # faster machine: each is named, to be looked at (docs/mutation-testing.md).
    for m in timeouts:
        print(f"timeout {m.id} ({m.operator}), {tasks[m.task][0]} line {m.line}: {m.description}\n"
              f"  now: {m.source.splitlines()[m.line - 1].strip()}")
    for m in unreviewed:
        print(f"\nSURVIVED {m.id} ({m.operator}), {tasks[m.task][0]} line {m.line}: {m.description}\n"
              f"  was: {m.site}\n  now: {m.source.splitlines()[m.line - 1].strip()}\nmutant: {m.key}")
    if not args.sample:
        stale = [k for k in reviewed if k.split(": ", 1)[0] in {tasks[n][0] for n in chosen} and k not in used]
        for k in stale:
            print(f"note: no surviving mutant matches this entry of {REVIEWED.name} (killed, or the code changed): {k}")
    if args.report:
        write_report(rows, reviewed, used, elapsed, args.jobs, tasks)
    return unreviewed


def drawn(candidates, sample, seed, task):
    """(candidates in the order to judge them, how many that compile are wanted): every one, or `sample`
    drawn with seed."""
    order = list(candidates)
    if sample:
        random.Random(seed * 1000 + task).shuffle(order)
    return order, sample or len(order)


def judge_all(lab, draws, jobs):
    """{key: [(candidate, verdict)]} for draws {key: (order, wanted)}: the first `wanted` candidates of each
    order that compile (a candidate that does not compile is replaced by the next), judged `jobs` at a time
    across every draw."""
    results = {key: [] for key in draws}
    queues = {key: iter(order) for key, (order, _) in draws.items()}
    built = dict.fromkeys(draws, 0)
    running = dict.fromkeys(draws, 0)

    def next_candidate():
        for key, (_, wanted) in draws.items():
            if built[key] + running[key] < wanted:
                m = next(queues[key], None)
                if m is not None:
                    return key, m
        return None

    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        pending = {}
        while True:
            while len(pending) < jobs:
                chosen = next_candidate()
                if chosen is None:
                    break
                running[chosen[0]] += 1
                pending[pool.submit(lab.judge, chosen[1])] = chosen
            if not pending:
                break
            finished, _ = concurrent.futures.wait(pending, return_when=concurrent.futures.FIRST_COMPLETED)
            for future in finished:
                key, m = pending.pop(future)
                result = future.result()
                running[key] -= 1
                results[key].append((m, result))
                if result["verdict"] != "compile-error":
                    built[key] += 1
                judged = sum(len(r) for r in results.values())
                if sys.stderr.isatty() or judged % 50 == 0:
                    print(f"{chr(13) if sys.stderr.isatty() else ''}  {judged} judged, {sum(built.values())} built",
                          end="" if sys.stderr.isatty() else "\n", file=sys.stderr, flush=True)
    for (kind, n), r in sorted(results.items()):
        print(f"  task {n}: {len(r)} {kind}s judged, {built[(kind, n)]} built", file=sys.stderr)
    return results


def report_conventions(judged, tasks, elapsed, jobs, write):
    """Prints (and with write, puts in docs/mutation-testing.md) the convention alternates' table; True when
    one that is correct lost a point, or one listed as not correct kept full marks."""
    not_correct = read_reviewed(NOT_CORRECT, "alternate", ("wrong",))
    rows, failures, used = [], [], set()
    for n, results in judged.items():
        c = dict(generated=len(results), compile=0, full=0, wrong=0, review=0, pinned=0)
        for m, r in results:
            if r["verdict"] == "compile-error":
                c["compile"] += 1
            elif m.key in not_correct:
                used.add(m.key)
                if r["verdict"] == "survived":
                    failures.append(f"FULL MARKS FOR A WRONG ALTERNATE {m.id} ({m.operator}), {m.folder} line {m.line}: "
                                    f"{m.description}\n  listed in {NOT_CORRECT.name} as not correct ("
                                    f"{not_correct[m.key][1]}), yet it passes every test: a missing test\n"
                                    f"alternate: {m.key}")
                else:
                    c["wrong"] += 1
            elif r["verdict"] == "survived":
                c["full"] += 1
                c["review"] += m.needs_review
            else:
                c["pinned"] += 1
                failures.append(f"PINNED {m.id} ({m.operator}), {m.folder} line {m.line}: {m.description}\n"
                                f"  a correct alternate loses points: {r['verdict']} by {r.get('test', '')}\n"
                                f"{r.get('output', '')[-1200:]}\nalternate: {m.key}")
        rows.append((n, c))
    print(f"{'task':16} {'alternates':>10} {'no build':>8} {'full marks':>10} {'not correct':>11} {'pinned':>6}")
    for n, c in rows:
        print(f"{tasks[n][0]:16} {c['generated']:10} {c['compile']:8} {c['full']:10} {c['wrong']:11} {c['pinned']:6}")
    print(f"{elapsed:.0f} s with {jobs} jobs")
    for f in failures:
        print("\n" + f)
    if write:
        lines = [f"`tools/mutate --conventions-only --report`: every convention alternate of the reference, judged "
                 f"by its task's suite (this run {elapsed / 60:.1f} min with {jobs} jobs; verdicts whose source and "
                 f"suite did not change come from the cache). *Full marks*: every "
                 f"test passes. *Not correct*: listed in tests/mutants/conventions.txt with the reason, and the "
                 f"suite takes points. *Pinned*: a correct alternate that loses points (must be 0).", "",
                 "| task | alternates | no build | full marks | not correct | pinned |",
                 "| --- | --- | --- | --- | --- | --- |"]
        for n, c in rows:
            lines.append(f"| {tasks[n][0]} | {c['generated']} | {c['compile']} | {c['full']} | {c['wrong']} | "
                         f"{c['pinned']} |")
        total = {k: sum(c[k] for _, c in rows) for k in rows[0][1]} if rows else {}
        if total:
            lines.append(f"| all | {total['generated']} | {total['compile']} | {total['full']} | {total['wrong']} | "
                         f"{total['pinned']} |")
        lines.append("")
        write_table("conventions", lines)
        print("wrote the convention table in docs/mutation-testing.md")
    return bool(failures)


def write_report(rows, reviewed, used, elapsed, jobs, tasks):
    lines = [f"`tools/mutate --report`: every mutant of the reference, judged by its task's suite (this run "
             f"{elapsed / 60:.1f} min with {jobs} jobs; verdicts whose source and suite did not change come from "
             "the cache). *No build*: discarded. *Equivalent* and *correct*: survivors reviewed in "
             "tests/mutants/survivors.txt. *Killed %*: killed (timeouts included) over all that are neither.", "",
             "| task | mutants | no build | killed | timeout | equivalent | correct | survived | killed % |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    judged = {tasks[n][0]: f"| {tasks[n][0]} | {c['generated']} | {c['compile']} | {c['killed']} | {c['timeout']} | "
                           f"{c['equivalent']} | {c['correct']} | {c['survived']} | {c['score']:.1f} % |" for n, c in rows}
    # A run of some tasks (--tasks) keeps the other tasks' rows from the last report.
    kept = {}
    for line in read_table("mutation"):
        folder = line.split("|")[1].strip() if line.startswith("| ") else ""
        if folder in {t[0] for t in tasks.values()} and folder not in judged:
            kept[folder] = line
    if kept:
        lines[0] += f" Rows of tasks this run did not judge are from an earlier run: {', '.join(sorted(kept))}."
    lines += [judged.get(folder) or kept[folder] for folder, _ in sorted(tasks.values()) if folder in judged or folder in kept]
    lines.append("")
    write_table("mutation", lines)
    print("wrote the mutation table in docs/mutation-testing.md")


def read_table(name):
    """The lines between <!-- NAME:begin --> and <!-- NAME:end --> in docs/mutation-testing.md (none if absent)."""
    text = (ROOT / "docs" / "mutation-testing.md").read_text()
    begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
    return text.split(begin, 1)[1].split(end, 1)[0].splitlines() if begin in text else []


def write_table(name, lines):
    """Puts `lines` between <!-- NAME:begin --> and <!-- NAME:end --> in docs/mutation-testing.md (added at its
    end the first time)."""
    doc = ROOT / "docs" / "mutation-testing.md"
    text = doc.read_text()
    begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
    if begin not in text:
        text = text.rstrip("\n") + f"\n\n{begin}\n{end}\n"
    head, rest = text.split(begin, 1)
    doc.write_text(head + begin + "\n" + "\n".join(lines) + end + rest.split(end, 1)[1])
