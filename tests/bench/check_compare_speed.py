"""Smoke test of tools/compare-speed (CTest compare-speed). No timing is
asserted: speed is reported, never tested. Two paired runs of the same
binary on a tiny render: every run line, both summaries and the speed-up
are printed and parse as positive numbers; a binary that fails or does not
exist is named in one clear error with a non-zero exit, and a malformed
command line prints the usage (exit 2).

usage: check_compare_speed.py PATHLAB"""
import re
import subprocess
import sys
from pathlib import Path

tool = Path(__file__).resolve().parents[2] / "tools" / "compare-speed"


def run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(tool), *args], capture_output=True, text=True, timeout=300)


def main() -> int:
    pathlab = sys.argv[1]
    failures = []
    done = run("--runs", "2", pathlab, pathlab, "--", "-r", "32", "24", "-s", "2", "-t", "1")
    if done.returncode != 0:
        failures.append(f"paired runs failed (exit {done.returncode}): {done.stderr.strip()}")
    out = done.stdout
    runs = re.findall(r"^run \d \S+: ([0-9.]+) CPU us/sample, 1024 spp in ([0-9.]+) s$", out, re.M)
    # CPU time is positive; the projection may print 0.0 s (the stubs of a student release render in no time).
    if len(runs) != 4 or not all(float(a) > 0 and float(b) >= 0 for a, b in runs):
        failures.append(f"expected 4 run lines with positive CPU times:\n{out}")
    if len(re.findall(r"^  CPU us/sample: median [0-9.e+-]+  \(range [0-9.e+-]+ \.\. [0-9.e+-]+\)$", out, re.M)) != 2:
        failures.append(f"expected an old and a new summary:\n{out}")
    ratio = re.search(r"^speed-up \(old / new CPU time per sample, medians\): ([0-9.]+)x$", out, re.M)
    if not ratio or not float(ratio.group(1)) > 0:
        failures.append(f"no speed-up line:\n{out}")

    broken = run("--runs", "1", pathlab, "/bin/false", "--", "-r", "8", "8", "-s", "1")
    if broken.returncode == 0 or "/bin/false failed" not in broken.stderr:
        failures.append(f"a failing binary: exit {broken.returncode}, stderr {broken.stderr.strip()!r}")
    missing = run("--runs", "1", pathlab, "/nonexistent/pathlab", "--", "-r", "8", "8", "-s", "1")
    if missing.returncode == 0 or "cannot run /nonexistent/pathlab" not in missing.stderr:
        failures.append(f"a missing binary: exit {missing.returncode}, stderr {missing.stderr.strip()!r}")
    usage = run(pathlab, pathlab)
    if usage.returncode != 2 or "usage: tools/compare-speed" not in usage.stderr:
        failures.append(f"no '--': exit {usage.returncode}, stderr {usage.stderr.strip()!r}")

    for failure in failures:
        print("FAIL:", failure)
    if not failures:
        print("ok: compare-speed runs, prints its numbers, and reports failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
