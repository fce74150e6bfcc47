"""What tools/grade (the grader, in its sandbox) and tools/check (a
student's own check, no sandbox) share, so the two cannot drift apart:
finding the task files in a submission, the compile rules (each task file
alone, only the framework's headers and the compiler's own, no inline
assembly: building.py), the judges, the points, the time budgets and
results.json.

Grader(options, sandbox).grade(submission, tasks) grades; the sandbox is
sandbox.Sandbox for tools/grade, Unsandboxed for tools/check."""
import json
import os
import re
import shlex
import shutil
import sys
import tempfile
import time
import zipfile
from pathlib import Path

from tools import pathlab_tasks  # the task list: the tasks/NN-name folders
from . import verdicts  # what a judge tells the grader: grader/suite/verdicts.json
from .building import CandidateBuilder, build_target, memory_watch
from .processes import clip, run
from .sandbox import JUDGE_MEMORY
from .submission import find_task_files, unpack_zip

ROOT = Path(__file__).resolve().parents[2]
TASKS = pathlab_tasks.tasks()  # {n: (folder, file)}: the tasks/NN-name folders
# The limits of a grade (tools/grade's defaults, so Gradescope's; tools/check's).
TEST_TIMEOUT = 60.0          # seconds per test case
TASK_BUDGET = 300.0          # seconds for one task: compiling and all its tests
SUBMISSION_BUDGET = 1200.0   # seconds for the whole submission


def task_numbers(text: str, program: str):
    """--tasks "1,2,8" -> [1, 2, 8] in the order given, or None (with the error printed) unless each is a task."""
    try:
        tasks = [int(t) for t in text.split(",") if t.strip()]
        if tasks and all(t in TASKS for t in tasks):
            return tasks
    except ValueError:
        pass
    print(f"{program}: --tasks must list task numbers {min(TASKS)}-{max(TASKS)}, got '{text}'", file=sys.stderr)
    return None


def judge_manifest(build: Path, task: int):
    """(name, points, visibility) of task's test cases, from the judge's own listing (build/tests/test-NN-name)."""
    directory, _ = TASKS[task]
    code, listing = run([str(build / "tests" / f"test-{directory}"), "--list-test-cases"], timeout=60)
    cases = verdicts.parse_listing(listing)
    if not cases:
        raise RuntimeError(f"the judge test-{directory} listed no test cases:\n{clip(listing, 2000)}")
    return cases


class Unsandboxed:
    """tools/check's stand-in for the sandbox: the student's own code on the
    student's own machine runs as the student, with no limits but the time
    budgets (the same interface as sandbox.Sandbox, doing nothing)."""
    mode, root, warning, confine = "none", False, "", None

    def command(self, argv, scratch, **_):
        return list(argv)

    def path(self, scratch: Path, real: Path) -> str:
        return str(real)

    def out_path(self, writable: Path, real: Path) -> str:
        return str(real)

    def give(self, path): pass
    def protect(self, paths): pass
    def deny_shared_folders(self): pass
    def restore(self): pass
    def clean_up(self, stale=False): pass


class Grader:
    """options: out, build_dir, timeout, task_budget, budget, sanitize,
    fail_under (tools/grade's command-line options); sandbox: where
    untrusted commands run; say: where progress lines go."""

    def __init__(self, args, sandbox, say=None):
        self.args = args
        self.say = say or (lambda text, progress=False: progress or print(text, flush=True))
        self.start = time.time()
        self.results = []
        self.notes = []  # what the submission's archive left out
        self.leaderboard = {}  # name: entry; measured by the judges (LEADERBOARD lines), ungraded
        self.total = 0.0
        self.build = Path(args.build_dir).resolve()
        self.objects = self.build / "submission-objects"
        self.work = Path(tempfile.mkdtemp(prefix="pathlab-grade-"))
        os.chmod(self.work, 0o711)  # the sandbox uid may enter its own scratch folders, list nothing
        self.verdicts = Path(tempfile.mkdtemp(prefix="verdicts-", dir=self.work))  # 0700: the judge's only
        self.sandbox = sandbox
        self.isolation_checked = False
        self.builder = None  # CandidateBuilder, once configure() knows the build's folders
        # The judge's memory limit (sandbox.JUDGE_MEMORY); not under
        # sanitizers, whose shadow memory is the judge's own memory too.
        self.judge_memory = None if getattr(args, "sanitize", "") else JUDGE_MEMORY
        # Pictures of failed image tests (the student's render, the reference,
        # a z-score map), written by the judge next to results.json.
        out = Path(args.out).resolve()
        self.pictures = out.parent / f"{out.stem}-images"
        if self.pictures.is_dir():
            for old in self.pictures.glob("*.png"):
                old.unlink()

    def record(self, task, name, score, points, output, status=None, visibility="visible", timing=None):
        """timing: (seconds the test took, its time limit), for a test that ran."""
        self.total += score
        result = {
            "name": f"Task {task}: {name}",
            "score": score,
            "max_score": points,
            "status": status or ("passed" if score >= points else "failed"),
            "output": clip(output),
            "visibility": visibility,
        }
        if timing:  # Gradescope keeps extra_data without showing it; tools/check shows it
            result["extra_data"] = {"seconds": round(timing[0], 2), "time_limit": round(timing[1], 2)}
        self.results.append(result)

    def manifest(self, task):
        return judge_manifest(self.build, task)

    def prepare_sandbox(self):
        """uid mode: pathlab-confine (no sockets, no IPC) where the sandbox uid
        can run it, and the world-writable folders closed to that uid."""
        if self.sandbox.mode == "uid" and self.sandbox.root:
            ok, out = build_target(self.build, "pathlab-confine")
            binary = self.build / "grader" / "confine" / "pathlab-confine"
            if ok and binary.exists():
                folder = self.work / "confine"
                folder.mkdir()
                os.chmod(folder, 0o755)
                shutil.copy(binary, folder / binary.name)
                os.chmod(folder / binary.name, 0o755)
                self.sandbox.confine = str(folder / binary.name)
                code, out = run(self.sandbox.command(["/bin/true"], scratch=None), timeout=20)
                if code != 0:  # a container that forbids seccomp filters too
                    self.sandbox.confine = None
                    self.sandbox.warning += ("; seccomp filters are not allowed here, so the candidate may open "
                                             "sockets and System V IPC: " + clip(out, 300))
            else:
                self.sandbox.warning += ("; pathlab-confine was not built (install libseccomp-dev), so the "
                                         "candidate may open sockets and System V IPC")
        self.sandbox.deny_shared_folders()

    def check_isolation(self, judge: Path):
        """The sandbox must not reach the reference, the suites or the judge,
        nor (uid mode, pathlab-confine) open a socket."""
        self.isolation_checked = True
        if self.sandbox.mode == "none":
            return
        if self.sandbox.confine:  # (bubblewrap: a network namespace of its own)
            code, out = run(self.sandbox.command(["/usr/bin/python3", "-c", "import socket; socket.socket()"],
                                                 scratch=None), timeout=20)
            if code == 0:
                raise RuntimeError("isolation check failed: code in the sandbox can open a socket")
        # The listener and the judge are in every grader's tree; the reference's source only in the course's.
        listener = ROOT / "grader" / "suite" / "listener.cpp"
        if not listener.exists():
            raise RuntimeError(f"isolation check: {listener} is missing, so there is no secret to test the sandbox on")
        secrets = [ROOT / "solutions" / "01-camera-rays" / "camera_rays.cpp", listener, judge]
        readable = [p for p in secrets if p.exists() and self.sandbox.can_read(p)]
        if readable:
            raise RuntimeError(f"isolation check failed: code in the sandbox can read {readable[0]}")

    def fail_all(self, task, cases, message):
        for name, points, visibility in cases:
            self.record(task, name, 0, points, message, visibility=visibility)

    def configure(self):
        """The "grade" preset in a new build folder. A folder that already holds
        a configured build (an earlier grade's, the course's own release or
        sanitizer build) is used as it is: its judges and flags, no second build."""
        cache = self.build / "CMakeCache.txt"
        if cache.exists():
            values = dict(re.findall(r"^(PATHLAB_SUBMISSION_OBJECTS|PATHLAB_SANITIZE):\w+=(.*)$",
                                     cache.read_text(errors="replace"), re.M))
            if values.get("PATHLAB_SANITIZE", "") != self.args.sanitize:
                raise RuntimeError(f"{self.build} is built with sanitizers '{values.get('PATHLAB_SANITIZE', '')}', "
                                   f"not '{self.args.sanitize}': choose another --build-dir")
            if values.get("PATHLAB_SUBMISSION_OBJECTS"):
                self.objects = Path(values["PATHLAB_SUBMISSION_OBJECTS"])
            self.objects.mkdir(parents=True, exist_ok=True)
            self.builder = CandidateBuilder(self.build, self.objects, self.work, self.sandbox)
            return
        sanitize = [f"-DPATHLAB_SANITIZE={self.args.sanitize}", "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -g1"] \
            if self.args.sanitize else []
        self.objects.mkdir(parents=True, exist_ok=True)
        # The "grade" preset (CMakePresets.json), in this grade's build folder.
        code, out = run(["cmake", "--preset", "grade", "-B", str(self.build),
                         f"-DPATHLAB_SUBMISSION_OBJECTS={self.objects}", *sanitize], cwd=ROOT)
        if code != 0:
            raise RuntimeError("configuring the grader's build failed:\n" + clip(out))
        self.builder = CandidateBuilder(self.build, self.objects, self.work, self.sandbox)

    def grade_task(self, task, source, note, deadline):
        directory, file_name = TASKS[task]
        self.say(f"task {task}: building its judge (test-{directory}; a first build takes minutes)", progress=True)
        ok, out = build_target(self.build, f"test-{directory}")
        if not ok:
            raise RuntimeError(f"building the judge test-{directory} failed:\n" + clip(out))
        cases = self.manifest(task)
        if not self.isolation_checked:
            self.check_isolation(self.build / "tests" / f"test-{directory}")
        if source is None:
            self.say(f"task {task}: no {file_name} in the submission")
            self.fail_all(task, cases, f"{file_name} was not found in the submission")
            return
        self.say(f"task {task}: grading {source}{note}")
        task_deadline = min(deadline, time.time() + self.args.task_budget)  # compiling included
        self.say(f"task {task}: compiling {file_name}", progress=True)
        obj, message = self.builder.compile(task, source, task_deadline)
        if obj is None:
            self.fail_all(task, cases, message)
            return
        self.say(f"task {task}: linking", progress=True)
        linked, message = self.builder.link(task, obj, task_deadline)
        if linked is None:
            self.fail_all(task, cases, message)
            return
        run_dir = Path(tempfile.mkdtemp(prefix=f"run-{task}-", dir=self.work))
        os.chmod(run_dir, 0o755)
        candidate = run_dir / ("candidate" + (".exe" if os.name == "nt" else ""))
        shutil.copy(linked, candidate)
        cpu = max(10.0, self.args.timeout + 5)
        command = self.sandbox.command([self.sandbox.path(run_dir, candidate)], run_dir, cpu_seconds=cpu)
        launcher = candidate  # unsandboxed: the judge starts the candidate itself
        if command != [str(candidate)]:
            launcher = self.verdicts / f"launch-{task}"
            launcher.write_text("#!/bin/sh\nexec " + shlex.join(command) + "\n")
            launcher.chmod(0o700)
        for index, (name, points, visibility) in enumerate(cases):
            left = task_deadline - time.time()
            if left < 1.0:
                which = "the submission's" if task_deadline >= deadline else f"task {task}'s"
                budget = self.args.budget if task_deadline >= deadline else self.args.task_budget
                self.record(task, name, 0, points, f"not run: {which} time budget of {budget:g} s was used up "
                            "by the tests before it", visibility=visibility)
                continue
            limit = min(self.args.timeout, left)
            self.say(f"task {task}: running test {index + 1} of {len(cases)}", progress=True)
            self.run_case(task, directory, name, points, visibility, index, launcher, limit)

    def run_case(self, task, directory, name, points, visibility, index, launcher, limit):
        verdict = self.verdicts / f"verdict-{task}-{index}"
        env = {k: v for k, v in os.environ.items() if not k.startswith("PATHLAB_")}
        env.update({verdicts.CANDIDATE: str(launcher), verdicts.VERDICT_FILE: str(verdict),
                    verdicts.IMAGE_FAILURES_DIR: str(self.pictures)})
        started = time.time()
        judge = {}  # its own memory is limited too: a hostile answer must fail this test, not the grade
        with memory_watch(self.sandbox) as watch:
            code, out = run([str(self.build / "tests" / f"test-{directory}"), f"--test-case={verdicts.test_case_filter(name)}",
                             "--no-version", "--no-intro"], timeout=limit, env=env, memory_limit=self.judge_memory,
                            memory=judge)
        timing = (time.time() - started, limit)
        self.sandbox.clean_up()
        out = out.replace(f"{self.pictures}/", f"{self.pictures.name}/")  # named beside results.json
        judged = verdicts.Verdicts.read(verdict)
        self.leaderboard.update(judged.leaderboard)
        if watch.exceeded:
            self.record(task, name, 0, points, watch.message() + "\n" + out, visibility=visibility, timing=timing)
        elif judge.get("exceeded"):
            self.record(task, name, 0, points, f"the judge needed more than its {self.judge_memory >> 20} MB of memory "
                        "for this test's answers, and was stopped (does the candidate send far more than was asked "
                        "for?)\n" + out, visibility=visibility, timing=timing)
        elif code is None:
            self.record(task, name, 0, points, f"timed out after {limit:g} s (an endless loop?)\n" + out,
                        visibility=visibility, timing=timing)
        elif judged.passed_alone() and code == 0:
            self.record(task, name, points, points, "passed", visibility=visibility, timing=timing)
        elif len(judged.ran) == 1:
            self.record(task, name, 0, points, out, visibility=visibility, timing=timing)
        else:
            self.record(task, name, 0, points, f"the test did not finish (judge exit code {code})\n" + out,
                        visibility=visibility, timing=timing)

    def finish(self):
        report = {
            "score": self.total,
            "execution_time": round(time.time() - self.start, 1),
            "output": f"{sum(r['score'] for r in self.results):g} of "
                      f"{sum(r['max_score'] for r in self.results):g} points",
            "tests": self.results,
        }
        if self.leaderboard:
            report["leaderboard"] = list(self.leaderboard.values())
        if self.sandbox.warning:
            report["output"] += "\n" + self.sandbox.warning
        if self.notes:
            report["output"] += "\nFrom the submitted archive:\n" + clip("\n".join(self.notes), 2000)
        Path(self.args.out).write_text(json.dumps(report, indent=2))
        failed = sum(1 for r in self.results if r["status"] != "passed")
        self.say(f"{report['output'].splitlines()[0]}; {len(self.results) - failed} passed, {failed} failed; "
                 f"wrote {self.args.out}")
        points = sum(r["max_score"] for r in self.results)
        if self.args.fail_under is not None and self.total < self.args.fail_under / 100.0 * points:
            return 1
        return 0

    def grade(self, submission: Path, tasks) -> int:
        """Grades `tasks` of a submission (a folder or a zip); always writes
        results.json. Exit code: 0, 1 for a submission without task files
        (or under --fail-under), 2 when the grader's own build or isolation failed."""
        out_dir = Path(self.args.out).resolve().parent
        try:
            if self.sandbox.warning:
                print(self.sandbox.warning, file=sys.stderr)
            folder = submission
            if submission.is_file():  # a zip, or something that was meant to be one
                folder = self.work / "submission"
                folder.mkdir()
                self.notes += unpack_zip(submission, folder)
            elif not submission.is_dir():
                raise ValueError(f"submission {submission} is neither a folder nor a file")
            found = find_task_files(folder)
            if not any(t in found for t in tasks):
                names = ", ".join(TASKS[t][1] for t in tasks)
                raise ValueError(f"no task file found in {submission} (looked for {names})")
            self.say("configuring the grader's build", progress=True)
            self.configure()
            self.sandbox.protect([ROOT, self.build, out_dir] if out_dir != Path("/") else [ROOT, self.build])
            self.prepare_sandbox()
            deadline = time.time() + self.args.budget
            for task in tasks:
                source, note = found.get(task, (None, ""))
                self.grade_task(task, source, note, deadline)
        except (ValueError, zipfile.BadZipFile, RuntimeError) as e:
            # A submission without task files (1), or the grader's own build or isolation failing (2).
            print(f"grade: {str(e).splitlines()[0]}", file=sys.stderr)
            for task in tasks:
                self.record(task, "submission", 0, 0, str(e))
            self.finish()
            return 2 if isinstance(e, RuntimeError) else 1
        except Exception as e:  # noqa: BLE001 — whatever went wrong, the submission still gets a results.json
            print(f"grade: the grader failed: {type(e).__name__}: {e}", file=sys.stderr)
            for task in tasks:
                self.record(task, "submission", 0, 0, f"the grader failed on this submission ({type(e).__name__}: "
                            f"{str(e)[:300]}); please tell the course staff")
            self.finish()
            return 2
        finally:
            self.sandbox.restore()
            self.sandbox.clean_up()
            shutil.rmtree(self.work, ignore_errors=True)
        return self.finish()
