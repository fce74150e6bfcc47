"""Smoke test of `pathlab-bench bvh --json`: it runs, its last line is the
promised JSON object, and the reference agrees with Embree on every ray.
No timing is asserted: speed is reported, never tested."""
import json
import subprocess
import sys

bench = sys.argv[1]
out = subprocess.run([bench, "bvh", "--json"], capture_output=True, text=True, timeout=120)
print(out.stdout)
print(out.stderr, file=sys.stderr)
if out.returncode != 0:
    sys.exit(f"pathlab-bench exited with {out.returncode}")
result = json.loads(out.stdout.strip().splitlines()[-1])
failures = []
for key in ("build_ms_reference", "build_ms_embree", "triangles"):
    if key not in result:
        failures.append(f"missing key {key}")
for name in ("primary", "shadow", "diffuse"):
    entry = result.get(name, {})
    for key in ("reference_mrays", "embree_mrays", "ratio", "mismatches"):
        if key not in entry:
            failures.append(f"{name}: missing key {key}")
    if not entry.get("reference_mrays", 0) > 0:
        failures.append(f"{name}: no reference rays traced")
    if entry.get("mismatches") not in (0, None):
        failures.append(f"{name}: {entry['mismatches']} rays where the reference and Embree disagree")
if result.get("triangles", 0) < 50000:
    failures.append("expected the bunny or the generated mesh (>= 50k triangles)")
for f in failures:
    print("FAIL:", f)
print(f"{4 - min(4, len(failures))} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
