"""The write-up: a web page and a PDF made from your own build.

  python3 tools/writeup            your build: BUILD/writeup/writeup.html and writeup.pdf (BUILD: build/ in
                                   the course repository, build-student/ in a student release)
  python3 tools/writeup --stubs    the same for the untouched stubs (what every student starts from)

For each task: the renders and debugger views that show it working (the
course's scenes at the settings written under each picture, with the
command, which code ran, the time, samples/s and NaN count), your renders
beside the test suites' stored reference images (a slider; the suites' own
verdict), and your text from writeup/NN-name.md under the course's prompts.
Then a convergence figure (error against samples and against time, per
sampling strategy your build supports) and the speed table. A task that is
not done yet gets a box saying so, never a broken picture.

The page needs nothing at view time (every image is inside it); the PDF is
the page printed by headless Chromium (Debian: apt-get install chromium),
for Gradescope's PDF upload. About two minutes on two cores.

  --program PATH     another pathlab of the build to show (default: BUILD/pathlab; --stubs: BUILD/pathlab-stubs)
  --build DIR        the build folder (default: the preset's folder, configured if missing)
  --preset NAME      the preset (default: student in a student release, release in the course repository)
  --out DIR          where the page and PDF go (default: BUILD/writeup)
  --tasks 1,2        only these tasks' sections (default: every task the course hands out)
  --no-pdf           the page only
  --no-convergence   skip the convergence figure (about 40 s)
  --browser PATH     the Chromium or Chrome to print with (default: found on PATH and the usual places)
"""
import argparse
import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from tools import pathlab_tasks

ROOT = pathlab_tasks.ROOT
if importlib.util.find_spec("markdown") is None:  # (writeup_page uses it)
    # Debian's python3-markdown is on /usr/bin/python3's path; a pyenv or venv python3 first on PATH lacks it.
    if Path("/usr/bin/python3").exists() and sys.executable != "/usr/bin/python3" and not os.environ.get("PATHLAB_REEXEC"):
        os.environ["PATHLAB_REEXEC"] = "1"
        os.execv("/usr/bin/python3", ["/usr/bin/python3", *sys.argv])
    sys.exit("writeup: needs Python-Markdown (Debian: apt-get install python3-markdown; elsewhere: pip install markdown)")
from tools.docs import writeup_page
from tools.docs.writeup_page import data_uri  # noqa: E402


# What each task's section shows: its task.json's "writeup" figures
# (tools/pathlab_tasks.py), each (kind, arguments, caption). "render" runs
# `pathlab ARGS` and reports its numbers; "view" runs `pathlab debug --task N
# ARGS` and shows what it prints. Scenes are the course's (media/scenes); the
# settings are in the arguments, so a caption is the exact command.
def figures(number: int) -> list:
    return [(f["kind"], f["args"] if f["kind"] == "render" else f"--task {number} {f['args']}", f["caption"])
            for f in pathlab_tasks.manifest(number, ROOT)["writeup"]]


# The convergence figure: a path tracer (tasks 1-5) on the spheres box, at half size so the
# reference it is measured against (the build's own render at many samples) takes seconds.
CONVERGENCE_SCENE = "media/scenes/cornell-spheres.json"
CONVERGENCE_TASKS = [1, 2, 3, 4, 5]
CONVERGENCE_STRATEGIES = "reference,uniform-hemisphere,no-nee"  # tasks 4 and 5's pieces only (MIS is task 9's figure)
CONVERGENCE_BUDGET = 3.0        # render seconds per strategy
CONVERGENCE_REFERENCE_SPP = 512


class Progress:
    """A bar that rewrites itself on a terminal; one line per step in a log."""

    def __init__(self, steps):
        self.steps, self.done, self.start = steps, 0, time.time()
        self.tty = sys.stdout.isatty()

    def step(self, text):
        self.done += 1
        width = 30
        filled = width * min(self.done, self.steps) // max(1, self.steps)
        line = f"[{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.steps} {time.time() - self.start:5.0f} s  {text}"
        if self.tty:
            print("\r\033[K" + line[:shutil.get_terminal_size().columns - 1], end="", flush=True)
        else:
            print(line, flush=True)

    def finish(self):
        if self.tty:
            print()


def run(command, cwd=ROOT, timeout=600):
    """(exit code, stdout, stderr, seconds): a program that fails is a result, not an exception."""
    start = time.time()
    try:
        p = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout, p.stderr, time.time() - start
    except subprocess.TimeoutExpired:
        return 124, "", f"timed out after {timeout} s", time.time() - start
    except OSError as e:
        return 127, "", str(e), time.time() - start


def first_error(stderr, stdout=""):
    """The line that says why a program failed (a TODO left, an error), without the program's name."""
    lines = [l.strip() for l in (stderr + "\n" + stdout).splitlines() if l.strip()]
    for l in lines:
        if "not implemented" in l or "error" in l.lower():
            return re.sub(r"^pathlab(-bench)?: ", "", l)
    return re.sub(r"^pathlab(-bench)?: ", "", lines[0]) if lines else "no output"


def png_size(path: Path):
    head = path.read_bytes()[:24]
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def student_file(build: Path, folder: str, name: str) -> Path:
    """Where the build took task files from: PATHLAB_STUDENT_DIR (a tasks/ tree or flat), else tasks/."""
    student_dir = None
    cache = build / "CMakeCache.txt"
    if cache.exists():
        m = re.search(r"^PATHLAB_STUDENT_DIR:PATH=(.*)$", cache.read_text(errors="replace"), re.M)
        if m and m.group(1):
            student_dir = Path(m.group(1))
    for candidate in ([student_dir / folder / name, student_dir / name] if student_dir else []) + [ROOT / "tasks" / folder / name]:
        if candidate.exists():
            return candidate
    return ROOT / "tasks" / folder / name


def todos_left(path: Path):
    """[(line, tag)] of the PATHLAB_TODO calls left outside comments."""
    left = []
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        if line.lstrip().startswith("//"):
            continue
        m = re.search(r'PATHLAB_TODO\("([^"]*)"', line)
        if m:
            left.append((number, m.group(1)))
    return left


def ownership(program: Path):
    """{task: "student" | "reference"} from `pathlab --version`."""
    code, out, err, _ = run([str(program), "--version"])
    if code != 0:
        raise SystemExit(f"writeup: {program} --version failed: {first_error(err, out)}")
    return {int(n): who for n, who in re.findall(r"(\d+):(\w+)", out.split("(tasks", 1)[-1])}


def preset_folder(preset: str) -> Path:
    presets = json.loads((ROOT / "CMakePresets.json").read_text())["configurePresets"]
    found = [p for p in presets if p["name"] == preset]
    if not found:
        raise SystemExit(f"writeup: no preset {preset!r} in CMakePresets.json")
    return Path(found[0]["binaryDir"].replace("${sourceDir}", str(ROOT))).resolve()


def ensure_build(build: Path, targets, preset: str):
    if not (build / "CMakeCache.txt").exists():
        if build != preset_folder(preset):
            raise SystemExit(f"writeup: {build} is not a configured build folder")
        print(f"writeup: configuring {build.name}/ (cmake --preset {preset})", flush=True)
        subprocess.run(["cmake", "--preset", preset], cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    # A build configured without the tests has no suites: their comparisons say so instead.
    listing = subprocess.run(["cmake", "--build", str(build), "--target", "help"], cwd=ROOT, capture_output=True,
                             text=True).stdout
    known = {line.split(":")[0].strip() for line in listing.splitlines() if ":" in line}
    targets = [t for t in targets if t in known or not t.startswith(("test-", "candidate-"))]
    print(f"writeup: building {', '.join(targets)} in {build}", flush=True)
    p = subprocess.run(["cmake", "--build", str(build), "--parallel", str(os.cpu_count() or 2), "--target", *targets],
                       cwd=ROOT, capture_output=True, text=True)
    if p.returncode != 0:
        tail = "\n".join((p.stdout + p.stderr).splitlines()[-30:])
        raise SystemExit(f"writeup: the build failed; fix it first:\n{tail}")


def make_figure(kind, arguments, caption, program, work: Path, index):
    """One picture with its numbers, or the reason it could not be made."""
    png = work / f"figure-{index}.png"
    args = arguments.split()
    if kind == "render":
        stats = work / f"figure-{index}.json"
        command = [str(program), *args, "-q", "-o", str(png), "--stats", str(stats)]
    else:
        command = [str(program), "debug", *args, "-o", str(png)]
    code, out, err, seconds = run(command)
    shown = "./build/pathlab " + ("debug " if kind == "view" else "") + arguments
    figure = {"kind": kind, "command": shown, "caption": caption, "seconds": seconds}
    if code != 0 or not png.exists():
        figure["error"] = first_error(err, out)
        return figure
    try:
        figure["image"], figure["size"] = data_uri(png), png_size(png)
    except ValueError as error:
        figure["error"] = str(error)
        return figure
    if kind == "render":
        figure["stats"] = json.loads(stats.read_text())
    else:
        # What the view prints about itself (statistics, the inspected pixel): the first lines, not every sample.
        lines = [l for l in out.splitlines()[1:] if l.strip()]
        figure["printed"] = "\n".join(lines[:6]) + (f"\n… ({len(lines) - 6} more lines)" if len(lines) > 6 else "")
    return figure


def image_comparisons(build: Path, folder: str, work: Path):
    """The suite's image tests, your render beside the stored reference: [{name, yours, reference, z, verdict}]."""
    suite = build / "tests" / f"test-{folder}"
    if not suite.exists():
        return [], f"no test program {suite.name} in this build"
    listed = subprocess.run([str(suite), "--list-test-cases", "--test-case=*image:*", "--no-version"],
                            capture_output=True, text=True, timeout=60)
    if listed.returncode == 0 and "image:" not in listed.stdout:
        return [], writeup_page.NO_IMAGE_TESTS
    pictures = work / f"images-{folder}"
    pictures.mkdir()
    stats = work / f"image-stats-{folder}.txt"
    env = dict(os.environ, PATHLAB_IMAGE_PICTURES="always", PATHLAB_IMAGE_FAILURES_DIR=str(pictures),
               PATHLAB_IMAGE_STATS=str(stats))
    start = time.time()
    p = subprocess.run([str(suite), "--test-case=*image:*", "--no-version"], cwd=build / "tests", env=env,
                       capture_output=True, text=True, timeout=600)
    verdicts = {}
    if stats.exists():
        for line in stats.read_text().splitlines():
            fields = line.split()
            name = fields[0].split("/", 1)[1]
            # name, worst block |z|, whole-image |z|, limit, three noise ratios, NaN or Inf samples, passed
            verdicts[name] = {"worst_z": max(float(fields[1]), float(fields[2])), "limit": float(fields[3]),
                              "non_finite": int(fields[7]) if len(fields) > 8 else 0,
                              "pass": fields[8] == "1" if len(fields) > 8 else None}
    found = []
    for yours in sorted(pictures.glob(f"{folder}-*-yours.png")):
        name = yours.name[len(folder) + 1:-len("-yours.png")]
        reference, z = yours.with_name(f"{folder}-{name}-reference.png"), yours.with_name(f"{folder}-{name}-z.png")
        if not reference.exists():
            continue
        try:
            found.append({"name": name, "yours": data_uri(yours), "reference": data_uri(reference),
                          "z": data_uri(z) if z.exists() else None, "size": png_size(yours),
                          "verdict": verdicts.get(name)})
        except ValueError:
            continue  # not shown; a comparison with no picture is the suite's verdict alone
    if not found:
        return [], first_error(p.stderr, p.stdout) if p.returncode != 0 else "the image tests drew no pictures"
    return found, f"{time.time() - start:.1f} s"


def convergence(program_dir: Path, work: Path, threads):
    """Error against samples and time per strategy (pathlab-bench converge), at half the scene's size."""
    bench = program_dir / "pathlab-bench"
    scene = json.loads((ROOT / CONVERGENCE_SCENE).read_text())
    render = scene.setdefault("render", {})
    render["width"], render["height"] = render.get("width", 400) // 2, render.get("height", 300) // 2
    small = work / f"{Path(CONVERGENCE_SCENE).stem}-{render['width']}x{render['height']}.json"  # refers to no other file
    small.write_text(json.dumps(scene))
    out = work / "convergence"
    command = [str(bench), "converge", str(small), "--strategies", CONVERGENCE_STRATEGIES,
               "--budget", str(CONVERGENCE_BUDGET), "--reference-spp", str(CONVERGENCE_REFERENCE_SPP),
               "--out", str(out), "--json"]
    if threads:
        command += ["--threads", str(threads)]
    code, stdout, err, seconds = run(command, timeout=900)
    pngs = sorted(out.glob("*-converge.png"))
    if code != 0 or not pngs:
        return {"error": first_error(err, stdout), "seconds": seconds}
    try:
        result = json.loads(stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        return {"error": "pathlab-bench converge printed no result", "seconds": seconds}
    table = [{"name": st["name"], "efficiency": st.get("efficiency", 0.0), "slope": st.get("slope", 0.0),
              "relies_on": sorted(int(t) for t in st.get("relies_on", {})), "default": st.get("default", False)}
             for st in result.get("strategies", []) if st.get("available")]
    return {"image": data_uri(pngs[0]), "size": png_size(pngs[0]), "seconds": seconds, "table": table,
            "summary": result.get("comparison", ""), "reference_spp": CONVERGENCE_REFERENCE_SPP,
            "command": f"./build/pathlab-bench converge {CONVERGENCE_SCENE} (at {render['width']}x{render['height']}) "
                       f"--strategies {CONVERGENCE_STRATEGIES} --budget {CONVERGENCE_BUDGET:g} "
                       f"--reference-spp {CONVERGENCE_REFERENCE_SPP}"}


def find_browser(given):
    if given:
        return given
    for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable", "chrome", "msedge"):
        if shutil.which(name):
            return shutil.which(name)
    for path in ("/Applications/Chromium.app/Contents/MacOS/Chromium",
                 "/Applications/Google Chrome.app/Contents/MacOS/Google Chrome",
                 r"C:\Program Files\Google\Chrome\Application\chrome.exe",
                 r"C:\Program Files (x86)\Microsoft\Edge\Application\msedge.exe"):
        if Path(path).exists():
            return path
    return None


def browser_flags():
    """Chromium's sandbox cannot start as root (CI, containers); a user's browser keeps it."""
    flags = ["--headless", "--disable-gpu", "--no-first-run", "--no-default-browser-check", "--hide-scrollbars"]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        flags.append("--no-sandbox")
    return flags


def print_pdf(browser, page: Path, pdf: Path):
    with tempfile.TemporaryDirectory(prefix="pathlab-chromium-") as profile:
        command = [browser, *browser_flags(), f"--user-data-dir={profile}", "--no-pdf-header-footer",
                   f"--print-to-pdf={pdf}", page.resolve().as_uri()]
        if pdf.exists():
            pdf.unlink()
        code, out, err, seconds = run(command, timeout=300)
    if not pdf.exists():
        raise SystemExit(f"writeup: {Path(browser).name} did not print the PDF (exit {code}): {first_error(err, out)}")
    return seconds


def main() -> int:
    parser = argparse.ArgumentParser(prog="tools/writeup", description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", help="the build folder (default: the preset's)")
    parser.add_argument("--preset", help="the CMake preset whose folder to use (default: student in a student "
                                         "release, release in the course repository)")
    parser.add_argument("--out")
    parser.add_argument("--stubs", action="store_true", help="the untouched stubs (the build's pathlab-stubs)")
    parser.add_argument("--program", help="another pathlab of this build (e.g. its tests' pathlab-mixed)")
    parser.add_argument("--tasks", help="only these tasks, e.g. 1,2")
    parser.add_argument("--no-pdf", action="store_true")
    parser.add_argument("--no-convergence", action="store_true")
    parser.add_argument("--threads", type=int, default=0, help="render threads (default: all cores)")
    parser.add_argument("--browser")
    args = parser.parse_args()
    # A student release has no solutions/: its students build with the student preset (build-student/).
    preset = args.preset or ("release" if (ROOT / "solutions").is_dir() else "student")
    build = Path(args.build).resolve() if args.build else preset_folder(preset)
    program_name = "pathlab-stubs" if args.stubs else "pathlab"
    program = Path(args.program).resolve() if args.program else build / program_name
    out = Path(args.out).resolve() if args.out else build / ("writeup" if program.name == "pathlab" else "writeup-" + program.name.removeprefix("pathlab-"))
    every = pathlab_tasks.tasks()
    # By default the course's tasks (a student release's tasks/handed-out.txt; elsewhere every task).
    chosen = pathlab_tasks.parse_task_list(args.tasks, every, "writeup: --tasks") if args.tasks else pathlab_tasks.handed_out()
    if why := pathlab_tasks.not_handed_out(chosen):
        raise SystemExit(f"writeup: {why}")
    browser = None if args.no_pdf else find_browser(args.browser)
    if not args.no_pdf and not browser:
        raise SystemExit("writeup: no Chromium or Chrome to print the PDF with (Debian: apt-get install chromium; "
                         "or --browser PATH, or --no-pdf for the page alone)")

    ensure_build(build, ([] if args.program else [program_name]) + ["pathlab", "pathlab-bench"] + [f"test-{every[n][0]}" for n in chosen] +
                 [f"candidate-{every[n][0]}" for n in chosen], preset)
    if not program.exists():
        raise SystemExit(f"writeup: no program {program}")
    owners = ownership(program)
    # The suites' candidates link the build's own choice per task: their renders are this program's only where it agrees.
    suites_owners = owners if program == build / "pathlab" else ownership(build / "pathlab")
    out.mkdir(parents=True, exist_ok=True)
    figures_total = sum(len(figures(n)) + 1 for n in chosen)
    progress = Progress(figures_total + (0 if args.no_convergence else 1) + (0 if args.no_pdf else 1) + 1)
    started = time.time()
    sections = []
    with tempfile.TemporaryDirectory(prefix="pathlab-writeup-") as scratch:
        work = Path(scratch)
        index = 0
        for n in chosen:
            folder, name = every[n]
            source = student_file(build, folder, name) if owners.get(n) == "student" else None
            todos = todos_left(source) if source else []
            section = {"number": n, "folder": folder, "owner": owners.get(n, "?"),
                       "file": str(source.relative_to(ROOT)) if source and source.is_relative_to(ROOT) else str(source or f"solutions/{folder}/{name}"),
                       "todos": todos, "figures": [], "comparisons": [], "comparison_note": ""}
            if args.stubs and owners.get(n) != "student":
                raise SystemExit(f"writeup: {program_name} links the reference for task {n}")
            if todos:
                progress.done += len(figures(n))
                progress.step(f"task {n}: not implemented yet ({len(todos)} TODOs left)")
            else:
                for kind, arguments, caption in figures(n):
                    index += 1
                    section["figures"].append(make_figure(kind, arguments, caption, program, work, index))
                    progress.step(f"task {n}: {arguments}")
                if suites_owners.get(n) == owners.get(n):
                    section["comparisons"], section["comparison_note"] = image_comparisons(build, folder, work)
                else:
                    section["comparison_note"] = (f"this build's test programs link the {suites_owners.get(n)} for "
                                                  f"task {n}, not the code shown here")
                progress.step(f"task {n}: your renders against the reference images")
            section["text"] = writeup_page.student_text(ROOT / "writeup" / f"{folder}.md")
            sections.append(section)
        converge = None
        if not args.no_convergence:
            missing = [n for n in CONVERGENCE_TASKS if n in every and (
                owners.get(n) == "student" and todos_left(student_file(build, *every[n])))]
            if missing:
                converge = {"error": "needs a path tracer: task" + ("s " if len(missing) > 1 else " ") +
                            ", ".join(map(str, missing)) + " not implemented yet", "seconds": 0.0}
            else:
                converge = convergence(build, work, args.threads)
            progress.step("convergence: error against samples and time")
        page = out / "writeup.html"
        page.write_text(writeup_page.page(sections, converge, owners, {
            "program": program.name, "build": str(build), "seconds": time.time() - started,
            "date": time.strftime("%Y-%m-%d %H:%M"), "stubs": args.stubs}), encoding="utf-8")
        progress.step(f"wrote {page}")
    pdf = out / "writeup.pdf"
    if not args.no_pdf:
        print_pdf(browser, page, pdf)
        progress.step(f"printed {pdf}")
    progress.finish()
    print(f"writeup: {page}" + ("" if args.no_pdf else f"\nwriteup: {pdf}") + f"  ({time.time() - started:.0f} s)")
    return 0
