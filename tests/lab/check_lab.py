#!/usr/bin/env python3
"""The sampling lab, headless, judged on what it must accept and reject.

  check_lab.py PATHLAB TESTS_BUILD_DIR TESTS_SOURCE_DIR [--task NN-name]

(--task NN-name: that task's warps in 1 and 4 and its lab_cases.txt in 3
alone, as tests/new-task/test_new_task.py checks a course's own task.)

Each verdict is taken under seeds 1, 2, 3 (independent samples): a correct
warp must be ACCEPTED under at least two (a correct warp is rejected in
1 run in 1000, so in two of three with probability 3e-6; the third seed
runs only when one of the first two rejects), a mistake REJECTED under
all three.
1. Every warp `pathlab lab --list` names, on the reference this build
   links; and once with its figure and CSV written (a PNG, and one CSV line
   per cell with the counts summing to the samples drawn).
2. The reference on more settings (every light shape; the environment on
   maps read from files, one wider than the lab's bins resolve, one hot
   pixel): accepted. The lab's own warps with their classic mistake switched
   on (--set mistake=K: an unnormalised CDF, the annulus without its
   Jacobian, the hemisphere without sin theta, blocks that do not sum to 1,
   light triangles chosen by count or points without sqrt, a sphere light
   uniform in theta): rejected.
3. Every case of each task's TESTS_SOURCE_DIR/NN-name/lab_cases.txt: the pathlab-lab program linked with that task file
   (TESTS_BUILD_DIR/pathlab-lab-KIND-NN-name-FILE; KIND tasks: the stub)
   gives the verdict listed, without crashing.
4. What a user sees first: every warp with every default (no --set) on the
   reference is ACCEPTED with p >= 0.05, clear of the rejection tail.
5. Bad input (an unknown warp, an unknown or out-of-range parameter; a map
   for a warp that reads none, missing or black): a message and exit code 1.
Fixed seeds, so the test itself cannot flake; the lab's rate of rejecting a
correct warp, measured over many seeds, is in docs/debugger.md."""
import csv
import io
import re
import subprocess
import sys
import tempfile
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
# The classic mistakes the lab's own warps switch on with --set mistake=K.
MISTAKES = [("pdf-cdf", "mistake=1"), ("annulus", "mistake=1"), ("uniform-hemisphere", "mistake=1"),
            ("discrete", "mistake=1"), ("light-points", "shape=1", "mistake=1"),
            ("light-points", "shape=1", "mistake=2"), ("light-points", "shape=0", "mistake=2"),
            ("light-points", "shape=2", "mistake=1")]
# Warps on settings beyond their defaults the reference must pass: every
# light shape, and the environment on users' maps (wider than the lab's
# bins resolve: averaged down; a hot pixel).
REFERENCE_SETTINGS = [("light-points", "--set", "shape=1"), ("light-points", "--set", "shape=2"),
                      ("environment", "--map", "media/envmaps/sky-sun.exr"),
                      ("environment", "--map", "media/envmaps/studio.exr"),
                      ("environment", "--map", "media/envmaps/hot-pixel.exr")]


def options(*settings):
    """NAME=VALUE settings as --set options; options already written (--set X, --map FILE) kept."""
    out, i = [], 0
    while i < len(settings):
        if settings[i].startswith("--"):
            value = settings[i + 1]
            out += [settings[i], str(SOURCE / value) if settings[i] == "--map" else value]
            i += 2
        else:
            out += ["--set", settings[i]]
            i += 1
    return out


def lab(program, warp, *settings, figure=None):
    command = [str(program), "lab"] if Path(program).name == "pathlab" else [str(program)]
    command += [warp, *options(*settings)]
    command += ["-o", str(figure)] if figure else ["--no-figure"]
    run = subprocess.run(command, capture_output=True, text=True, timeout=300)
    verdict = "ACCEPTED" if "\nACCEPTED" in "\n" + run.stdout else ("REJECTED" if "\nREJECTED" in "\n" + run.stdout else "?")
    return run.returncode, verdict, run.stdout + run.stderr


SEEDS = (1, 2, 3)
# The reference with every default must not sit in the test's tail: p at
# least this (the defaults' seed was chosen for it: lab/lab.cpp).
DEFAULTS_LEAST_P = 0.05


def verdicts(program, warp, *settings, want="accept"):
    """(verdicts under the seeds run, the output of the first run not matching the majority). Where the
    warp must be accepted, two acceptances end it: the third seed cannot change the judgement."""
    runs = []
    for seed in SEEDS:
        runs.append(lab(program, warp, f"seed={seed}", *settings))
        if want == "accept" and sum(code == 0 and verdict == "ACCEPTED" for code, verdict, _ in runs) == 2:
            break
    bad = [out for code, _, out in runs if code != 0]
    return [verdict if code == 0 else f"exit {code}" for code, verdict, _ in runs], (bad or [runs[0][2]])[0]


def judged(want, seen):
    return seen.count("ACCEPTED") >= 2 if want == "accept" else seen.count("REJECTED") == len(SEEDS)


def main() -> int:
    pathlab, build, tests = Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
    only = sys.argv[sys.argv.index("--task") + 1] if "--task" in sys.argv[4:] else None
    failures = []
    listing = subprocess.run([str(pathlab), "lab", "--list"], capture_output=True, text=True, check=True).stdout
    warps = [line.split()[0] for line in listing.splitlines()
             if line.strip() and (not only or line.split()[1].startswith(f"T{int(only[:2])}."))]
    if len(warps) < (1 if only else 11):
        failures.append(f"pathlab lab --list names {len(warps)} warps{f' of task {only}' if only else ''}: {warps}")

    with tempfile.TemporaryDirectory(prefix="pathlab-lab-") as temp:
        for warp in warps:
            seen, out = verdicts(pathlab, warp)
            print(f"  reference {warp}: {' '.join(seen)}")
            if not judged("accept", seen):
                failures.append(f"reference {warp}: {seen}\n{out}")
            # What a user sees first: every default shows the reference ACCEPTED, clear of the tail.
            code, verdict, out = lab(pathlab, warp)
            p = re.search(r"p = ([0-9.e+-]+)", out)
            if code != 0 or verdict != "ACCEPTED" or (p and float(p.group(1)) < DEFAULTS_LEAST_P):
                failures.append(f"reference {warp} with every default: {verdict}, p {p and p.group(1)} "
                                f"(want ACCEPTED, p >= {DEFAULTS_LEAST_P}):\n{out}")
            figure, table = Path(temp) / f"{warp}.png", Path(temp) / f"{warp}.csv"
            run = subprocess.run([str(pathlab), "lab", warp, "-o", str(figure), "--csv", str(table),
                                  "--set", "samples=20000"], capture_output=True, text=True, timeout=300)
            if run.returncode != 0 or not figure.exists() or figure.stat().st_size < 10000:
                failures.append(f"{warp}: no figure ({run.returncode}):\n{run.stdout}{run.stderr}")
            elif not table.exists():
                failures.append(f"{warp}: no CSV")
            else:
                rows = list(csv.DictReader(io.StringIO(table.read_text())))
                drawn = sum(float(r["observed"]) for r in rows)
                expected = sum(float(r["expected"]) for r in rows)
                if drawn != 20000 or abs(expected - 20000) > 200:
                    failures.append(f"{warp}: the CSV's counts sum to {drawn:g} observed, {expected:g} expected")

        for warp, *settings in [] if only else REFERENCE_SETTINGS:
            seen, out = verdicts(pathlab, warp, *settings)
            print(f"  reference {warp} {' '.join(settings)}: {' '.join(seen)}")
            if not judged("accept", seen):
                failures.append(f"reference {warp} {settings}: {seen}\n{out}")

        for warp, *settings in [] if only else MISTAKES:
            seen, out = verdicts(pathlab, warp, *settings, want="reject")
            print(f"  {warp} with {' '.join(settings)}: {' '.join(seen)}")
            if not judged("reject", seen):
                failures.append(f"{warp} {settings}: {seen}\n{out}")

    case_lines = [line for cases in sorted(tests.glob(f"{only or '[0-9][0-9]-*'}/lab_cases.txt"))
                  for line in cases.read_text().splitlines()]
    if not case_lines:
        failures.append(f"no lab case in {tests}/NN-name/lab_cases.txt")
    for line in case_lines:
        if not line.startswith(("mutants/", "alternates/", "tasks/")):
            continue
        fields = line.split()
        path, warp, want = fields[0], fields[1], fields[2]
        settings = fields[3:]  # --set NAME=VALUE, --map FILE (from the repository's root)
        kind, task, name = path.removesuffix(".cpp").split("/")
        program = build / f"pathlab-lab-{kind}-{task}-{name}"
        seen, out = verdicts(program, warp, *settings, want=want)
        print(f"  {path} on {warp} {' '.join(settings)}: {' '.join(seen)} (want {want})")
        if not judged(want, seen):
            failures.append(f"{path} on {warp}: {seen}, want {want}\n{out[-1500:]}")

    if only:
        return report(failures)
    black = SOURCE / "media/envmaps/black.exr"
    for bad, why in ((["lab", "no-such-warp"], "no warp"), (["lab", "annulus", "--set", "r1=7"], "must be between"),
                     (["lab", "annulus", "--set", "colour=1"], "has the parameters"),
                     (["lab", "annulus", "--map", str(black)], "--map is for the environment warp"),
                     (["lab", "environment", "--map", str(SOURCE / "no-such-map.exr")], "cannot open"),
                     (["lab", "environment", "--map", str(black)], "black everywhere"),
                     (["lab", "annulus", "--set", "grid=10.5"], "grid takes whole numbers"),
                     (["lab", "annulus", "--set", "sequence=0.5"], "sequence takes whole numbers"),
                     (["lab", "annulus", "--csv", ""], "--csv: expected an output file name")):
        run = subprocess.run([str(pathlab), *bad, "--no-figure"], capture_output=True, text=True, timeout=60)
        if run.returncode != 1 or why not in run.stderr:
            failures.append(f"pathlab {' '.join(bad)}: exit {run.returncode}, {run.stderr.strip()[:200]!r}")

    # Outputs checked before anything is written: a table that cannot be
    # written leaves no figure, and the figure and the table may not be one file.
    with tempfile.TemporaryDirectory(prefix="pathlab-lab-outputs-") as tmp:
        for bad, why in ((["--csv", "/no-such-folder/cells.csv"], "output folder does not exist"),
                         (["-o", "same.png", "--csv", "same.png"], "-o and --csv name the same file")):
            run = subprocess.run([str(pathlab), "lab", "annulus", *bad], capture_output=True, text=True, timeout=60,
                                 cwd=tmp)
            left = sorted(p.name for p in Path(tmp).iterdir())
            if run.returncode != 1 or why not in run.stderr or left:
                failures.append(f"pathlab lab annulus {' '.join(bad)}: exit {run.returncode}, "
                                f"{run.stderr.strip()[:200]!r}, files left: {left}")
    named = subprocess.run([str(pathlab), "lab", "annulus", "--set", "sequence=sobol", "--no-figure"],
                           capture_output=True, text=True, timeout=60)
    if named.returncode != 0 or "ACCEPTED" not in named.stdout:
        failures.append(f"pathlab lab annulus --set sequence=sobol: exit {named.returncode}, {named.stderr[:200]!r}")

    return report(failures)


def report(failures) -> int:
    for f in failures:
        print("FAIL:", f)
    print(f"sampling-lab: {'ok' if not failures else f'{len(failures)} failures'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
