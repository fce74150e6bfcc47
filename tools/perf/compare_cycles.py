"""Renders a PathLab scene in PathLab and in Blender's Cycles and compares
them region by region: an outside check of task 8's rough metal against a
production renderer's GGX (docs/microfacet-validation.md has a run), and of
task 12's media against Cycles' volumes (docs/media-validation.md).

usage: tools/compare-cycles SCENE.json [--pathlab build/pathlab] [--also LABEL=BINARY]
           [--spp N] [--cycles-spp N] [--max-depth M] [--out DIR] [--blender blender]
           [--environment IMAGE] [--environment-scale S]
       tools/compare-cycles SCENE.json --scene-only OUT.json   (step 1 alone; no Blender needed)

Needs Debian's `blender` (3.4, apt-get install blender); not part of CI.

What it does:
1. Makes the comparison scene, which both renderers model exactly:
   conductors become white (F0 = 1; Blender 3.4's Glossy BSDF has no Fresnel)
   and plastics are dropped (Cycles 3.4 has no such coat), each change printed;
   media (density and albedo) and interfaces become Cycles volumes;
   any other material or shape (emission, lights, OBJ files) is refused.
   --environment lights it with another map: Cycles 3.4 does not converge on
   sky-sun.exr's sun, 5 texels of radiance 5e4 (a diffuse ground lit by it
   alone is still 1.8 % too bright at 16,384 spp, where PathLab matches the
   map's exact irradiance to 1e-5): compare under media/envmaps/studio.exr.
2. Renders it twice with independent seeds in each renderer (PathLab with
   -m M, Cycles with M - 1 bounces: PathLab counts the camera ray's segment),
   and in each extra PathLab build given by --also (e.g. one whose task 8
   uses the separable masking Cycles uses).
3. Labels each pixel by the shape its centre sees (edge pixels left out) and
   prints, per region and channel, each renderer's mean, its standard error
   (from the two renders' difference) and z = difference / combined error.
   |z| < 3 in every row: the renders agree within noise. Then the same in
   10x10-pixel blocks (background and edges left out), finer than a shape:
   the largest |z| and how many pass 3, against the 0.27 % chance expects.
Writes DIR/compare.json, the renders (EXR and PNG) and a side-by-side PNG."""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BRIDGE = ROOT / "tools" / "perf" / "cycles_bridge.py"


def comparison_scene(scene_path: Path, environment_image: Path | None = None,
                     environment_scale: float | None = None) -> tuple[dict, list[str]]:
    spec = json.loads(scene_path.read_text())
    changes = []
    materials = spec.get("materials", {})
    dropped = set()
    for name, material in list(materials.items()):
        kind = material.get("type", "diffuse")
        if "emission" in material:
            sys.exit(f"compare-cycles: material {name!r}: emission has no exact translation here")
        if kind == "conductor":
            if material.get("f0") != [1, 1, 1]:
                changes.append(f"conductor {name!r}: F0 = 1 (was {material.get('f0') or 'eta and k'})")
            for key in ("eta", "k"):
                material.pop(key, None)
            material["f0"] = [1, 1, 1]
        elif kind == "plastic":
            changes.append(f"plastic {name!r}: dropped, with the shapes that use it")
            dropped.add(name)
            del materials[name]
        elif kind == "interface":
            pass  # a medium's index-matched boundary: a volume without a surface in Cycles
        elif kind == "diffuse":
            if isinstance(material.get("albedo"), str):
                sys.exit(f"compare-cycles: material {name!r}: textures have no translation here")
        else:
            sys.exit(f"compare-cycles: material {name!r}: type {kind!r} has no translation here")
    for name, medium in spec.get("media", {}).items():
        if "density" not in medium:
            sys.exit(f"compare-cycles: medium {name!r}: give density and albedo (sigma_a and sigma_s have no "
                     "translation here)")
    if spec.get("lights"):
        sys.exit("compare-cycles: point lights have no translation here")
    spec["spheres"] = [s for s in spec.get("spheres", []) if s.get("material") not in dropped]
    meshes = []
    for mesh in spec.get("meshes", []):
        if mesh.get("material") in dropped:
            continue
        if not ("quad" in mesh or "positions" in mesh) or "transform" in mesh:
            sys.exit("compare-cycles: only quads and untransformed inline meshes have a translation here")
        meshes.append(mesh)
    spec["meshes"] = meshes
    environment = spec.get("environment")
    if environment_image is not None:
        environment = spec["environment"] = {"image": environment_image.name, "scale": environment.get("scale", 1.0)}
        changes.append(f"environment: {environment_image}")
        environment["image"] = str(environment_image.resolve())
    elif environment and "image" in environment:
        environment["image"] = str((scene_path.parent / environment["image"]).resolve())
    if environment_scale is not None:
        environment["scale"] = environment_scale
        changes.append(f"environment scale: {environment_scale}")
    return spec, changes


def run(command: list[str], what: str, env: dict | None = None) -> None:
    done = subprocess.run(command, capture_output=True, text=True, env=env)
    if done.returncode != 0:
        sys.exit(f"compare-cycles: {what} failed (exit {done.returncode}):\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene", type=Path)
    parser.add_argument("--pathlab", default=str(ROOT / "build" / "pathlab"))
    parser.add_argument("--also", action="append", default=[], metavar="LABEL=BINARY")
    parser.add_argument("--spp", type=int, default=4096, help="PathLab's samples per pixel, per render")
    parser.add_argument("--cycles-spp", type=int, default=1024, help="Cycles' samples per pixel, per render")
    parser.add_argument("--max-depth", type=int, default=8)
    parser.add_argument("--out", type=Path, default=Path("cycles-comparison"))
    parser.add_argument("--blender", default="blender")
    parser.add_argument("--environment", type=Path, metavar="IMAGE", help="light the scene with this map instead")
    parser.add_argument("--environment-scale", type=float, metavar="S")
    parser.add_argument("--scene-only", type=Path, metavar="OUT.json", help="write the comparison scene and stop")
    args = parser.parse_args()
    if args.scene_only:
        spec, changes = comparison_scene(args.scene, args.environment, args.environment_scale)
        print("\n".join(f"comparison scene: {change}" for change in changes))
        args.scene_only.write_text(json.dumps(spec, indent=1))
        return 0
    if shutil.which(args.blender) is None:
        sys.exit(f"compare-cycles: no {args.blender!r} on PATH (Debian: apt-get install blender)")
    args.out.mkdir(parents=True, exist_ok=True)
    spec, changes = comparison_scene(args.scene, args.environment, args.environment_scale)
    for change in changes:
        print(f"comparison scene: {change}")
    scene = args.out / "scene.json"
    scene.write_text(json.dumps(spec, indent=1))

    pathlabs = {"pathlab": args.pathlab}
    for also in args.also:
        label, _, binary = also.partition("=")
        pathlabs[label] = binary
    runs = []
    for label, binary in pathlabs.items():
        files = []
        for seed in (1, 2):
            image = args.out / f"{label}-{seed}.exr"
            run([binary, str(scene), "-q", "-s", str(args.spp), "-m", str(args.max_depth), "--seed", str(seed),
                 "-o", str(image)], f"{label} (seed {seed})")
            files.append(str(image))
            print(f"rendered {image}", flush=True)
        runs.append(f"{label}={','.join(files)}")
    blender = [args.blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python", str(BRIDGE), "--"]
    # Debian's Blender embeds the system's Python, which finds its home through
    # the first python3 on PATH: a pyenv or conda one first hides numpy from it.
    blender_env = {**os.environ, "PATH": "/usr/bin:" + os.environ.get("PATH", "")}
    files = []
    for seed in (1, 2):
        image = args.out / f"cycles-{seed}.exr"
        run(blender + ["render", str(scene), str(image), str(args.cycles_spp), str(seed), str(args.max_depth - 1)],
            f"Cycles (seed {seed})", blender_env)
        files.append(str(image))
        print(f"rendered {image}", flush=True)
    runs.append(f"cycles={','.join(files)}")
    report = args.out / "compare.json"
    run(blender + ["compare", str(report), str(scene), *runs], "the comparison", blender_env)

    results = json.loads(report.read_text())
    names = {-1: "background"}
    names.update({i: f"sphere {i} ({s.get('material', 'default')})" for i, s in enumerate(spec.get("spheres", []))})
    names.update({100 + j: f"mesh {j} ({m.get('material', 'default')})" for j, m in enumerate(spec.get("meshes", []))})
    labels = [label for label in pathlabs] + ["cycles"]
    worst = 0.0
    print(f"\n{'region':28s} {'pixels':>7s} ch " + " ".join(f"{label + ' mean ± se':>22s}" for label in labels)
          + " " + " ".join(f"{'z ' + label:>10s}" for label in pathlabs))
    for key, entry in results["regions"].items():
        for c, channel in enumerate("rgb"):
            cells = [f"{entry[l]['mean'][c]:11.5f} ± {entry[l]['stderr'][c]:8.5f}" for l in labels]
            zs = []
            for label in pathlabs:
                a, b = entry[label], entry["cycles"]
                z = (a["mean"][c] - b["mean"][c]) / max(math.hypot(a["stderr"][c], b["stderr"][c]), 1e-12)
                zs.append(f"{z:10.2f}")
                if label == "pathlab" and int(key) != -1:
                    worst = max(worst, abs(z))
            print(f"{names.get(int(key), key):28s} {entry['pixels']:7d} {channel}  " + " ".join(cells) + " " + " ".join(zs))
    print(f"\nlargest |z| of pathlab against Cycles outside the background: {worst:.2f}")
    for label, block in results.get("blocks", {}).items():
        print(f"{label} against Cycles in {block['count']} {block['size']}x{block['size']}-pixel blocks x channels: "
              f"largest |z| {block['max_abs_z']:.2f}, rms z {block['rms_z']:.2f}, {block['beyond_3']} beyond 3 "
              f"({0.0027 * block['count']:.1f} expected by chance)")
    return 0
