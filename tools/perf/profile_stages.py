"""Where a render's time goes, stage by stage: samples a command with
`perf record` (Linux perf; apt-get install linux-perf) and sums each
function's own time into the stage it belongs to.

usage: tools/profile-stages [--json] [-- COMMAND ...]
       (default command: build/pathlab-bench render --quick --threads 1)

Self time only: work the compiler inlined counts in the function it was
inlined into (the random numbers drawn inside the light sampling count as
light sampling). Stages are matched by function name, first match wins;
what matches nothing is listed under "other" with its largest functions."""
import json
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

root = Path(__file__).resolve().parents[2]

# (stage, pattern over the demangled symbol or library name), first match wins.
STAGES = [
    ("hit records (surface point, normals)", r"surfaceHit|fastSurfaceHit|triangleSurfacePoint|sphereSurfacePoint"),
    ("ray queries: BVH traversal and primitive tests",
     r"WideBvh::|intersectClosest|intersectAny|intersectBox|intersectTriangle|intersectSphere|childEntries|"
     r"testPacket|testSpheres|leafHits|Accelerator::|LeafGeometry::|intersectBruteForce|fastIntersect"),
    ("light sampling and shadow-ray set-up",
     r"AreaLight::|Lights::|lightDirection|offsetRayOrigin|EnvironmentLight::|sampleEnvironment|environmentPdf|"
     r"estimateDirectLighting|emittedRadiance|\bvisible\b"),
    ("BSDF construction, evaluation, sampling",
     r"Bsdf::|lambertianBrdf|sampleDiffuseDirection|diffuseDirectionPdf|sampleMirror|sampleGlass|fresnel"),
    ("random numbers", r"Sampler::|pixelSampler|sobol|Sobol|owen|Owen|scramble|hash"),
    ("camera rays", r"generateCameraRay|pixelSamplePosition|estimatePixelSample|cameraBasis"),
    ("path loop", r"tracePath|estimateRadiance|traceWithStrategy|TraceContext::"),
    ("film and render loop", r"ProgressiveRender::|parallelFor|Image::|ProgressBar|render\("),
    ("maths library (sin, cos, exp, ...)", r"^libm|libm\.so|sincos|__sin|__cos|__exp|__log|__pow|__atan|__acos"),
    ("start-up (dynamic linking, libraries)", r"ld-linux|do_lookup|_dl_|libOpenImageIO|libstdc\+\+"),
    ("kernel", r"\[kernel|^\[k\]"),
]


def main() -> int:
    args = sys.argv[1:]
    as_json = "--json" in args
    if as_json:
        args.remove("--json")
    if args and args[0] == "--":
        args = args[1:]
    command = args or [str(root / "build/pathlab-bench"), "render", "--quick", "--threads", "1"]
    if not shutil.which("perf"):
        print("profile-stages: perf is not installed (apt-get install linux-perf)", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as scratch:
        data = Path(scratch) / "perf.data"
        run = subprocess.run(["perf", "record", "-q", "-F", "999", "-o", str(data), "--", *command],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if run.returncode != 0 or not data.exists():
            print(f"profile-stages: perf record failed: {run.stderr.strip()}", file=sys.stderr)
            return 2
        report = subprocess.run(["perf", "report", "-i", str(data), "--no-children", "--stdio", "--sort", "dso,sym",
                                 "--percent-limit", "0"], capture_output=True, text=True)
    # Lines: "  12.34%  dso  [.] symbol"
    line = re.compile(r"^\s*([0-9.]+)%\s+(\S+)\s+\[(.)\]\s+(.*)$")
    totals = {stage: 0.0 for stage, _ in STAGES}
    totals["other"] = 0.0
    others: dict[str, float] = {}
    for text in report.stdout.splitlines():
        m = line.match(text)
        if not m:
            continue
        percent, dso, kind, symbol = float(m.group(1)), m.group(2), m.group(3), m.group(4).strip()
        name = f"[kernel] {symbol}" if kind == "k" else f"{dso} {symbol}"
        for stage, pattern in STAGES:
            if re.search(pattern, symbol) or re.search(pattern, dso) or (kind == "k" and stage == "kernel"):
                totals[stage] += percent
                break
        else:
            totals["other"] += percent
            others[name] = others.get(name, 0.0) + percent
    if as_json:
        print(json.dumps({"command": command, "stages": totals,
                          "other_top": sorted(others.items(), key=lambda kv: -kv[1])[:8]}))
        return 0
    print(f"time by stage (self time, perf samples) of: {' '.join(command)}")
    for stage, percent in sorted(totals.items(), key=lambda kv: -kv[1]):
        print(f"  {percent:5.1f} %  {stage}")
    top = sorted(others.items(), key=lambda kv: -kv[1])[:8]
    if top:
        print("largest in other: " + ", ".join(f"{name} {p:.1f} %" for name, p in top))
    return 0
