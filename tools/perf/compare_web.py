"""The web build's speed against the native renderer's: the same render of
the built-in Cornell box (or SCENE) by build/pathlab and by the web build's
pathlab.wasm under Node.js (V8, the engine of Chrome and Edge), on one
thread and on all cores, RUNS times each in turn; prints the medians of the
samples per second each render reports, their ratio, and the download's
size (the .wasm and its JavaScript, raw and gzip-compressed, as a server
sends them).

usage: tools/compare-web [--native build/pathlab] [--web-build build-web]
                         [--runs 3] [--spp 16] [SCENE]

The web build is made first (the `web` preset, tools/web/build.py). Node.js
stands in for the page: it runs the same WebAssembly on the same engine as
Chromium; what the browser adds (a canvas, its event loop) is outside the
render. Speed is measured here, never in a unit test (docs/web.md)."""
import argparse
import gzip
import json
import os
import statistics
import subprocess
import tempfile
from pathlib import Path

from tools.web.build import PACKAGES, ROOT, WebBuildError, build_web, missing_tools, node_command


def samples_per_second(command: list, scratch: Path) -> float:
    stats = scratch / "stats.json"
    done = subprocess.run([*command, "-q", "-o", str(scratch / "image.exr"), "--stats", str(stats)],
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"compare-web: {' '.join(command[:3])} failed (exit {done.returncode}): {done.stderr[-600:]}")
    return json.loads(stats.read_text())["samples_per_second"]


def download_size(program: Path) -> tuple:
    files = [program, program.with_suffix(".wasm"), program.with_name(program.stem + ".worker.js")]
    raw = sum(f.stat().st_size for f in files if f.exists())
    packed = sum(len(gzip.compress(f.read_bytes(), 9)) for f in files if f.exists())
    return raw, packed


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene", nargs="?")
    parser.add_argument("--native", default=str(ROOT / "build" / "pathlab"))
    parser.add_argument("--web-build", default=str(ROOT / "build-web"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--spp", type=int, default=16)
    args = parser.parse_args()
    if missing_tools():
        raise SystemExit(f"compare-web: no {' or '.join(missing_tools())}: install {PACKAGES}")
    if not Path(args.native).is_file():
        raise SystemExit(f"compare-web: no native renderer at {args.native} (cmake --build --preset release)")
    try:
        web = build_web(Path(args.web_build).resolve())
    except WebBuildError as e:
        raise SystemExit(f"compare-web: {e}")
    render = ([args.scene] if args.scene else []) + ["-s", str(args.spp), "--seed", "1"]
    cores = os.cpu_count() or 1
    print(f"{args.scene or 'the built-in Cornell box'}, {args.spp} spp, median of {args.runs} runs (samples per second)")
    with tempfile.TemporaryDirectory(prefix="pathlab-compare-web-") as scratch:
        for threads in sorted({1, cores}):
            rates = {"native": [], "web": []}
            for _ in range(args.runs):  # in turn, so a machine that slows down slows both alike
                rates["native"].append(samples_per_second([args.native, *render, "-t", str(threads)], Path(scratch)))
                rates["web"].append(samples_per_second([*node_command(web), *render, "-t", str(threads)],
                                                       Path(scratch)))
            native, page = statistics.median(rates["native"]), statistics.median(rates["web"])
            print(f"  {threads} thread{'s' if threads > 1 else ' '}  native {native:12,.0f}  web {page:12,.0f}  "
                  f"web/native {page / native:.2f}")
    raw, packed = download_size(web)
    print(f"download: {raw / 1e6:.2f} MB ({packed / 1e6:.2f} MB gzip-compressed): {web.name}, "
          f"{web.with_suffix('.wasm').name} and its worker")
    return 0
