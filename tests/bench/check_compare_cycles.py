"""Smoke test of tools/compare-cycles (CTest compare-cycles): its comparison
scene of the roughness sweep makes every conductor white and drops the
plastic, keeps the environment readable and loads in pathlab; task 12's
medium cube keeps its medium and interface; scenes it
cannot translate exactly are refused with a reason; the Blender-side script
compiles. With `blender` on PATH, a tiny comparison runs end to end (no
verdict on so few samples); without it, one line says so.

usage: check_compare_cycles.py PATHLAB"""
import json
import py_compile
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TOOL = ROOT / "tools" / "compare-cycles"


def main() -> int:
    pathlab = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as scratch:
        out = Path(scratch) / "white.json"
        done = subprocess.run([sys.executable, str(TOOL), str(ROOT / "media/scenes/roughness-sweep.json"),
                               "--scene-only", str(out)], capture_output=True, text=True)
        if done.returncode != 0:
            failures.append(f"--scene-only on the roughness sweep failed: {done.stderr.strip()}")
        else:
            spec = json.loads(out.read_text())
            kinds = {m.get("type", "diffuse") for m in spec["materials"].values()}
            conductors = [m for m in spec["materials"].values() if m.get("type") == "conductor"]
            if kinds != {"diffuse", "conductor"} or any(m["f0"] != [1, 1, 1] or "eta" in m for m in conductors):
                failures.append(f"the comparison scene keeps what Cycles 3.4 cannot model: {spec['materials']}")
            if any(s["material"] == "red plastic" for s in spec["spheres"]) or len(spec["spheres"]) != 5:
                failures.append("the plastic sphere was not dropped, or other spheres were")
            if not Path(spec["environment"]["image"]).is_file():
                failures.append(f"the environment image is not an existing path: {spec['environment']['image']}")
            if "plastic 'red plastic': dropped" not in done.stdout:
                failures.append(f"the changes are not printed: {done.stdout!r}")
            render = subprocess.run([pathlab, str(out), "-q", "-s", "1", "-d", "16x8", "-o", str(Path(scratch) / "x.png")],
                                    capture_output=True, text=True)
            if render.returncode != 0:
                failures.append(f"pathlab does not load the comparison scene: {render.stderr.strip()}")
        # Task 12's scene: the medium and its interface go across unchanged.
        cube = ROOT / "media/scenes/medium-cube.json"
        done = subprocess.run([sys.executable, str(TOOL), str(cube), "--scene-only", str(Path(scratch) / "cube.json")],
                              capture_output=True, text=True)
        if done.returncode != 0:
            failures.append(f"--scene-only on the medium cube failed: {done.stderr.strip()}")
        else:
            spec, original = json.loads((Path(scratch) / "cube.json").read_text()), json.loads(cube.read_text())
            if spec.get("media") != original["media"] or spec["materials"] != original["materials"]:
                failures.append(f"the medium cube's media or interface changed: {spec.get('media')} {spec['materials']}")
        for scene, reason in (("cornell-mirror-glass.json", "type 'mirror'"), ("cornell-spheres.json", "emission")):
            done = subprocess.run([sys.executable, str(TOOL), str(ROOT / "media/scenes" / scene), "--scene-only",
                                   str(Path(scratch) / "refused.json")], capture_output=True, text=True)
            if done.returncode == 0 or reason not in done.stderr:
                failures.append(f"{scene} is not refused for its {reason} (exit {done.returncode}: {done.stderr.strip()})")
        try:
            py_compile.compile(str(ROOT / "tools" / "perf" / "cycles_bridge.py"), cfile=str(Path(scratch) / "b.pyc"), doraise=True)
        except py_compile.PyCompileError as error:
            failures.append(f"tools/perf/cycles_bridge.py does not compile: {error}")
        if shutil.which("blender") is None:
            print("skipped: the end-to-end comparison (no blender on PATH; Debian: apt-get install blender)")
        else:
            done = subprocess.run([sys.executable, str(TOOL), str(ROOT / "media/scenes/roughness-sweep.json"),
                                   "--pathlab", pathlab, "--spp", "4", "--cycles-spp", "2", "--out", str(Path(scratch) / "run")],
                                  capture_output=True, text=True)
            if done.returncode != 0 or "largest |z|" not in done.stdout or "10x10-pixel blocks" not in done.stdout:
                failures.append(f"the end-to-end comparison failed: {done.stdout[-500:]} {done.stderr[-500:]}")
    for failure in failures:
        print(f"FAIL: {failure}")
    if not failures:
        print("ok: compare-cycles translates the roughness sweep and refuses what it cannot translate")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
