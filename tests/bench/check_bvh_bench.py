"""Smoke test of pathlab-bench (CTest bench-bvh-agrees). No timing is
asserted: speed is reported, never tested.

bvh --json: it runs, its last line is the promised JSON object, task 3's BVH
agrees with Embree on every ray, and the output names whose code ran ("yours"
or "reference", as `pathlab --version` beside it says when it is there).

converge --json on a small Cornell box: every strategy is either run or
reported unavailable with a reason, never both; a strategy whose change a
probe render shows to make no difference is unavailable (env-uniform on a
scene without an environment map, in any build); with the reference's
task 5 the path-tracing strategies (the framework's tracer) run; with the
student's stub task 5 (it reached a T5 TODO: e.g. a build configured
-DPATHLAB_TASK5=student) each either runs, and the output notes the TODOs
reached, or is unavailable with a reason that names your task 5. The stub case needs a second
build configuration, so CTest's build (all reference by default) checks the
probe through env-uniform, and the stub case runs when this script is given
such a build's pathlab-bench.

render --scene FILE --json with Sobol and stratified samples: it runs, the
JSON describes the run, and the ray-query share is a fraction; a missing
scene file is one clear error and a non-zero exit, and so is every option
out of range (--spp 0, --budget -1 or nan, ...); pathlab-envmap --help prints
its usage and writes nothing.

usage: check_bvh_bench.py PATHLAB-BENCH [--skip-bvh]"""
import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))  # the repository: the import root (docs/architecture.md)
from tools import pathlab_tasks  # noqa: E402  (the task list: the tasks/NN-name folders)

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
TASK5_STRATEGIES = ("uniform-hemisphere", "no-nee", "no-rr", "mis-power")

bench = sys.argv[1]
failures = []
checks = 0


def check(condition, message):
    global checks
    checks += 1
    if not condition:
        failures.append(message)
    return condition


def configured_tasks():
    """{'1': 'reference', ...} from `pathlab --version` beside the bench, or None."""
    cli = os.path.join(os.path.dirname(os.path.abspath(bench)), "pathlab")
    if not os.path.exists(cli):
        return None
    out = subprocess.run([cli, "--version"], capture_output=True, text=True, timeout=30)
    pairs = re.findall(r"(\d+):(reference|student)", out.stdout)
    return {n: ("yours" if v == "student" else "reference") for n, v in pairs} or None


def run(args, timeout):
    out = subprocess.run([bench] + args, capture_output=True, text=True, timeout=timeout)
    print("$ pathlab-bench " + " ".join(args))
    print(out.stdout)
    print(out.stderr, file=sys.stderr)
    return out


expected = configured_tasks()

# ---- bvh ---------------------------------------------------------------------
if "--skip-bvh" not in sys.argv:
    out = run(["bvh", "--json"], 300)
    if check(out.returncode == 0, f"bvh: pathlab-bench exited with {out.returncode}"):
        result = json.loads(out.stdout.strip().splitlines()[-1])
        for key in ("build_ms_task3", "build_ms_embree", "triangles", "task3", "tasks"):
            check(key in result, f"bvh: missing key {key}")
        for name in ("primary", "shadow", "diffuse"):
            entry = result.get(name, {})
            for key in ("task3_mrays", "embree_mrays", "ratio", "mismatches"):
                check(key in entry, f"bvh {name}: missing key {key}")
            check(entry.get("task3_mrays", 0) > 0, f"bvh {name}: no rays traced through task 3")
            check(entry.get("mismatches") in (0, None),
                  f"bvh {name}: {entry.get('mismatches')} rays where task 3 and Embree disagree")
            # The render path's SIMD walk of the same tree: task 3's hits exactly.
            check(entry.get("fast_mrays", 0) > 0, f"bvh {name}: no rays traced through the fast path")
            check(entry.get("fast_mismatches_vs_task3") == 0,
                  f"bvh {name}: {entry.get('fast_mismatches_vs_task3')} rays where the fast path and task 3 differ")
        check(result.get("triangles", 0) >= 50000, "bvh: expected the bunny or the generated mesh (>= 50k triangles)")
        # Whose code ran.
        who = result.get("task3")
        check(who in ("yours", "reference"),
              f"bvh: task3 is {who!r}, not 'yours' or 'reference' (was pathlab-bench built without "
              "PATHLAB_TASK_SUMMARY? apps/CMakeLists.txt gives it to pathlab and should to pathlab-bench)")
        check(re.search(rf"^code: task 3 \(BVH\) {who}\b", out.stdout, re.M) is not None,
              "bvh: the text output does not name whose task 3 ran")
        if expected:
            check(who == expected.get("3"), f"bvh: says task 3 is {who!r}, pathlab --version says {expected.get('3')!r}")
            check(result.get("tasks", {}).get("2") == expected.get("2"), "bvh: task 2 labelled unlike pathlab --version")
        if who in ("yours", "reference"):
            label = "yours" if who == "yours" else "ref"
            check(re.search(rf"^rays .*\|\s+{label}\s+Embree\s+ratio", out.stdout, re.M) is not None,
                  f"bvh: the table's columns are not labelled {label!r}")
        # The student's task 3 against the reference's, run by the reference build beside this one.
        beside = os.path.join(os.path.dirname(os.path.abspath(bench)), "pathlab-bench-reference")
        if who == "yours" and os.path.exists(beside):
            comparison = result.get("reference_task3") or {}
            for name in ("primary", "shadow", "diffuse"):
                check(comparison.get(name, {}).get("reference_mrays", 0) > 0,
                      f"bvh {name}: no speed of the reference's task 3 from {beside}")
            check("the reference's task 3 on the same mesh" in out.stdout, "bvh: no lines for the reference's task 3")
        elif who == "yours":
            check("reference_task3" in result and result["reference_task3"] is None and
                  "the reference's task 3: not measured: no reference build" in out.stdout,
                  "bvh: without a reference build beside it, the bench does not say so")
        else:
            check("reference_task3" not in result, "bvh: the reference compared with itself")

    # What a student build asks of the reference build beside it: task 3's speed alone, as JSON, nothing printed.
    with tempfile.TemporaryDirectory(prefix="pathlab-bench-speed-") as tmp:
        speed_file = os.path.join(tmp, "speed of task 3.json")
        out = run(["bvh", "--triangles", "2000", "--threads", "1", "--task3-speed-only", speed_file], 120)
        if check(out.returncode == 0 and out.stdout == "" and os.path.exists(speed_file),
                 f"bvh --task3-speed-only: exit {out.returncode}, printed {out.stdout[-200:]!r}"):
            speed = json.load(open(speed_file))
            check(speed.get("task3") in ("yours", "reference") and
                  all(speed.get(n, {}).get("task3_mrays", 0) > 0 for n in ("primary", "shadow", "diffuse")),
                  f"bvh --task3-speed-only: {speed}")

# ---- converge ----------------------------------------------------------------
strategies = ["reference", *TASK5_STRATEGIES, "env-uniform", "stratified"]
with tempfile.TemporaryDirectory(prefix="pathlab-bench-converge-") as tmp:
    scene = json.load(open(os.path.join(SOURCE, "media", "scenes", "cornell-spheres.json")))
    scene["render"].update(width=64, height=48)
    scene_path = os.path.join(tmp, "small-cornell.json")
    json.dump(scene, open(scene_path, "w"))
    out = run(["converge", scene_path, "--strategies", ",".join(strategies), "--budget", "0.2",
               "--reference-spp", "16", "--out", tmp, "--json"], 300)
    if check(out.returncode == 0, f"converge: pathlab-bench exited with {out.returncode}"):
        result = json.loads(out.stdout.strip().splitlines()[-1])
        tasks = result.get("tasks", {})
        every = sorted(str(n) for n in pathlab_tasks.tasks(ROOT))
        check(sorted(tasks, key=int) == sorted(every, key=int), f"converge: 'tasks' does not name tasks {every}")
        check(all(v in ("yours", "reference") for v in tasks.values()),
              f"converge: tasks {tasks} (whose code ran is not recorded in this pathlab-bench)")
        check(re.search(r"^code: task", out.stdout, re.M) is not None, "converge: no 'code:' line")
        if expected:
            check(tasks == expected, f"converge: says tasks are {tasks}, pathlab --version says {expected}")
        by_name = {s["name"]: s for s in result.get("strategies", [])}
        check(list(by_name) == strategies, f"converge: strategies {list(by_name)}, asked for {strategies}")
        for name, s in by_name.items():
            if s["available"]:
                check(len(s["points"]) > 0, f"converge {name}: available but not run")
                check(not s.get("reason"), f"converge {name}: available with a reason")
            else:
                check(not s["points"] and s["efficiency"] is None, f"converge {name}: unavailable but measured")
                check(bool(s.get("reason")), f"converge {name}: unavailable without a reason")
                check(re.search(rf"^{re.escape(name)}\s+unavailable\s+\S", out.stdout, re.M) is not None,
                      f"converge {name}: the text table does not say unavailable")
                check(re.search(rf"\d+(\.\d+)?x less time than {re.escape(name)}\b", out.stdout) is None and
                      re.search(rf"^{re.escape(name)} needs", out.stdout, re.M) is None,
                      f"converge {name}: a time ratio printed for an unavailable strategy")
        check(by_name.get("reference", {}).get("available") is True, "converge: the default strategy must run")
        env = by_name.get("env-uniform", {})
        check(env.get("available") is False and "no environment map" in env.get("reason", ""),
              "converge env-uniform: the probe should find it has no effect on a scene without an environment map")
        stub5 = any(tag.startswith("T5.") for tag in result.get("todos_reached", []))
        for name in TASK5_STRATEGIES:
            s = by_name.get(name, {})
            if tasks.get("5") == "reference":
                check(s.get("available") is True, f"converge {name}: the reference's task 5 implements it")
            elif stub5:
                if s.get("available"):
                    check(re.search(r"^note: the linked code reached TODO .*T5\.", out.stdout, re.M) is not None,
                          f"converge {name}: run with the stub task 5, but no note names the T5 TODOs reached")
                else:
                    check("your task 5" in s.get("reason", ""),
                          f"converge {name}: unavailable with the stub task 5, but the reason does not name it")
        # The CSV says the same.
        rows = list(csv.DictReader(open(os.path.join(tmp, "small-cornell-converge.csv"))))
        for name, s in by_name.items():
            mine = [r for r in rows if r["strategy"] == name]
            flags = {r["available"] for r in mine}
            check(flags == {"true" if s["available"] else "false"}, f"converge {name}: CSV available {flags}")
            if not s["available"]:
                check(len(mine) == 1 and mine[0]["reason"] == s["reason"], f"converge {name}: CSV reason")

# ---- converge at equal time, with -r and -m ------------------------------------
# Each curve runs on until it passes the last --at time (even past the
# budget), and the relMSE reported there lies between its two points around it.
with tempfile.TemporaryDirectory(prefix="pathlab-bench-equal-time-") as tmp:
    scene_path = os.path.join(SOURCE, "media", "scenes", "cornell-spheres.json")
    at = 0.05
    out = run(["converge", scene_path, "--strategies", "reference,adaptive-0.2", "--budget", "0.01", "--at", str(at),
               "-r", "40", "30", "-m", "3", "--reference-spp", "16", "--out", tmp, "--json"], 300)
    if check(out.returncode == 0, f"converge --at: pathlab-bench exited with {out.returncode}: {out.stderr[-300:]}"):
        result = json.loads(out.stdout.strip().splitlines()[-1])
        check(os.path.basename(result["reference_image"]["path"]) == "cornell-spheres-40x30-m3-reference-16spp.exr",
              f"converge -r -m: the cached reference's name {result['reference_image']['path']} does not say 40x30, -m 3")
        check(re.search(rf"^at {at:g} s:.*adaptive-0\.2 relMSE [\d.e-]+ \(efficiency [\d.]+x reference's\)",
                        out.stdout, re.M) is not None, "converge --at: no equal-time line naming both strategies")
        equal = result.get("equal_time", [])
        check(len(equal) == 1 and equal[0].get("seconds") == at, f"converge --at: equal_time {equal}")
        for s in result.get("strategies", []):
            points = s["points"]
            check(points and points[-1]["seconds"] >= at, f"converge --at {s['name']}: stopped before {at} s")
            value = equal[0]["relmse"].get(s["name"]) if equal else None
            around = [(a, b) for a, b in zip(points, points[1:]) if a["seconds"] <= at <= b["seconds"]]
            if check(value is not None and around, f"converge --at {s['name']}: no relMSE at {at} s ({value})"):
                a, b = around[0]
                low, high = sorted((a["relmse"], b["relmse"]))
                check(low <= value <= high, f"converge --at {s['name']}: {value} not between {low} and {high}")
                # The bias beside it: each point's block shift, and at --at one between its two points'.
                shift = equal[0].get("block_shift", {}).get(s["name"])
                low, high = sorted((a.get("block_shift", math.nan), b.get("block_shift", math.nan)))
                check(shift is not None and low <= shift <= high,
                      f"converge --at {s['name']}: block shift {shift} not between {low} and {high}")

    for args, says in ((["-r", "0", "30"], "-r: an image of 0x30 pixels is out of range"),
                       (["-m", "2000"], "-m: at most 1024")):
        out = run(["converge", scene_path, *args, "--out", tmp], 60)
        check(out.returncode == 1 and says in out.stderr, f"converge {' '.join(args)}: exit {out.returncode}, "
              f"stderr {out.stderr[-200:]!r}")

# ---- render ------------------------------------------------------------------
with tempfile.TemporaryDirectory(prefix="pathlab-bench-render-") as tmp:
    scene_path = os.path.join(SOURCE, "media", "scenes", "cornell-mirror-glass.json")
    for sampler in ("sobol", "stratified"):
        out = run(["render", "--scene", scene_path, "--spp", "2", "--threads", "2", "--sampler", sampler, "--json"], 300)
        if check(out.returncode == 0, f"render --sampler {sampler}: pathlab-bench exited with {out.returncode}"):
            result = json.loads(out.stdout.strip().splitlines()[-1])
            check(result.get("scene") == scene_path and result.get("spp") == 2 and result.get("sampler") == sampler,
                  f"render: the JSON does not describe the run: {result}")
            # The replayed rays are part of the paths' own work, so the share is below 1 (timed in the
            # thread's CPU seconds: a busy machine does not tip it over, as wall time did in CI).
            share = result.get("ray_query_share", -1)
            check(0.0 < share < 1.0, f"render: ray-query share {share} is not a fraction")
            check(re.search(r"^ray queries .*: \d+ % of the time", out.stdout, re.M) is not None,
                  "render: no line with the ray-query share")
            # With Embree built in, the same rays through it: a share, and the same answers (a wrong
            # primitive numbering, or spheres left out, would disagree on most rays of this scene).
            if result.get("embree_query_share") is not None:
                # Embree's walk is not part of the paths' work: its share may pass 1 on some scene.
                check(0.0 < result["embree_query_share"] < math.inf and result.get("embree_agreement", 0) > 0.99,
                      f"render: Embree's share {result['embree_query_share']} or agreement "
                      f"{result.get('embree_agreement')} is off")
                check("through Intel Embree" in out.stdout, "render: no line with Embree's share")
    missing = os.path.join(tmp, "no-such-scene.json")
    out = run(["render", "--scene", missing, "--spp", "1"], 60)
    check(out.returncode != 0 and "no-such-scene.json" in out.stderr and "Traceback" not in out.stderr,
          f"render --scene of a missing file: exit {out.returncode}, stderr {out.stderr[-200:]!r}")

# ---- options out of range: one clear error, exit 1, nothing run -----------------
for args in (["render", "--spp", "0"], ["render", "--threads", "-2"], ["bvh", "--triangles", "0"],
             ["converge", "x.json", "--budget", "-1"], ["converge", "x.json", "--budget", "nan"],
             ["converge", "x.json", "--budget", "inf"], ["converge", "x.json", "--reference-spp", "0"],
             ["converge", "x.json", "--at", "0"], ["converge", "x.json", "--max-depth", "-1"]):
    out = run(args, 60)
    option = next(a for a in args if a.startswith("--"))
    check(out.returncode == 1 and option in out.stderr and "must be" in out.stderr,
          f"{' '.join(args)}: exit {out.returncode}, stderr {out.stderr[-200:]!r}")
# A scene with media takes task 12's path tracer only: said in this program's flags, before any render.
with tempfile.TemporaryDirectory(prefix="pathlab-bench-media-") as tmp:
    fog = os.path.join(SOURCE, "media", "scenes", "fog-shafts.json")
    for flag, name in (("--strategies", "mis-power"), ("--reference-strategy", "no-rr")):
        out = run(["converge", fog, flag, name, "--budget", "0.2", "--out", tmp], 60)
        check(out.returncode == 1 and f"{flag} {name}: " in out.stderr and "--integrator" not in out.stderr and
              len(out.stderr.strip().splitlines()) == 1 and not os.listdir(tmp),
              f"converge {flag} {name} on a scene with media: exit {out.returncode}, stderr {out.stderr[-300:]!r}")
envmap = os.path.join(os.path.dirname(os.path.abspath(bench)), "pathlab-envmap")
if os.path.exists(envmap):
    with tempfile.TemporaryDirectory(prefix="pathlab-envmap-") as tmp:
        out = subprocess.run([envmap, "--help"], capture_output=True, text=True, timeout=60, cwd=tmp)
        check(out.returncode == 0 and "usage" in out.stdout and not os.listdir(tmp),
              f"pathlab-envmap --help: exit {out.returncode}, wrote {os.listdir(tmp)}")
        out = subprocess.run([envmap, "--out"], capture_output=True, text=True, timeout=60, cwd=tmp)
        check(out.returncode == 1 and not os.listdir(tmp), f"pathlab-envmap --out: exit {out.returncode}")

for f in failures:
    print("FAIL:", f)
print(f"{checks - len(failures)} checks passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
