"""Judging mutants, for tools/mutate: the reviewed survivors, and the Lab
that builds a mutant's candidate and runs its suite on it."""
import hashlib
import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import tempfile
import threading
import time
from pathlib import Path

from tools import pathlab_tasks
from grader.driver import verdicts as verdict_format
from tools.validity.mutants import Mutant
from grader.driver.processes import link_command

ROOT = Path(__file__).resolve().parents[2]
REVIEWED = ROOT / "tests" / "mutants" / "survivors.txt"
SUBMISSION_FLAGS = pathlab_tasks.SUBMISSION_FLAGS  # compiled as tools/grade compiles a submission


# ---------------------------------------------------------------------------
# The reviewed list of survivors.

def read_reviewed(path=None, item="mutant", verdicts=("equivalent", "correct")):
    """{key: (verdict, reason)} from tests/mutants/survivors.txt (or conventions.txt: item "alternate")."""
    path = path or REVIEWED
    reviewed, entry = {}, {}
    if not path.exists():
        return reviewed

    keys = []

    def flush():
        if entry or keys:
            if not keys or {"verdict", "why"} - entry.keys() or entry["verdict"] not in verdicts:
                raise SystemExit(f"{path}: an entry needs one or more {item} lines, a verdict "
                                 f"({' or '.join(verdicts)}) and why: {keys} {entry}")
            for key in keys:
                if key in reviewed:
                    raise SystemExit(f"{path}: listed twice: {key}")
                reviewed[key] = (entry["verdict"], entry["why"])
            entry.clear()
            keys.clear()

    last = None
    for raw in path.read_text().splitlines() + [""]:
        if raw.startswith("#"):
            continue
        if not raw.strip():
            flush()
            continue
        if raw.startswith("  ") and last:
            entry[last] += " " + raw.strip()
            continue
        name, _, value = raw.partition(":")
        if name.strip() == item:
            keys.append(value.strip())
            last = None
        else:
            last = name.strip()
            entry[last] = value.strip()
    return reviewed


# ---------------------------------------------------------------------------
# Building and judging.

class Lab:
    def __init__(self, build: Path, timeout_factor: float = 10.0):
        self.build = build
        # A mutant's judge may run this many times the reference's suite time
        # (at least this many times 6 s) before it counts as killed.
        self.timeout_factor = timeout_factor
        if not (build / "build.ninja").exists():
            raise SystemExit(f"tools/mutate needs a Ninja build with the reference (cmake --preset default): "
                             f"no {build}/build.ninja")
        self.commands = json.loads((build / "compile_commands.json").read_text())
        self.cache = build / "mutate-cache"
        self.cache.mkdir(exist_ok=True)
        self.work = Path(tempfile.mkdtemp(prefix="pathlab-mutate-"))
        self.recipes = {}
        self.tasks = pathlab_tasks.tasks(ROOT)  # read once, not once per mutant
        self.recipe_locks = {}

    def prepare(self, tasks):
        """Builds each task's judge and reference candidate, in one Ninja run (two Ninja runs in one build
        folder at once would clash); the recipes are then made as the judges need them, in parallel."""
        folders = [self.tasks[n][0] for n in tasks]
        targets = [f"test-{f}" for f in folders] + [str(Path("tests") / f"candidate-{f}") for f in folders]
        built = subprocess.run(["cmake", "--build", str(self.build), "--target", *targets], capture_output=True, text=True)
        if built.returncode != 0:
            raise SystemExit(f"tools/mutate: building {' '.join(targets)} failed:\n"
                             f"{built.stdout[-3000:]}{built.stderr[-2000:]}")
        self.recipe_locks = {n: threading.Lock() for n in tasks}

    def recipe(self, task: int):
        """(compile argv, link argv, reference object, fingerprint, reference seconds) for a prepared task."""
        with self.recipe_locks[task]:  # one thread makes it; the task's other judges wait for it
            if task not in self.recipes:
                self.recipes[task] = self.make_recipe(task)
        return self.recipes[task]

    def make_recipe(self, task: int):
        folder, file_name = self.tasks[task]
        judge = self.build / "tests" / f"test-{folder}"
        candidate = str(Path("tests") / f"candidate-{folder}")  # the reference candidate, as ninja names it
        solution = str(ROOT / "solutions" / folder / file_name)
        entry = next((e for e in self.commands if e["file"] == solution), None)
        if entry is None:
            raise SystemExit(f"tools/mutate: {self.build} does not compile {solution} (configure with the reference)")
        compile_argv = shlex.split(entry["command"])
        reference_object = compile_argv[compile_argv.index("-o") + 1]
        link_argv = link_command(self.build, candidate)
        if reference_object not in link_argv:
            raise SystemExit(f"tools/mutate: the link of {candidate} does not name {reference_object}")
        digest = hashlib.sha256()
        for part in [judge, self.build / candidate]:
            digest.update(part.read_bytes())
        # The judge's data is part of it too: its noise ceilings and its reference images.
        suite_dir = ROOT / "tests" / folder
        for data in sorted(suite_dir.glob("reference-variances.txt")) + sorted(suite_dir.glob("images/**/*")):
            if data.is_file():
                digest.update(str(data.relative_to(suite_dir)).encode())
                digest.update(data.read_bytes())
        digest.update(" ".join(compile_argv + SUBMISSION_FLAGS).encode())
        start = time.time()
        reference = subprocess.run([str(judge), "--no-version", "--no-intro"], capture_output=True, text=True,
                                   env={**os.environ, verdict_format.CANDIDATE: str(self.build / candidate)}, cwd=self.work)
        seconds = time.time() - start
        if reference.returncode != 0:
            raise SystemExit(f"tools/mutate: the reference fails its own suite test-{folder}:\n{reference.stdout[-3000:]}")
        return compile_argv, link_argv, reference_object, digest.hexdigest(), seconds

    def judge(self, m: Mutant):
        """{'verdict': killed|survived|timeout|compile-error, 'test': ..., 'seconds': ...}, cached."""
        compile_argv, link_argv, reference_object, fingerprint, reference_seconds = self.recipe(m.task)
        key = hashlib.sha256((fingerprint + "\0" + m.source).encode()).hexdigest()
        cached = self.cache / f"{key}.json"
        if cached.exists():
            result = json.loads(cached.read_text())
            # A timeout under a shorter limit (CI's sample) is judged again under a longer one.
            if result["verdict"] != "timeout" or result.get("timeout_factor", 10.0) >= self.timeout_factor:
                result["cached"] = True
                return result
        folder, file_name = self.tasks[m.task]
        start = time.time()
        scratch = Path(tempfile.mkdtemp(prefix=f"{m.id}-", dir=self.work))
        try:
            source = scratch / file_name
            source.write_text(m.source)
            obj, exe = scratch / "task.o", scratch / "candidate"
            argv = list(compile_argv)
            argv[argv.index("-o") + 1] = str(obj)
            argv[argv.index("-c") + 1] = str(source)
            argv = [a for a in argv if a not in ("-Wall", "-Wextra", "-Wpedantic", "-Wshadow")] + ["-w"] + \
                SUBMISSION_FLAGS
            built = subprocess.run(argv, capture_output=True, text=True, cwd=self.build)
            if built.returncode != 0:
                result = {"verdict": "compile-error", "test": built.stderr.splitlines()[0] if built.stderr else ""}
            else:
                argv = [str(obj) if a == reference_object else a for a in link_argv]
                argv[argv.index("-o") + 1] = str(exe)
                linked = subprocess.run(argv, capture_output=True, text=True, cwd=self.build)
                if linked.returncode != 0:
                    result = {"verdict": "compile-error", "test": "link: " + linked.stderr[-300:]}
                else:
                    limit = self.timeout_factor * max(6.0, reference_seconds)
                    result = self.run_judge(folder, exe, scratch, limit)
                    if result["verdict"] == "timeout":
                        result["timeout_factor"] = self.timeout_factor
        finally:
            shutil.rmtree(scratch, ignore_errors=True)
        result["seconds"] = round(time.time() - start, 2)
        cached.write_text(json.dumps(result))
        return result

    def run_judge(self, folder, exe, cwd, limit):
        env = {k: v for k, v in os.environ.items() if not k.startswith("PATHLAB_")}
        env[verdict_format.CANDIDATE] = str(exe)
        process = subprocess.Popen([str(self.build / "tests" / f"test-{folder}"), "--abort-after=1", "--no-version",
                                    "--no-intro"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                   cwd=cwd, env=env, start_new_session=True)
        try:
            out, _ = process.communicate(timeout=limit)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.communicate()
            return {"verdict": "timeout", "test": f"no verdict after {limit:.0f} s"}
        if process.returncode == 0:
            return {"verdict": "survived", "test": ""}
        # The test case of the first failed check (a passing test's MESSAGE prints a TEST CASE line too).
        failed = [m.group(1) for block in out.split("=" * 79)
                  if re.search(r": (ERROR|FATAL ERROR): ", block)
                  for m in [re.search(r"^TEST CASE:\s*(.*)$", block, re.M)] if m]
        return {"verdict": "killed", "test": failed[0].strip() if failed else f"judge exit code {process.returncode}",
                "output": out[-3000:]}
