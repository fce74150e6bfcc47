"""Hostile submissions against tools/grade (grader/tests/attacks/*.cpp).

Each attack is a task file (task 1's, or the task its "task: NN" names):
the stub (or the reference, for an attack that also does the work
honestly; or nothing, "base: none") with the attack appended, after any
shared part it names with "uses: FILE" (protocol-hijack.inc: the candidate's
side of the judge's protocol, taken over). "expect:" says what it must score:
"0", "full" (the reference's work), or a number of points N, for an attack
that does part of the work honestly to reach the tests it lies to (a tree it
really builds): N is what that honest part earns alone, measured with the
attack's lies turned off, as its comment says. The attack knows the
real paths of the repository, the build and results.json (@ROOT@, @BUILD@,
@OUT@: the worst case) and of listeners this script keeps open (@PORT@ on
127.0.0.1, the abstract Unix socket @ABSTRACT@). Every attack must score
exactly what its honest work earns (0 on the stub, full marks on the
reference, N for an honest part), and after each grade: the reference never
appears in results.json, the repository's tracked files and the judge are unchanged, no
process of the sandbox is left (looked at twice, a second apart), nothing of
the sandbox's is left in any world-writable folder or as a System V IPC
object, nothing reached the listeners, results.json is not rewritten later,
and the grade ended within its budget. While it runs, memory is sampled every
20 ms: the sandbox's (its processes and RAM-backed files) must stay within
the submission's limit (MEMORY_LIMIT here) plus what one poll of the
grader's watch can miss, and the grader's side (grader, judge, compiler
driver: everything not the sandbox's) within GRADER_MEMORY.

With --half 0 or 1 it runs one half of the attacks, drawn afresh for each
commit (CTest runs half 0 in bubblewrap and half 1 under the uid fallback):
every attack meets one sandbox on every commit and both within a few
commits, for half the time of both on each (docs/ci.md). PATHLAB_ATTACKS_ALL=1
runs every attack.

usage: test_attacks.py REPO_ROOT WORK_DIR GRADE_BUILD_DIR [--sandbox bwrap|uid] [--half 0|1] [ATTACK ...]"""
import hashlib
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the repository: the import root (docs/architecture.md)
from tools import pathlab_tasks
from tools.validity.adversary_lab import compile_argv, lto_sections  # noqa: E402
from tools.pathlab_tasks import commit_random  # noqa: E402

root, build, grade_build = (Path(a).resolve() for a in sys.argv[1:4])
args = sys.argv[4:]
sandbox = "auto"
if args[:1] == ["--sandbox"]:
    sandbox, args = args[1], args[2:]
half = None
if args[:1] == ["--half"]:
    half, args = int(args[1]), args[2:]
only = set(args)
work = build / f"attacks-{sandbox}"
SANDBOX_UID = int(os.environ.get("PATHLAB_SANDBOX_UID", "64990"))
TIMEOUT, TASK_BUDGET = 3, 12  # seconds per test case and for the task (sleep-to-limit)
MEMORY_LIMIT = 1 << 30        # the submission's memory limit in this suite (PATHLAB_SANDBOX_MEMORY)
MEMORY_SLACK = 512 << 20      # what 50 ms between the grader's polls may add, with margin
GRADER_MEMORY = 1 << 30       # the grader's side: a linker and a judge fit in far less
ANSWER_READER_MEMORY = 400 << 20  # huge-answer: the judge reads no answer longer than its request allows
# A line of the reference's task 1 that the stub does not have.
SECRET = "basis.right = glm::normalize(right);"
# A world-readable file outside the framework (@LEAK@) and a variable in the
# grader's environment: neither may reach results.json.
LEAK_MARKER = "PATHLAB-LEAK-MARKER-7c1e"
LEAK_FILE = Path("/tmp/pathlab-attack-leak/marker.h")


def tree_digest() -> str:
    files = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], capture_output=True, check=True).stdout
    h = hashlib.sha256()
    for name in sorted(files.decode().split("\0")):
        path = root / name
        if name and path.is_file():
            h.update(name.encode() + b"\0" + path.read_bytes())
    return h.hexdigest()


TASKS = pathlab_tasks.tasks()  # {n: (folder, file)}


def judge_digest(task=1) -> str:
    judge = grade_build / "tests" / f"test-{TASKS[task][0]}"
    return hashlib.sha256(judge.read_bytes()).hexdigest() if judge.exists() else "none"


def judge_points(task) -> int:
    """The task's points as its judge lists them (every attack on it must see the same manifest)."""
    judge = grade_build / "tests" / f"test-{TASKS[task][0]}"
    subprocess.run(["cmake", "--build", str(grade_build), "--target", judge.name], capture_output=True, timeout=1500)
    listing = subprocess.run([str(judge), "--list-test-cases"], capture_output=True, text=True, timeout=60).stdout
    return sum(int(m.group(1)) for m in re.finditer(r"^TEST (\d+) ", listing, re.M))


def sandbox_processes():
    found = []
    for pid in os.listdir("/proc"):
        try:
            if pid.isdigit() and os.stat(f"/proc/{pid}").st_uid == SANDBOX_UID:
                state = Path(f"/proc/{pid}/status").read_text().split("State:")[1].split()[0]
                if state != "Z":
                    found.append(pid)
        except (OSError, IndexError):
            pass
    return found


def world_writable_folders():
    """Found here, independently of the grader's own list."""
    out = subprocess.run(["find", "/", "-maxdepth", "5", "(", "-path", "/proc", "-o", "-path", "/sys", ")", "-prune",
                          "-o", "-type", "d", "-perm", "-0002", "-print"], capture_output=True, text=True).stdout
    return sorted(set(out.split()) | {"/tmp", "/var/tmp", "/dev/shm"})


def sandbox_files(folders):
    """Files and folders the sandbox uid owns anywhere under `folders` (find: fast on a big /tmp)."""
    out = subprocess.run(["find", *folders, "-uid", str(SANDBOX_UID), "-print"], capture_output=True, text=True).stdout
    return [line for line in out.splitlines() if line]


def sandbox_ipc():
    """The sandbox uid's System V IPC objects, as ipcs lists them."""
    found = []
    for kind in ("-m", "-s", "-q"):
        out = subprocess.run(["ipcs", kind, "-c"], capture_output=True, text=True).stdout
        found += [line for line in out.splitlines() if re.search(rf"\s{SANDBOX_UID}\s", line)]
    return found


def shared_memory_bytes() -> int:
    """RAM held by tmpfs files and shared memory, system-wide (/proc/meminfo Shmem)."""
    for line in Path("/proc/meminfo").read_text().splitlines():
        if line.startswith("Shmem:"):
            return int(line.split()[1]) * 1024
    return 0


class MemorySampler(threading.Thread):
    """Peak memory of one grade, every 20 ms: the sandbox uid's processes plus
    what tmpfs and shared memory grew by (the sandbox's files in RAM), and the
    grade's other processes (the grader's process tree minus the sandbox)."""

    def __init__(self, grader_pid: int):
        super().__init__(daemon=True)
        self.grader_pid, self.stop = grader_pid, threading.Event()
        self.baseline = shared_memory_bytes()
        self.sandbox_peak = self.grader_peak = 0

    def run(self):
        page = os.sysconf("SC_PAGE_SIZE")
        while not self.stop.wait(0.02):
            parent, rss, uid = {}, {}, {}
            for pid in os.listdir("/proc"):
                try:
                    if not pid.isdigit():
                        continue
                    stat = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
                    parent[int(pid)] = int(stat[1])
                    rss[int(pid)] = int(stat[21]) * page
                    uid[int(pid)] = os.stat(f"/proc/{pid}").st_uid
                except (OSError, IndexError, ValueError):
                    pass
            def in_grade(pid):
                for _ in range(64):
                    if pid == self.grader_pid:
                        return True
                    pid = parent.get(pid, 0)
                    if pid <= 1:
                        return False
                return False
            sandbox = sum(r for p, r in rss.items() if uid.get(p) == SANDBOX_UID)
            grader = sum(r for p, r in rss.items() if uid.get(p) != SANDBOX_UID and in_grade(p))
            self.sandbox_peak = max(self.sandbox_peak, sandbox + max(0, shared_memory_bytes() - self.baseline))
            self.grader_peak = max(self.grader_peak, grader)


class Listener(threading.Thread):
    """Accepts connections on a socket and keeps what they send."""

    def __init__(self, family, address):
        super().__init__(daemon=True)
        self.server = socket.socket(family, socket.SOCK_STREAM)
        self.server.bind(address)
        self.server.listen(8)
        self.received = []

    def run(self):
        while True:
            try:
                connection, _ = self.server.accept()
            except OSError:
                return
            with connection:
                connection.settimeout(2)
                try:
                    self.received.append(connection.recv(1 << 16) or b"(connected)")
                except OSError:
                    self.received.append(b"(connected)")


def main() -> int:
    if SECRET not in (root / "solutions/01-camera-rays/camera_rays.cpp").read_text():
        print(f"the reference no longer contains the marker line '{SECRET}': update SECRET")
        return 1
    if SECRET in (root / "tasks/01-camera-rays/camera_rays.cpp").read_text():
        print(f"the stub contains the marker line '{SECRET}': pick another")
        return 1
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    LEAK_FILE.parent.mkdir(exist_ok=True)
    LEAK_FILE.parent.chmod(0o755)
    LEAK_FILE.write_text(f"{LEAK_MARKER}\n")
    LEAK_FILE.chmod(0o644)
    grader_env = {**os.environ, "PATHLAB_ATTACK_MARKER": LEAK_MARKER, "PATHLAB_SANDBOX_MEMORY": str(MEMORY_LIMIT)}
    tcp = Listener(socket.AF_INET, ("127.0.0.1", 0))
    abstract_name = f"pathlab-attack-{os.getpid()}"
    local = Listener(socket.AF_UNIX, "\0" + abstract_name)
    tcp.start()
    local.start()
    folders = world_writable_folders()
    attacks = sorted((root / "grader/tests/attacks").glob("*.cpp"))
    if only:
        attacks = [a for a in attacks if a.stem in only]
    elif half is not None and os.environ.get("PATHLAB_ATTACKS_ALL") != "1":
        commit_random("attacks", root).shuffle(attacks)
        attacks = sorted(attacks[half::2])
    failures = []
    # Warm up the grader's build (the judge must not change after this) and
    # check that the reference still gets full marks in this sandbox mode.
    warm = work / "reference.json"
    subprocess.run([sys.executable, str(root / "tools/grade"), str(root / "solutions"), "--tasks", "1", "--out",
                    str(warm), "--build-dir", str(grade_build), "--sandbox", sandbox], capture_output=True, timeout=1500)
    # Task 1's points as its judge lists them: every attack must see the same manifest.
    full = sum(t["max_score"] for t in json.loads(warm.read_text())["tests"]) if warm.exists() else None
    if not full or json.loads(warm.read_text())["score"] != full:
        failures.append(f"reference: not full marks with --sandbox {sandbox}")
    before_tree = tree_digest()
    judges_before, full_points = {1: judge_digest()}, {1: full}
    for attack in attacks:
        text = attack.read_text()
        header = re.search(r"// (?:task: (\d+)\s+)?base: (\w+)\s+expect: (\w+)(?:\s+uses: (\S+))?(?:\s+lto: (\S+))?",
                           text)
        task, base, expect, uses = int(header.group(1) or 1), header.group(2), header.group(3), header.group(4)
        if task not in full_points:
            full_points[task] = judge_points(task)
            judges_before[task] = judge_digest(task)
        directory, file_name = TASKS[task]
        if uses:
            text = (root / "grader/tests/attacks" / uses).read_text() + "\n" + text
        out = work / f"{attack.stem}.json"
        values = {"@ROOT@": str(root), "@BUILD@": str(grade_build), "@OUT@": str(out), "@LEAK@": str(LEAK_FILE),
                  "@PORT@": str(tcp.server.getsockname()[1]), "@ABSTRACT@": abstract_name}
        body = re.sub("|".join(values), lambda m: values[m.group(0)], text)
        if header.group(5):
            ir = (root / "tasks" / directory / file_name).read_text() + "\n" + \
                re.sub("|".join(values), lambda m: values[m.group(0)], (attack.parent / header.group(5)).read_text())
            body = body.replace("@LTO_SECTIONS@", lto_sections(ir, compile_argv(grade_build, task),
                                                               work / f"{attack.stem}-ir"))
        prefix = "" if base == "none" else \
            (root / ("solutions" if base == "reference" else "tasks") / directory / file_name).read_text()
        submission = work / attack.stem
        submission.mkdir()
        (submission / file_name).write_text(prefix + "\n" + body)
        start = time.time()
        received_before = len(tcp.received) + len(local.received)
        grade = subprocess.Popen([sys.executable, str(root / "tools/grade"), str(submission), "--tasks", str(task),
                                  "--out", str(out), "--build-dir", str(grade_build), "--timeout", str(TIMEOUT),
                                  "--task-budget", str(TASK_BUDGET), "--sandbox", sandbox], stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, text=True, env=grader_env)
        sampler = MemorySampler(grade.pid)
        sampler.start()
        try:
            _, grade.stderr = grade.communicate(timeout=900)
        finally:
            sampler.stop.set()
            sampler.join()
        seconds = time.time() - start
        problems = []
        if sampler.sandbox_peak > MEMORY_LIMIT + MEMORY_SLACK:
            problems.append(f"the sandbox held {sampler.sandbox_peak / 2**30:.2f} GB (limit {MEMORY_LIMIT / 2**30:.1f} GB)")
        grader_memory = ANSWER_READER_MEMORY if attack.stem == "huge-answer" else GRADER_MEMORY
        if sampler.grader_peak > grader_memory:
            problems.append(f"the grader's side held {sampler.grader_peak / 2**20:.0f} MB (limit {grader_memory >> 20} MB)")
        if len(tcp.received) + len(local.received) > received_before:
            problems.append("a listener outside the sandbox was reached: "
                            + repr((tcp.received + local.received)[-1][:80]))
        if not out.exists():
            problems.append(f"no results.json (grader exit {grade.returncode}: {grade.stderr[-300:]})")
        else:
            report_text = out.read_text()
            digest = hashlib.sha256(report_text.encode()).hexdigest()
            report = json.loads(report_text)
            points = sum(t["max_score"] for t in report["tests"])
            wanted = points if expect == "full" else int(expect)  # "0", or an honest part's N points
            if points != full_points[task]:
                problems.append(f"the task's manifest changed: {points} points instead of {full_points[task]}")
            if report["score"] != wanted:
                problems.append(f"scored {report['score']:g}, expected {wanted}")
            if SECRET in report_text:
                problems.append("the reference's source is in results.json")
            if LEAK_MARKER in report_text:
                problems.append("a file outside the framework, or the grader's environment, is in results.json")
            if attack.stem.startswith("include-") and "may include only" not in report_text:
                problems.append("the include was not refused with a clear message")
            if attack.stem == "incbin-spliced" and "inline assembly" not in report_text:
                problems.append("the inline assembly was not refused with a clear message")
            if attack.stem == "sleep-to-limit" and "time budget" not in report_text:
                problems.append("tests past the task's budget are not reported as not run")
            if attack.stem == "error-message-flood" and "over the limit" not in report_text:
                problems.append("the oversized error message is not reported")
            if attack.stem == "slow-compile" and "compiling took longer" not in report_text:
                problems.append("the compile's time limit is not reported")
            if attack.stem == "memory-in-children" and "processes together used" not in report_text:
                problems.append("the memory limit is not reported")
            if attack.stem == "huge-answer" and "the most a right answer to this request takes" not in report_text:
                problems.append("the answer's length was not refused against its request")
            if attack.stem == "image-size-lie" and "the request asked for" not in report_text:
                problems.append("the image's size was not checked against its request")
            if attack.stem == "daemon":
                time.sleep(3)  # the daemon would rewrite results.json every second
                if hashlib.sha256(out.read_bytes()).hexdigest() != digest:
                    problems.append("results.json was rewritten after the grade")
            if len(report_text) > 1_000_000:
                problems.append(f"results.json is {len(report_text)} bytes: output not clipped")
        if seconds > TASK_BUDGET + 60:
            problems.append(f"the grade took {seconds:.0f} s (budget {TASK_BUDGET} s)")
        if judge_digest(task) != judges_before[task]:
            problems.append("the judge binary changed")
        left = sandbox_processes()
        time.sleep(1)  # a chain of forks may be between two of its processes
        left = left or sandbox_processes()
        if left:
            problems.append(f"{len(left)} sandbox processes still running")
        files = sandbox_files(folders)
        if files:
            problems.append(f"sandbox files left behind: {files[:3]}")
        ipc = sandbox_ipc()
        if ipc:
            problems.append(f"System V IPC objects left behind: {ipc[:2]}")
        status = "ok" if not problems else "FAIL: " + "; ".join(problems)
        print(f"{attack.stem:20s} {sandbox:5s} {seconds:5.1f} s  memory: sandbox {sampler.sandbox_peak / 2**20:5.0f} MB, "
              f"grader {sampler.grader_peak / 2**20:4.0f} MB  {status}")
        failures += [f"{attack.stem}: {p}" for p in problems]
    if tree_digest() != before_tree:
        failures.append("the repository's tracked files changed")
    for f in failures:
        print("FAIL:", f)
    checks = len(attacks) + 1
    print(f"{checks - len({f.split(':')[0] for f in failures})} passed, {len({f.split(':')[0] for f in failures})} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
