"""The web build (docs/web.md) against the native one: the `web` preset is
built into BUILD/tests/web-build (tools/web/build.py) and its pathlab runs
under Node.js, the JavaScript engine of Chromium, on the same WebAssembly a
page runs. Checked:
  - renders: the built-in Cornell box, an environment-lit scene (its map an
    EXR, read by tinyexr on the web) and a 69,120-triangle mesh, with the same
    seed, samples and threads, match the native renders: relMSE under 1e-4
    (measured: 1e-15 to 2e-7; a wrong seed, sampler or decoder gives 0.1 and
    more). Not bit for bit: the C libraries' sin, cos, exp and pow differ in
    the last bit, and a few paths out of millions then take another bounce.
  - images both ways: each program writes EXR, PNG and HDR, and each file
    lights a scene as its environment map in both: the two renders must
    match to a relMSE of 1e-8 (measured: about 1e-15), so the web's decoders
    read what OpenImageIO writes and the other way.
  - every sampling-lab warp: the web's verdict line and sample count are the
    native program's (the chi-square differs in the last digits, for the
    same reason as the renders).
  - bad input: a missing scene, a COLLADA scene (not read on the web), a
    corrupt image and an unsupported output give a message and exit 1,
    never a crash.
Without Emscripten or Node.js it says what to install and is skipped (77).

usage: test_web.py REPOSITORY BUILD_DIR"""
import json
import re
import subprocess
import sys
from pathlib import Path

root, build = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
sys.path.insert(0, str(root))  # the repository: the import root (docs/architecture.md)
from tools.web.build import PACKAGES, WebBuildError, build_web, missing_tools, node_command  # noqa: E402

SKIPPED = 77
MATCH = 1e-4  # relMSE between the native and the web render
DECODED_ALIKE = 1e-8  # relMSE between their renders lit by one map file
work = build / "tests" / "web"
failures = []


def check(ok: bool, message: str):
    if not ok:
        failures.append(message)
        print(f"FAIL: {message}")


def run(command: list, what: str) -> subprocess.CompletedProcess:
    done = subprocess.run(command, capture_output=True, text=True, timeout=600)
    print(f"  {what}: exit {done.returncode}")
    return done


def errors(output: str) -> tuple:
    """(RMSE, relMSE) of a --ref run's last line."""
    found = re.search(r"RMSE ([0-9.e+-]+), relMSE ([0-9.e+-]+)", output)
    return (float(found.group(1)), float(found.group(2))) if found else (float("nan"), float("nan"))


def web_against_native(native: list, web: list, arguments: list, name: str) -> tuple:
    """Renders `arguments` with the web build, then natively against that image (--ref): (the web's exit and
    stderr, the relMSE between the two renders; NaN when there is none)."""
    made = run([*web, *arguments, "-o", str(work / f"{name}-web.exr")], f"web render of {name}")
    compared = run([*native, *arguments, "-o", str(work / f"{name}-native.exr"), "--ref",
                    str(work / f"{name}-web.exr")], f"native render of {name} against it")
    _, relmse = errors(compared.stdout + compared.stderr)
    print(f"    {name}: relMSE {relmse:.3g} between native and web")
    return made, relmse


def check_renders(native: list, web: list):
    for scene in ("", "media/scenes/sky-spheres.json", "media/scenes/cornell-scan.json"):
        name = Path(scene).stem or "default"
        render = ([str(root / scene)] if scene else []) + ["-s", "8", "--seed", "5", "-t", "2", "-q"]
        made, relmse = web_against_native(native, web, render, name)
        check(made.returncode == 0, f"web render of {name}: exit {made.returncode}: {made.stderr[-800:]}")
        check(relmse < MATCH, f"{name}: the web render differs from the native one: relMSE {relmse} (at most {MATCH})")


def check_images_both_ways(native: list, web: list):
    """Each program's EXR, PNG and HDR as the environment map of a scene both render: a map the two decode
    alike gives renders as alike as the scenes above (relMSE about 1e-15); a decoder's mistake (a channel, a
    scale, 1/256 for 1/255) moves it by 1e-5 and more."""
    render = ["-s", "2", "--seed", "9", "-t", "2", "-q", "-d", "200x150"]
    for program, side in ((native, "native"), (web, "web")):
        for ext in ("exr", "png", "hdr"):
            made = run([*program, *render, "-o", str(work / f"map-{side}.{ext}")], f"{side} writes .{ext}")
            check(made.returncode == 0, f"{side} .{ext}: exit {made.returncode}: {made.stderr[-500:]}")
    scene = json.loads((root / "media/scenes/sky-spheres.json").read_text())
    for ext in ("exr", "png", "hdr"):
        for writer in ("native", "web"):
            scene["environment"] = {"image": str(work / f"map-{writer}.{ext}"), "scale": 1.0}
            lit = work / f"lit-by-{writer}-{ext}.json"
            lit.write_text(json.dumps(scene))
            made, relmse = web_against_native(native, web, [str(lit), *render], f"lit-by-{writer}-{ext}")
            check(made.returncode == 0 and relmse < DECODED_ALIKE,
                  f"{writer}'s .{ext} as a map: relMSE {relmse} between native and web (at most {DECODED_ALIKE}): "
                  f"the decoders disagree {made.stderr[-300:]}")


def verdict(output: str) -> list:
    return [line for line in output.splitlines() if re.match(r"(ACCEPTED|REJECTED)|\S+: \d+ samples", line)]


def check_lab(native: list, web: list):
    listed = run([*native, "lab", "--list"], "native lab --list")
    warps = [line.split()[0] for line in listed.stdout.splitlines() if line.strip()]
    check(len(warps) > 10, f"lab --list names {len(warps)} warps")
    web_list = run([*web, "lab", "--list"], "web lab --list")
    check(web_list.stdout == listed.stdout, "lab --list: the web's list is not the native one")
    for warp in warps:
        ours, theirs = (subprocess.run([*p, "lab", warp, "--no-figure"], capture_output=True, text=True, timeout=300)
                        for p in (native, web))
        same = ours.returncode == theirs.returncode and verdict(ours.stdout) == verdict(theirs.stdout) != []
        check(same, f"lab {warp}: native {verdict(ours.stdout)} (exit {ours.returncode}), web "
                    f"{verdict(theirs.stdout)} (exit {theirs.returncode}) {theirs.stderr[-300:]}")
    print(f"  lab: {len(warps)} warps, the same verdicts")


def check_bad_input(web: list):
    (work / "corrupt.png").write_bytes(b"\x89PNG\r\n\x1a\n" + b"\0" * 40)
    (work / "scene.dae").write_text("<COLLADA/>\n")
    cases = {"a missing scene": ([str(work / "missing.json")], "cannot open scene file"),
             "a COLLADA scene": ([str(work / "scene.dae")], "COLLADA"),
             "a corrupt image": (["-s", "1", "-q", "-o", str(work / "x.exr"), "--ref", str(work / "corrupt.png")],
                                 "corrupt.png"),
             "an unsupported output": (["-s", "1", "-q", "-o", str(work / "x.tiff")], "unsupported output format")}
    for what, (arguments, said) in cases.items():
        done = run([*web, *arguments], f"web, {what}")
        check(done.returncode == 1 and said in done.stderr and "Aborted" not in done.stderr,
              f"web, {what}: exit {done.returncode}, said {done.stderr[-400:]!r} (wanted exit 1 and '{said}')")


def main() -> int:
    if missing_tools():
        print(f"skipped: no {' or '.join(missing_tools())}: install {PACKAGES}")
        return SKIPPED
    work.mkdir(parents=True, exist_ok=True)
    try:
        program = build_web(build / "tests" / "web-build")
    except WebBuildError as e:
        print(f"FAIL: {e}")
        return 1
    native, web = [str(build / "pathlab")], node_command(program)
    check_renders(native, web)
    check_images_both_ways(native, web)
    check_lab(native, web)
    check_bad_input(web)
    print(f"{len(failures)} failed" if failures else "the web build renders, reads, writes and samples as the native one")
    return 1 if failures else 0


sys.exit(main())
