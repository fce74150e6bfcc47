"""The Gradescope zip graded in a container shaped like Gradescope's default
one: a cgroup with 768 MB of memory (no swap) and half a CPU, and the
autograder's 10-minute timeout. Needs root and a writable cgroup file system
(v2, or v1 with the memory and cpu controllers); elsewhere it says so in one
line and exits 2.

  tools/gradescope/container-check [--memory MB] [--cpus N] [--timeout S] [--tasks 1,2,...]
                                   [--modes bwrap,uid] [--cases NAME,...] [--keep DIR]

The zip is made (make-zip.sh --timeout S --tasks ...: the tasks a course
grades, default the seven core ones), unpacked where Gradescope unpacks
it and set up (setup.sh, outside the cgroup, as Gradescope builds its image;
PATHLAB_SKIP_APT=1: the packages must be installed). Then, for each sandbox
mode and case, the submission goes into submission/ and run_autograder runs
inside the cgroup, killed at the timeout as Gradescope would. Cases:
  reference      the model answers: full marks
  stubs          the untouched student files: 0, every test present
  slow           the model answers, each candidate start 6 s late (correct,
                 but too slow for the timeout: the grader's budget must end it)
  hog-one        task 1 allocates 1.5 GB in one process at start
  hog-children   task 1 forks five children that touch 1.8 GB each
  hog-sysv       task 1 makes a 512 MB System V segment, touches it, keeps it
  each-task      the model answer of one task at a time (the others not
                 handed in): each task's own peak memory and seconds
Each must write results.json before the timeout; a hog must lose task 1's
tests only (the other tasks full marks). Printed per run: seconds, score,
what task 1 scored, the cgroup's peak memory (the page cache included), and
whether the kernel's OOM killer acted."""
import argparse
import json
import os
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
from tools import pathlab_tasks

# A line of C++ put at the end of task 1's file: runs when the candidate starts.
HOGS = {
    "hog-one": """
#include <cstdlib>
static const bool pathlab_hog = [] {
  const size_t n = size_t(1536) << 20;
  volatile char* p = static_cast<char*>(std::malloc(n));  // volatile: the pages are touched, not optimised away
  for (size_t i = 0; p && i < n; i += 4096) p[i] = 1;
  return p != nullptr;
}();
""",
    "hog-children": """
#include <cstdlib>
#include <unistd.h>
static const bool pathlab_hog = [] {
  for (int i = 0; i < 5; ++i) {
    if (fork() == 0) {
      const size_t n = size_t(1843) << 20;
      volatile char* p = static_cast<char*>(std::malloc(n));
      for (size_t k = 0; p && k < n; k += 4096) p[k] = 1;
      sleep(600);
      _exit(0);
    }
  }
  return true;
}();
""",
    "hog-sysv": """
#include <sys/ipc.h>
#include <sys/shm.h>
static const bool pathlab_hog = [] {
  const int id = shmget(IPC_PRIVATE, size_t(512) << 20, IPC_CREAT | 0600);
  if (id < 0) return false;
  void* p = shmat(id, nullptr, 0);
  if (p != reinterpret_cast<void*>(-1)) {
    volatile char* q = static_cast<char*>(p);
    for (size_t i = 0; i < (size_t(512) << 20); i += 4096) q[i] = 1;
  }
  return true;
}();
""",
}
SLOW = """
#include <chrono>
#include <thread>
static const bool pathlab_slow = (std::this_thread::sleep_for(std::chrono::seconds(6)), true);
"""


class Cgroup:
    """A cgroup (v2, or v1's memory and cpu hierarchies) with a memory limit and a CPU quota."""

    def __init__(self, memory: int, cpus: float):
        name = f"pathlab-gradescope-{os.getpid()}"
        period = 100000
        self.dirs = []
        v2 = Path("/sys/fs/cgroup/cgroup.controllers")
        if v2.exists():
            root = Path("/sys/fs/cgroup")
            if "memory" not in (root / "cgroup.subtree_control").read_text() or \
                    "cpu" not in (root / "cgroup.subtree_control").read_text():
                (root / "cgroup.subtree_control").write_text("+memory +cpu")
            d = root / name
            d.mkdir()
            self.dirs = [d]
            (d / "memory.max").write_text(str(memory))
            if (d / "memory.swap.max").exists():
                (d / "memory.swap.max").write_text("0")
            (d / "cpu.max").write_text(f"{int(cpus * period)} {period}")
            self.procs, self.version = [d / "cgroup.procs"], 2
        else:
            mem, cpu = Path("/sys/fs/cgroup/memory") / name, Path("/sys/fs/cgroup/cpu") / name
            mem.mkdir()
            self.dirs.append(mem)
            cpu.mkdir()
            self.dirs.append(cpu)
            (mem / "memory.limit_in_bytes").write_text(str(memory))
            if (mem / "memory.memsw.limit_in_bytes").exists():
                (mem / "memory.memsw.limit_in_bytes").write_text(str(memory))
            (cpu / "cpu.cfs_period_us").write_text(str(period))
            (cpu / "cpu.cfs_quota_us").write_text(str(int(cpus * period)))
            self.procs, self.version = [mem / "cgroup.procs", cpu / "cgroup.procs"], 1

    def reset_peak(self):
        if self.version == 1:
            (self.dirs[0] / "memory.max_usage_in_bytes").write_text("0")

    def peak(self) -> int:
        f = self.dirs[0] / ("memory.max_usage_in_bytes" if self.version == 1 else "memory.peak")
        return int(f.read_text()) if f.exists() else 0

    def oom_kills(self) -> int:
        f = self.dirs[0] / ("memory.oom_control" if self.version == 1 else "memory.events")
        for line in f.read_text().splitlines() if f.exists() else []:
            key, _, value = line.partition(" ")
            if key == "oom_kill":
                return int(value)
        return 0

    def enter_command(self, argv):
        """argv run inside the cgroup (a shell moves itself in, then execs)."""
        moves = "; ".join(f"echo $$ > {p}" for p in self.procs)
        return ["sh", "-c", f"{moves}; exec \"$@\"", "sh", *argv]

    def remove(self):
        for d in self.dirs:
            for _ in range(50):
                try:
                    d.rmdir()
                    break
                except OSError:
                    time.sleep(0.2)


def submission(kind: str, out: Path, tasks):
    """The submission's files, flat, as a student uploads them ("task-N": task N's model answer alone)."""
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    for n, (folder, file_name) in tasks.items():
        if kind.startswith("task-") and kind != f"task-{n}":
            continue
        source = (ROOT / ("tasks" if kind == "stubs" else "solutions") / folder / file_name).read_text()
        if kind == "slow":
            source += SLOW
        elif kind in HOGS and n == 1:
            source += HOGS[kind]
        (out / file_name).write_text(source)


def arguments():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--memory", type=int, default=768, help="MB (Gradescope's default: 768)")
    parser.add_argument("--cpus", type=float, default=0.5, help="CPUs (Gradescope's default: 0.5)")
    parser.add_argument("--timeout", type=int, default=600, help="seconds (Gradescope's default: 600)")
    parser.add_argument("--tasks", default=pathlab_tasks.core_tasks(), help="the tasks graded (make-zip.sh --tasks)")
    parser.add_argument("--modes", default="bwrap,uid")
    parser.add_argument("--cases", default="reference,stubs,slow,hog-one,hog-children,hog-sysv")
    parser.add_argument("--keep", help="keep the scratch /autograder here")
    return parser.parse_args()


def set_up_zip(autograder: Path, timeout: int, tasks) -> dict:
    """The zip made, unpacked where Gradescope unpacks it and set up outside the cgroup, as Gradescope
    builds its image; returns the environment run_autograder runs in, or raises RuntimeError."""
    archive = autograder.parent / "autograder.zip"
    subprocess.run(["bash", str(ROOT / "tools/gradescope/make-zip.sh"), str(archive), "--timeout", str(timeout),
                    "--tasks", ",".join(str(n) for n in tasks)], check=True, stdout=subprocess.DEVNULL)
    shutil.rmtree(autograder, ignore_errors=True)
    (autograder / "source").mkdir(parents=True)
    subprocess.run(["python3", "-m", "zipfile", "-e", str(archive), str(autograder / "source")], check=True)
    for script in ("setup.sh", "run_autograder", "source/tools/ensure-cmake.sh", "source/tools/install-grader"):
        (autograder / "source" / script).chmod(0o755)
    env = dict(os.environ, AUTOGRADER_ROOT=str(autograder), PATHLAB_SKIP_APT="1")
    started = time.time()
    setup = subprocess.run(["bash", "./setup.sh"], cwd=autograder / "source", env=env, capture_output=True, text=True)
    if setup.returncode != 0:
        raise RuntimeError(f"setup.sh failed:\n{setup.stdout[-2000:]}{setup.stderr[-2000:]}")
    print(f"setup.sh: {time.time() - started:.0f} s (outside the container, as Gradescope builds its image)")
    shutil.copy(autograder / "source/run_autograder", autograder / "run_autograder")
    return env


def run_in_container(group: Cgroup, autograder: Path, env: dict, mode: str, timeout: int) -> dict:
    """run_autograder inside the cgroup, killed at the timeout: its row (seconds, peak, OOM kills, output,
    and the tests of results.json when it was written in time)."""
    results = autograder / "results/results.json"
    results.unlink(missing_ok=True)
    group.reset_peak()
    kills = group.oom_kills()
    started = time.time()
    run = subprocess.Popen(group.enter_command([str(autograder / "run_autograder")]), cwd=autograder,
                           env=dict(env, PATHLAB_SANDBOX=mode), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, start_new_session=True)
    try:
        out, _ = run.communicate(timeout=timeout)
        timed_out = False
    except subprocess.TimeoutExpired:
        os.killpg(run.pid, 9)
        out, _ = run.communicate()
        timed_out = True
    row = {"seconds": time.time() - started, "peak_mb": group.peak() >> 20, "oom_kills": group.oom_kills() - kills,
           "results": results.exists() and not timed_out, "output": out}
    if row["results"]:
        row["tests"] = json.loads(results.read_text()).get("tests", [])
    return row


def points_by_task(tests) -> dict:
    """{task: (earned, most)} from results.json's tests ("Task 6: T6.1 ..."); 0 for a test named otherwise."""
    by_task = {}
    for t in tests:
        head = t.get("name", "").split(":")[0].split()
        n = int(head[1]) if len(head) == 2 and head[1].isdigit() else 0
        got, of = by_task.get(n, (0.0, 0.0))
        by_task[n] = (got + t.get("score", 0), of + t.get("max_score", 0))
    return by_task


def judge_run(mode: str, case: str, row: dict) -> list:
    """What went other than the case expects; fills the row's score, most and task 1's points."""
    if not row["results"]:
        return [f"{mode} {case}: no results.json within the timeout ({row['seconds']:.0f} s)\n{row['output'][-1500:]}"]
    by_task = points_by_task(row["tests"])
    row["score"] = sum(g for g, _ in by_task.values())
    row["max"] = sum(m for _, m in by_task.values())
    row["task1"] = by_task.get(1, (0, 0))
    failures = []
    if case == "reference" and row["score"] != row["max"]:
        failures.append(f"{mode} {case}: {row['score']:g} of {row['max']:g}")
    if case.startswith("task-"):  # that task full marks, the rest not handed in
        n = int(case[5:])
        row["score"], row["max"] = by_task.get(n, (0.0, 0.0))
        if row["score"] != row["max"] or not row["max"]:
            failures.append(f"{mode} {case}: task {n} {row['score']:g} of {row['max']:g}")
    if case == "stubs" and row["score"] != 0:
        failures.append(f"{mode} {case}: {row['score']:g}, want 0")
    # (In uid mode pathlab-confine refuses System V IPC: that hog gets no segment to hold.)
    keeps_task1 = case == "hog-sysv" and mode == "uid"
    others = {n: points for n, points in sorted(by_task.items()) if n != 1}
    if case in HOGS and ((row["task1"][0] >= row["task1"][1] and not keeps_task1) or
                         any(g != m for g, m in others.values())):
        failures.append(f"{mode} {case}: task 1 {row['task1']}, the others {list(others.items())}")
    return failures


def print_row(mode: str, case: str, row: dict):
    task1 = row.get("task1", (0, 0))
    print(f"{mode:6} {case:13} {row['seconds']:5.0f} s  results.json {'yes' if row['results'] else 'NO '}  "
          f"score {row.get('score', 0):5g} of {row.get('max', 0):g}  task 1 {task1[0]:g} of {task1[1]:g}  "
          f"peak {row['peak_mb']} MB  OOM kills {row['oom_kills']}", flush=True)


def main() -> int:
    args = arguments()
    every = pathlab_tasks.tasks(ROOT)
    try:
        tasks = {int(t): every[int(t)] for t in args.tasks.split(",")}
    except (ValueError, KeyError):
        print(f"container-check: --tasks must list task numbers {min(every)}-{max(every)}, got '{args.tasks}'")
        return 2
    if os.geteuid() != 0:
        print("container-check: skipped: needs root (a cgroup, and the grader's sandbox uid)")
        return 2
    try:
        group = Cgroup(args.memory << 20, args.cpus)
    except OSError as e:
        print(f"container-check: skipped: cannot make a cgroup here ({e})")
        return 2
    cases = [c for case in args.cases.split(",")
             for c in ([f"task-{n}" for n in tasks] if case == "each-task" else [case])]
    work = Path(args.keep or tempfile.mkdtemp(prefix="pathlab-container-"))
    work.mkdir(parents=True, exist_ok=True)
    autograder = work / "autograder"
    failures, runs = [], 0
    try:
        env = set_up_zip(autograder, args.timeout, tasks)
        print(f"container: {args.memory} MB, {args.cpus:g} CPU, timeout {args.timeout} s (cgroup v{group.version})")
        for mode in args.modes.split(","):
            for case in cases:
                submission(case, autograder / "submission", tasks)
                row = run_in_container(group, autograder, env, mode, args.timeout)
                failures += judge_run(mode, case, row)
                print_row(mode, case, row)
                runs += 1
    except RuntimeError as e:
        print(f"container-check: {e}")
        return 1
    finally:
        group.remove()
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
    for f in failures:
        print(f"FAIL: {f}")
    print(f"container-check: {runs - len(failures)} of {runs} runs as expected")
    return 1 if failures else 0
