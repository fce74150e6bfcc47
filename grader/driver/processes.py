"""Running a command for the grader (sandbox.py, tools/check):
its output kept within bounds from both ends, its time and memory limited,
and the processes it leaves behind reaped."""
import os
import re
import selectors
import shlex
import signal
import subprocess
import time
from pathlib import Path


OUTPUT_LIMIT = 6000  # characters of a command's output the grader keeps (a test's, in results.json)


def clip(text: str, limit: int = OUTPUT_LIMIT) -> str:
    """At most `limit` characters of `text`: its two ends, and a note where the middle was."""
    return text if len(text) <= limit else text[: limit // 2] + "\n[... output cut ...]\n" + text[-limit // 2 :]


OUTPUT_KEPT = 1 << 20        # bytes of a command's output run() holds from each end


def own_memory(pid: int) -> int:
    """What a process holds of its own in memory: its resident anonymous and
    shared pages (RssAnon + RssShmem of /proc/PID/status), not the files it
    maps (libraries, read-only data, which the kernel can drop). 0 when gone."""
    try:
        fields = dict(line.split(":", 1) for line in Path(f"/proc/{pid}/status").read_text().splitlines() if ":" in line)
        return sum(int(fields.get(k, "0 kB").split()[0]) for k in ("RssAnon", "RssShmem")) * 1024
    except (OSError, ValueError):
        return 0


def run(command, cwd=None, timeout=None, env=None, keep=OUTPUT_KEPT, memory_limit=None, memory=None):
    """Runs a command in its own session; returns (exit code or None on timeout, output).
    Of the output only the first and last `keep` bytes are held (a flood of
    compiler diagnostics must not fill the grader's memory); the middle is
    replaced by a line saying how much was left out. With memory_limit
    (bytes), the command's own memory (own_memory, its process alone, every
    50 ms) may not pass it: the session is stopped, and `memory` (a dict, if
    given) says so ("exceeded") with the most seen ("peak")."""
    if os.name == "nt":
        return run_windows(command, cwd, timeout, env)
    try:
        p = subprocess.Popen(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                             start_new_session=True)
    except OSError as e:
        return 127, str(e)
    head, tail, dropped = bytearray(), bytearray(), 0
    deadline = None if timeout is None else time.monotonic() + timeout
    timed_out = exceeded = False
    peak = 0

    def over_limit():
        nonlocal peak
        if memory_limit is None:
            return False
        peak = max(peak, own_memory(p.pid))
        return peak > memory_limit

    try:
        with selectors.DefaultSelector() as selector:
            selector.register(p.stdout, selectors.EVENT_READ)
            while True:
                left = None if deadline is None else deadline - time.monotonic()
                if left is not None and left <= 0:
                    timed_out = True
                    break
                if memory_limit is not None:
                    left = 0.05 if left is None else min(left, 0.05)
                ready = selector.select(left)
                if over_limit():
                    exceeded = True
                    break
                if not ready:
                    continue
                chunk = os.read(p.stdout.fileno(), 1 << 16)
                if not chunk:
                    break
                room = keep - len(head)
                head += chunk[:max(room, 0)]
                tail += chunk[max(room, 0):]
                if len(tail) > keep:
                    dropped += len(tail) - keep
                    del tail[:len(tail) - keep]
        while not (timed_out or exceeded):  # the output is closed: wait for the exit, within the time and memory
            left = None if deadline is None else deadline - time.monotonic()
            if left is not None and left <= 0:
                timed_out = True
                break
            step = left if memory_limit is None else (0.05 if left is None else min(left, 0.05))
            try:
                p.wait(timeout=step)
                break
            except subprocess.TimeoutExpired:
                exceeded = over_limit()
    finally:
        try:
            os.killpg(p.pid, signal.SIGKILL)  # nothing of the session outlives it
        except ProcessLookupError:
            pass
        p.wait()
        p.stdout.close()
    if memory is not None:
        memory.update(peak=peak, exceeded=exceeded)
    out = bytes(head) + (f"\n[... {dropped} bytes of output left out ...]\n".encode() if dropped else b"") + bytes(tail)
    return (None if timed_out or exceeded else p.returncode), out.decode("utf-8", "replace")


def run_windows(command, cwd, timeout, env):
    """run() on Windows (tools/check only; never the grader): no process
    groups there, and select() takes no pipes, so communicate() with a timeout."""
    try:
        p = subprocess.Popen(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env)
    except OSError as e:
        return 127, str(e)
    try:
        out, _ = p.communicate(timeout=timeout)
        code = p.returncode
    except subprocess.TimeoutExpired:
        p.kill()
        out, _ = p.communicate()
        code = None
    return code, out.decode("utf-8", "replace")


def become_subreaper() -> None:
    """Orphans of the sandbox (bubblewrap leaves one per run) become this
    process's children, so they are reaped here: in a container whose init
    never reaps, each zombie would count against the sandbox uid's process
    limit until forking fails."""
    try:
        import ctypes
        ctypes.CDLL(None, use_errno=True).prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER
    except (OSError, AttributeError):
        pass


def reap_orphans(wait_seconds: float = 0) -> bool:
    """Reaps the exited orphans re-parented to this process (a launcher's subshell whose launcher was
    killed). With wait_seconds, waits up to that long for the running ones too, so that every one has
    exited (and written what it writes); False if one was still running then."""
    deadline = time.monotonic() + wait_seconds
    while True:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return True
        if pid == 0:
            if time.monotonic() >= deadline:
                return wait_seconds == 0
            time.sleep(0.02)


def link_command(build: Path, target: str):
    """The link line Ninja would run for `target` of `build` (its last command, `ninja -t commands`), as a
    list to run in `build`: read from build.ninja, nothing is built or run."""
    code, listing = run(["ninja", "-C", str(build), "-t", "commands", target], timeout=120)
    lines = listing.strip().splitlines()
    if code != 0 or not lines:
        raise RuntimeError(f"no link command for {target} in {build}:\n{clip(listing, 2000)}")
    return shlex.split(re.sub(r"\s*&&\s*:$", "", re.sub(r"^:\s*&&\s*", "", lines[-1].strip())))
