"""Paired speed runs of two pathlab binaries on the same render: A B A B ...
(alternating, so a machine that slows down mid-way slows both alike), then
the medians and ranges of CPU time per sample and their ratio.

usage: tools/compare-speed [--runs N] OLD NEW -- RENDER ARGUMENTS ...
  e.g. tools/compare-speed /tmp/old/pathlab build/pathlab -- \\
           CBspheres.dae -r 800 600 -m 4 -s 32 -t 2

CPU time is the child's user + system time (getrusage), start-up included
(about 0.1 s: keep runs at several seconds); samples come from the render's
--stats file. "Projected" is the wall time of 1024 samples per pixel at the
run's samples per second. Speed is measured here, never in a unit test."""
import json
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path


def run_once(binary: str, arguments: list[str], scratch: Path) -> dict:
    stats = scratch / "stats.json"
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        done = subprocess.run([binary, *arguments, "-q", "-o", str(scratch / "image.exr"), "--stats", str(stats)],
                              capture_output=True, text=True)
    except OSError as error:
        sys.exit(f"compare-speed: cannot run {binary}: {error.strerror}")
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        sys.exit(f"compare-speed: {binary} failed (exit {done.returncode}): {done.stderr.strip()}")
    numbers = json.loads(stats.read_text())
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    pixels = numbers["width"] * numbers["height"]
    return {"cpu_us_per_sample": 1e6 * cpu / numbers["samples"],
            "projected_1024_spp_s": pixels * 1024 / numbers["samples_per_second"]}


def summary(values: list[float]) -> str:
    return f"median {statistics.median(values):.4g}  (range {min(values):.4g} .. {max(values):.4g})"


def main() -> int:
    args = sys.argv[1:]
    runs = 5
    if args[:1] == ["--runs"]:
        runs = int(args[1])
        args = args[2:]
    if "--" not in args or args.index("--") != 2 or runs < 1:
        print(__doc__, file=sys.stderr)
        return 2
    binaries, arguments = args[:2], args[3:]
    results: dict[str, list[dict]] = {b: [] for b in binaries}
    with tempfile.TemporaryDirectory() as scratch:
        for k in range(runs):
            for binary in binaries:
                result = run_once(binary, arguments, Path(scratch))
                results[binary].append(result)
                print(f"run {k + 1} {binary}: {result['cpu_us_per_sample']:.4f} CPU us/sample, "
                      f"1024 spp in {result['projected_1024_spp_s']:.1f} s", flush=True)
    medians = {}
    for label, binary in zip(("old", "new"), binaries):
        cpu = [r["cpu_us_per_sample"] for r in results[binary]]
        projected = [r["projected_1024_spp_s"] for r in results[binary]]
        medians[label] = statistics.median(cpu)
        print(f"{label} {binary}\n  CPU us/sample: {summary(cpu)}\n  projected 1024 spp, s: {summary(projected)}")
    print(f"speed-up (old / new CPU time per sample, medians): {medians['old'] / medians['new']:.3f}x")
    return 0
