"""The grader's sandbox (tools/grade): runs untrusted commands — compiling
the student's file and running the candidate — as an unprivileged uid inside
bubblewrap, or with limits only where namespaces are missing. See Sandbox."""
import os
import re
import shlex
import shutil
import signal
import stat
import subprocess
import time
from pathlib import Path

SANDBOX_UID = int(os.environ.get("PATHLAB_SANDBOX_UID", "64990"))  # a uid nothing else uses
CANDIDATE_LIMITS = ["--nofile=256", "--fsize=67108864", "--core=0"]
ADDRESS_SPACE = "--as=8589934592"  # 8 GB; not under sanitizers, whose shadow memory reserves terabytes
CANDIDATE_PROCESSES = 64     # RLIMIT_NPROC of the sandbox uid: a fork bomb stops here


def run(command, cwd=None, timeout=None, env=None):
    """Runs a command in its own session; returns (exit code or None on timeout, output)."""
    try:
        p = subprocess.Popen(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                             start_new_session=True)
    except OSError as e:
        return 127, str(e)
    try:
        out, _ = p.communicate(timeout=timeout)
        return p.returncode, out.decode("utf-8", "replace")
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, _ = p.communicate()
        return None, out.decode("utf-8", "replace")
    finally:
        try:
            os.killpg(p.pid, signal.SIGKILL)  # nothing of the session outlives it
        except ProcessLookupError:
            pass


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


def reap_orphans() -> None:
    while True:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return


class Sandbox:
    """Runs untrusted commands (compiling and running the candidate).

    bwrap: an unprivileged uid (when root) inside bubblewrap's namespaces —
           only /usr and the scratch folder exist, no network, a private
           /tmp of bounded size, every process killed when it ends.
    uid:   root without namespaces (Gradescope's container): the sandbox
           uid, resource limits, and the repository and build made private
           for the duration of the grade.
    none:  neither (not root, no user namespaces): limits only. Loud."""

    def __init__(self, requested: str):
        self.root = os.geteuid() == 0
        self.mode = requested
        self.protected = []  # (path, original mode) to restore
        if requested == "auto":
            if shutil.which("bwrap") and self._bwrap_works():
                self.mode = "bwrap"
            elif self.root and shutil.which("setpriv"):
                self.mode = "uid"
            else:
                self.mode = "none"
        self.warning = {
            "bwrap": "",
            "uid": "sandbox: bubblewrap cannot create namespaces here; the candidate runs as uid "
                   f"{SANDBOX_UID} with resource limits, and the repository is private (mode 0700) while grading",
            "none": "WARNING: no sandbox (not root and no user namespaces): the candidate runs as this user and "
                    "could read the reference. Grades from this run are not protected against hostile code.",
        }[self.mode]

    def _bwrap_works(self) -> bool:
        code, _ = run(self.command(["/bin/true"], scratch=None, use="bwrap"), timeout=20)
        return code == 0

    def command(self, argv, scratch, writable=None, tmp_bytes=64 << 20, cpu_seconds=None, use=None):
        """argv run in the sandbox; `scratch` (read-only) is /sandbox inside bwrap, `writable` /out."""
        mode = use or self.mode
        limits = ["prlimit", *CANDIDATE_LIMITS] + ([] if os.environ.get("PATHLAB_SANITIZED") else [ADDRESS_SPACE])
        if cpu_seconds:
            limits.append(f"--cpu={int(cpu_seconds)}")
        if mode in ("bwrap", "uid") and self.root:
            limits.append(f"--nproc={CANDIDATE_PROCESSES}")
        prefix = limits + ["--"]
        if self.root and mode in ("bwrap", "uid"):
            prefix += ["setpriv", f"--reuid={SANDBOX_UID}", f"--regid={SANDBOX_UID}", "--clear-groups",
                       "--inh-caps=-all", "--bounding-set=-all", "--no-new-privs", "--"]
        sanitizer_options = [f"{name}={os.environ[name]}" for name in
                             ("TSAN_OPTIONS", "ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS") if name in os.environ]
        if mode != "bwrap":
            # A clean environment: the grader's variables are not the candidate's to read.
            return prefix + ["env", "-i", "PATH=/usr/bin:/bin", "TMPDIR=/tmp", "HOME=/tmp", "LANG=C.UTF-8",
                             *sanitizer_options] + argv  # (argv[0] is an absolute path: never an assignment)
        box = ["bwrap", "--unshare-all", "--die-with-parent", "--new-session",
               "--ro-bind", "/usr", "/usr", "--symlink", "usr/lib", "/lib", "--symlink", "usr/lib64", "/lib64",
               "--symlink", "usr/bin", "/bin", "--symlink", "usr/sbin", "/sbin",
               # Debian reaches some libraries (BLAS/LAPACK, which a build without
               # --as-needed links) through /etc/alternatives: links only, no secrets.
               "--ro-bind-try", "/etc/alternatives", "/etc/alternatives",
               "--proc", "/proc", "--dev", "/dev", "--size", str(tmp_bytes), "--tmpfs", "/tmp",
               "--clearenv", "--setenv", "PATH", "/usr/bin", "--setenv", "TMPDIR", "/tmp"]
        for name in ("TSAN_OPTIONS", "ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS"):
            if name in os.environ:  # suppression files are outside the sandbox
                box += ["--setenv", name, re.sub(r"(^|:)suppressions=[^:]*", "", os.environ[name])]
        if scratch:
            box += ["--ro-bind", str(scratch), "/sandbox"]
        if writable:
            box += ["--bind", str(writable), "/out"]
        return prefix + box + ["--chdir", "/tmp", "--"] + argv

    def path(self, scratch: Path, real: Path) -> str:
        """How a file under the read-only scratch folder is named inside the sandbox."""
        return "/sandbox/" + str(real.relative_to(scratch)) if self.mode == "bwrap" else str(real)

    def out_path(self, writable: Path, real: Path) -> str:
        return "/out/" + str(real.relative_to(writable)) if self.mode == "bwrap" else str(real)

    def give(self, path: Path) -> None:
        """Lets the sandbox uid own a folder it writes to (uid and bwrap modes as root)."""
        if self.root and self.mode in ("bwrap", "uid"):
            os.chown(path, SANDBOX_UID, SANDBOX_UID)

    def protect(self, paths) -> None:
        """uid mode: the repository, the build and the results are not readable by the sandbox uid."""
        if self.mode != "uid":
            return
        for path in paths:
            if path.exists():
                mode = stat.S_IMODE(path.stat().st_mode)
                self.protected.append((path, mode))
                os.chmod(path, 0o700)

    def restore(self) -> None:
        for path, mode in reversed(self.protected):
            try:
                os.chmod(path, mode)
            except OSError:
                pass
        self.protected = []

    def can_read(self, path: Path) -> bool:
        """Whether code in the sandbox can read `path` (the isolation check)."""
        code, _ = run(self.command(["/bin/sh", "-c", f"cat {shlex.quote(str(path))} > /dev/null"], scratch=None),
                      timeout=20)
        return code == 0

    def clean_up(self, stale: bool = False) -> None:
        """Kills every process of the sandbox uid and removes its files from the shared temporary folders.
        stale: also under bubblewrap, whose own /tmp vanishes with it but whose output folders live in
        the grader's scratch: what a grade killed before its cleanup left behind."""
        reap_orphans()
        if not (self.root and self.mode in ("bwrap", "uid")):
            return
        for _ in range(20):
            alive = []
            for pid in os.listdir("/proc"):
                if not pid.isdigit():
                    continue
                try:
                    if os.stat(f"/proc/{pid}").st_uid == SANDBOX_UID:
                        alive.append(int(pid))
                        os.kill(int(pid), signal.SIGKILL)
                except (OSError, ProcessLookupError):
                    pass
            reap_orphans()
            if not alive:
                break
            time.sleep(0.05)
        if self.mode == "uid" or stale:
            for folder in ("/tmp", "/var/tmp", "/dev/shm"):
                run(["find", folder, "-xdev", "-uid", str(SANDBOX_UID), "-delete"], timeout=60)
