"""Is the lab's verdict right over every setting it offers? Runs every warp
of `pathlab lab` with the reference (or the build's own task files) at each
of its parameters' ends and middle (the others at their defaults), under
several seeds, and counts the rejections: a correct sampler is rejected with
probability 10^-3 per run, so a setting rejected twice is beyond the test's
power, and its range should stop short of it.

  tools/lab-ranges [--build-dir build] [--seeds 3] [--warps a,b] [--write]

--write puts the table in docs/debugger.md (between its lab-ranges
markers). Exit 1 if a setting was rejected in more than one seed."""
import argparse
import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
COMMON = {"samples", "sequence", "seed", "grid"}  # the lab's own: the test assumes independent samples


def lab(binary, *args):
    p = subprocess.run([str(binary), "lab", *args], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout + p.stderr


def parameters(binary, warp):
    """[(name, default, low, high, whole)] of a warp's own parameters."""
    _, out = lab(binary, "--params", warp)
    result = []
    for line in out.splitlines():
        m = re.match(r"(\S+)\s+(\S+)\s+\[(\S+), (\S+)\]", line)
        if m and m.group(1) not in COMMON:
            low, high = float(m.group(3)), float(m.group(4))
            whole = all(float(v).is_integer() for v in (m.group(2), m.group(3), m.group(4))) and high - low <= 40
            result.append((m.group(1), float(m.group(2)), low, high, whole))
    return result


def settings(params):
    """Each parameter at its ends and middle (a whole-number one at every value up to 4), the rest at defaults."""
    seen = set()
    if not [p for p in params if p[0] != "mistake"]:
        yield None, None  # no parameter of its own: its defaults alone
    for name, default, low, high, whole in params:
        if name == "mistake":  # the warp's deliberate mistakes: rejected by design
            continue
        values = ([int(v) for v in range(int(low), int(high) + 1)] if whole and high - low <= 3 else
                  ([int(low), int((low + high) // 2), int(high)] if whole else [low, 0.5 * (low + high), high]))
        for v in values:
            key = (name, v)
            if key not in seen:
                seen.add(key)
                yield name, v


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build-dir", default=str(ROOT / "build"))
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--warps", default="")
    parser.add_argument("--write", action="store_true")
    args = parser.parse_args()
    binary = Path(args.build_dir) / "pathlab"
    _, listing = lab(binary, "--list")
    warps = [line.split()[0] for line in listing.splitlines() if line.strip()]
    if args.warps:
        warps = [w for w in warps if w in args.warps.split(",")]
    rows, runs, rejected_settings = [], 0, []
    for warp in warps:
        total = rejections = 0
        params = parameters(binary, warp)
        for name, value in settings(params):
            rejected = 0
            for seed in range(1, args.seeds + 1):
                chosen = ["--set", f"{name}={value:g}"] if name else []
                code, out = lab(binary, warp, "--no-figure", "-o", "/tmp/lab-ranges.png", *chosen, "--set", f"seed={seed}")
                verdict = "ACCEPTED" if re.search(r"^ACCEPTED", out, re.M) else "REJECTED"
                if verdict == "REJECTED":
                    rejected += 1
                    first = next((l for l in out.splitlines() if l.startswith("REJECTED") or "error" in l.lower()), "")
                    print(f"  {warp} {name or 'defaults'}={value or 0:g} seed {seed}: {first[:150]}")
                total += 1
            rejections += rejected
            if rejected > 1:
                rejected_settings.append(f"{warp} {name or 'defaults'}={value or 0:g}: {rejected} of {args.seeds} seeds")
        runs += total
        ranges = ", ".join(f"{n} [{lo:g}, {hi:g}]" for n, _, lo, hi, _ in params if n != "mistake")
        rows.append(f"| `{warp}` | {ranges or '(none of its own)'} | {total} | {rejections} |")
        print(f"{warp:20} {total:4} runs, {rejections} rejected")
    print(f"{runs} runs, {sum(int(r.split('|')[-2]) for r in rows)} rejected "
          f"({runs * 1e-3:.2f} expected of a correct sampler at 10^-3)")
    for s in rejected_settings:
        print(f"REJECTED MORE THAN ONCE: {s}")
    if args.write:
        doc = ROOT / "docs" / "debugger.md"
        text = doc.read_text()
        begin, end = "<!-- lab-ranges:begin -->", "<!-- lab-ranges:end -->"
        table = [f"`tools/lab-ranges --seeds {args.seeds}`: each warp with the reference, each of its parameters at "
                 "its ends and middle (every value of a small whole-number one; the others at their defaults), "
                 f"under seeds 1 to {args.seeds}. {runs} runs, about {runs * 1e-3:.1f} false rejections expected.", "",
                 "| warp | its parameters | runs | rejected |", "| --- | --- | --- | --- |", *rows, ""]
        head, rest = text.split(begin, 1)
        doc.write_text(head + begin + "\n" + "\n".join(table) + end + rest.split(end, 1)[1])
        print("wrote the table in docs/debugger.md")
    return 1 if rejected_settings else 0
