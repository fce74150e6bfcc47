"""The grader's sandbox (tools/grade): runs untrusted commands — compiling
the student's file and running the candidate — as an unprivileged uid inside
bubblewrap, or with limits only where namespaces are missing. See Sandbox."""
import os
import re
import shlex
import shutil
import signal
import stat
import threading
import time
from pathlib import Path

from .processes import reap_orphans, run

SANDBOX_UID = int(os.environ.get("PATHLAB_SANDBOX_UID", "64990"))  # a uid nothing else uses
CANDIDATE_LIMITS = ["--nofile=256", "--fsize=67108864", "--core=0"]
ADDRESS_SPACE = "--as=8589934592"  # 8 GB; not under sanitizers, whose shadow memory reserves terabytes
CANDIDATE_PROCESSES = 64     # RLIMIT_NPROC of the sandbox uid: a fork bomb stops here
# The judge's own memory (own_memory): beyond it the judge is stopped and its
# test case fails (every suite's test cases stay under 70 MB: docs/ta-guide.md).
# PATHLAB_JUDGE_MEMORY for a course whose own tests need more.
JUDGE_MEMORY = int(os.environ.get("PATHLAB_JUDGE_MEMORY", 224 << 20))
GRADER_MEMORY = 320 << 20    # what the grader, its judge and the page cache they need keep for themselves


def container_memory_limit():
    """The tightest memory limit on this process, in bytes: cgroup v2's
    memory.max of its cgroup and every parent, or cgroup v1's
    memory.limit_in_bytes; None when nothing limits it (Gradescope's
    container is such a cgroup: 768 MB by default)."""
    try:
        lines = Path("/proc/self/cgroup").read_text().splitlines()
    except OSError:
        return None
    limits = []
    for line in lines:
        hierarchy, controllers, path = (line.split(":", 2) + ["", ""])[:3]
        if hierarchy == "0" and not controllers:
            base, files = Path("/sys/fs/cgroup"), ["memory.max"]
        elif "memory" in controllers.split(","):
            base, files = Path("/sys/fs/cgroup/memory"), ["memory.limit_in_bytes"]
        else:
            continue
        group = Path("/") / path.lstrip("/")
        while True:  # the group and its parents (inside a container, "/" is the container's own)
            for name in files:
                try:
                    value = (base / str(group).lstrip("/") / name).read_text().strip()
                    if value.isdigit() and int(value) < 1 << 60:
                        limits.append(int(value))
                except OSError:
                    pass
            if group == group.parent:
                break
            group = group.parent
    return min(limits) if limits else None


def submission_memory():
    """Memory of all the sandbox's processes together (resident, System V and
    RAM-backed files included): one submission's, whatever it forks. 8 GB, or
    the container's limit less GRADER_MEMORY where that is less, so that a
    submission is stopped by the grader (and loses its own tests) before the
    container runs out. PATHLAB_SANDBOX_MEMORY for a course's own."""
    if "PATHLAB_SANDBOX_MEMORY" in os.environ:
        return int(os.environ["PATHLAB_SANDBOX_MEMORY"])
    limit = container_memory_limit()
    return min(8 << 30, max(64 << 20, limit - GRADER_MEMORY)) if limit else 8 << 30


SUBMISSION_MEMORY = submission_memory()
SHM_BYTES = 16 << 20         # bubblewrap's /dev/shm (its /tmp: Sandbox.command's tmp_bytes)


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
        self.denied = []     # world-writable folders closed to the sandbox uid: (path, mode or None for an ACL)
        self.confine = None  # pathlab-confine, where the sandbox uid can run it (uid mode)
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
        if shutil.which("choom"):
            # When the container runs out of memory, the kernel kills the
            # submission's processes first, never the grader or the judge
            # (tools/grade lowers its own score: protect_grader_from_oom).
            prefix = ["choom", "-n", "1000", "--"] + prefix
        if self.root and mode in ("bwrap", "uid"):
            prefix += ["setpriv", f"--reuid={SANDBOX_UID}", f"--regid={SANDBOX_UID}", "--clear-groups",
                       "--inh-caps=-all", "--bounding-set=-all", "--no-new-privs", "--"]
        sanitizer_options = [f"{name}={os.environ[name]}" for name in
                             ("TSAN_OPTIONS", "ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS") if name in os.environ]
        if mode != "bwrap":
            # No sockets, IPC or key rings (pathlab-confine: what bubblewrap's
            # namespaces do), and a clean environment: the grader's variables
            # are not the candidate's to read.
            confine = [self.confine] if self.confine and mode == "uid" else []
            return prefix + confine + ["/usr/bin/env", "-i", "PATH=/usr/bin:/bin", "TMPDIR=/tmp", "HOME=/tmp", "LANG=C.UTF-8",
                             *sanitizer_options] + argv  # (argv[0] is an absolute path: never an assignment)
        box = ["bwrap", "--unshare-all", "--die-with-parent", "--new-session",
               "--ro-bind", "/usr", "/usr", "--symlink", "usr/lib", "/lib", "--symlink", "usr/lib64", "/lib64",
               "--symlink", "usr/bin", "/bin", "--symlink", "usr/sbin", "/sbin",
               # Debian reaches some libraries (BLAS/LAPACK, which a build without
               # --as-needed links) through /etc/alternatives: links only, no secrets.
               "--ro-bind-try", "/etc/alternatives", "/etc/alternatives",
               "--proc", "/proc", "--dev", "/dev", "--size", str(SHM_BYTES), "--tmpfs", "/dev/shm",
               "--size", str(tmp_bytes), "--tmpfs", "/tmp",
               "--clearenv", "--setenv", "PATH", "/usr/bin", "--setenv", "TMPDIR", "/tmp"]
        for name in ("TSAN_OPTIONS", "ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS"):
            if name in os.environ:  # suppression files are outside the sandbox
                box += ["--setenv", name, re.sub(r"(^|:)suppressions=[^:]*", "", os.environ[name])]
        if scratch:
            box += ["--ro-bind", str(scratch), "/sandbox"]
        if writable:
            box += ["--bind", str(writable), "/out"]
        # The root and /dev are tmpfs too (RAM): read-only, so only the bounded
        # /tmp and /dev/shm and the grader's /out take files.
        return prefix + box + ["--remount-ro", "/dev", "--remount-ro", "/", "--chdir", "/tmp", "--"] + argv

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

    def can_read(self, path: Path) -> bool:
        """Whether code in the sandbox can read `path` (the isolation check)."""
        code, _ = run(self.command(["/bin/sh", "-c", f"cat {shlex.quote(str(path))} > /dev/null"], scratch=None),
                      timeout=20)
        return code == 0

    def clean_up(self, stale: bool = False) -> None:
        """Kills every process of the sandbox uid and removes what it left in the
        shared places: files in the world-writable folders, System V IPC objects.
        stale: also under bubblewrap, whose own /tmp vanishes with it but whose
        output folders live in the grader's scratch: what a grade killed before
        its cleanup left behind."""
        reap_orphans()
        if not (self.root and self.mode in ("bwrap", "uid")):
            return
        kill_every_process_of_sandbox()
        reap_orphans()
        if self.mode == "uid" or stale:
            for folder in world_writable_folders():
                run(["find", folder, "-xdev", "-uid", str(SANDBOX_UID), "-delete"], timeout=60)
            remove_ipc_objects()

    def deny_shared_folders(self) -> None:
        """uid mode: the world-writable folders (/tmp, /dev/shm, /run/lock, ...)
        take no files from the sandbox uid while grading: a POSIX ACL entry for
        that uid alone, search only (it still reaches its own scratch folder
        under /tmp). RAM-backed ones would hold memory no limit counts, and any
        of them could carry data to the next submission. Where a file system
        has no ACLs the folder loses its write bit for others instead."""
        if not (self.root and self.mode == "uid"):
            return
        for folder in world_writable_folders():
            path = Path(folder)
            mode = stat.S_IMODE(path.stat().st_mode)
            try:
                os.getxattr(folder, ACL_XATTR)
                has_acl = True
            except OSError:
                has_acl = False
            try:
                if has_acl:
                    raise OSError("the folder has an ACL of its own")
                os.setxattr(folder, ACL_XATTR, search_only_acl(mode), os.XATTR_CREATE)
                self.denied.append((path, None))
            except OSError:
                os.chmod(path, mode & ~0o002)
                self.denied.append((path, mode))

    def restore(self) -> None:
        for path, mode in reversed(self.protected):
            try:
                os.chmod(path, mode)
            except OSError:
                pass
        self.protected = []
        for path, mode in reversed(self.denied):
            try:
                if mode is None:
                    os.removexattr(path, ACL_XATTR)
                else:
                    os.chmod(path, mode)
            except OSError:
                pass
        self.denied = []


# ------------------------------------------------------------ the sandbox uid's traces

ACL_XATTR = "system.posix_acl_access"


def search_only_acl(mode: int) -> bytes:
    """A POSIX access ACL (the kernel's xattr form) keeping `mode` for everyone
    but SANDBOX_UID, which may only pass through (--x)."""
    import struct
    undefined = 0xFFFFFFFF
    group = (mode >> 3) & 7
    entries = [(0x01, (mode >> 6) & 7, undefined),  # owner
               (0x02, 1, SANDBOX_UID),               # the sandbox uid: search only
               (0x04, group, undefined),             # owning group
               (0x10, group | 1, undefined),         # mask (lets the entry above through)
               (0x20, mode & 7, undefined)]          # others
    return struct.pack("<I", 2) + b"".join(struct.pack("<HHI", *e) for e in entries)


_world_writable = None


def world_writable_folders():
    """Folders anyone may write to, four levels deep from / (found once per
    grade: /tmp, /var/tmp, /dev/shm, /run/lock, /dev/mqueue and their like)."""
    global _world_writable
    if _world_writable is None:
        code, out = run(["find", "/", "-maxdepth", "4", "(", "-path", "/proc", "-o", "-path", "/sys", ")", "-prune",
                         "-o", "-type", "d", "-perm", "-0002", "-print"], timeout=60)
        found = {line for line in out.splitlines() if line.startswith("/")}
        _world_writable = sorted(found | {f for f in ("/tmp", "/var/tmp", "/dev/shm", "/run/lock", "/dev/mqueue")
                                          if os.path.isdir(f)})
    return _world_writable


def sandbox_processes(include_zombies: bool = False):
    """Pids of the sandbox uid's processes (zombies hold no memory: left out by default)."""
    found = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            if os.stat(f"/proc/{pid}").st_uid != SANDBOX_UID:
                continue
            if not include_zombies:
                with open(f"/proc/{pid}/stat", "rb") as f:
                    if f.read().rsplit(b")", 1)[1].split()[0] == b"Z":
                        continue
            found.append(int(pid))
        except (OSError, IndexError):
            pass
    return found


def kill_every_process_of_sandbox() -> None:
    """Kills all of the sandbox uid's processes at once: kill(-1, SIGKILL) sent
    *as that uid* reaches every process it may signal in one pass the kernel
    makes with forking locked out, so a fork chain cannot outrun it (a loop
    over /proc can be outrun). Repeated until none is left but zombies."""
    for _ in range(200):
        if not sandbox_processes():
            return
        pid = os.fork()
        if pid == 0:  # no exec: the sandbox uid's process limit never applies
            try:
                os.setgroups([])
                os.setresgid(SANDBOX_UID, SANDBOX_UID, SANDBOX_UID)
                os.setresuid(SANDBOX_UID, SANDBOX_UID, SANDBOX_UID)
                os.kill(-1, signal.SIGKILL)
            finally:
                os._exit(0)
        os.waitpid(pid, 0)
        time.sleep(0.01)  # processes in the kernel finish dying


def sysvipc(kind: str):
    """The System V objects of one kind ("shm", "sem", "msg") in this process's
    IPC namespace, each a {column: value} of /proc/sysvipc/KIND."""
    try:
        lines = Path(f"/proc/sysvipc/{kind}").read_text().splitlines()
    except OSError:
        return []
    columns = lines[0].split() if lines else []
    return [dict(zip(columns, line.split())) for line in lines[1:]]


def ipc_objects():
    """(kind flag for ipcrm, id, resident bytes) of the sandbox uid's System V objects."""
    found = []
    for kind, flag in (("shm", "-m"), ("sem", "-s"), ("msg", "-q")):
        for fields in sysvipc(kind):
            if fields.get("uid") == str(SANDBOX_UID) or fields.get("cuid") == str(SANDBOX_UID):
                found.append((flag, fields.get("shmid") or fields.get("semid") or fields.get("msqid"),
                              int(fields.get("rss", 0))))
    return found


def remove_ipc_objects() -> None:
    for flag, ident, _ in ipc_objects():
        run(["ipcrm", flag, ident], timeout=20)


def sandbox_memory() -> int:
    """Bytes the sandbox uid holds in memory now: its processes' resident
    pages, its System V shared memory (in our IPC namespace, and in each
    namespace of its own that bubblewrap made), and the files in the RAM-backed
    /tmp and /dev/shm of each mount namespace of its own."""
    page = os.sysconf("SC_PAGE_SIZE")
    total = 0
    ipc_namespaces, mount_namespaces = {}, {}
    own_ipc, own_mnt = namespace("self", "ipc"), namespace("self", "mnt")
    for pid in sandbox_processes():
        try:
            with open(f"/proc/{pid}/statm", "rb") as f:
                total += int(f.read().split()[1]) * page
        except (OSError, IndexError, ValueError):
            continue
        ipc, mnt = namespace(pid, "ipc"), namespace(pid, "mnt")
        if ipc and ipc != own_ipc:
            ipc_namespaces.setdefault(ipc, pid)
        if mnt and mnt != own_mnt:
            mount_namespaces.setdefault(mnt, pid)
    total += sum(rss for _, _, rss in ipc_objects())
    total += sum(shared_memory_in_namespace(pid) for pid in ipc_namespaces.values())
    for pid in mount_namespaces.values():
        for folder in ram_folders(pid):
            try:
                fs = os.statvfs(f"/proc/{pid}/root{folder}")
                total += (fs.f_blocks - fs.f_bfree) * fs.f_frsize
            except OSError:
                pass
    return total


def ram_folders(pid: int):
    """/tmp and /dev/shm where they are RAM-backed (tmpfs) in the mount namespace of `pid`."""
    try:
        mounts = Path(f"/proc/{pid}/mounts").read_text().splitlines()
    except OSError:
        return []
    found = {fields[1] for fields in (line.split() for line in mounts)
             if len(fields) > 2 and fields[2] == "tmpfs" and fields[1] in ("/tmp", "/dev/shm")}
    return sorted(found)


def namespace(pid, kind: str) -> str:
    try:
        return os.readlink(f"/proc/{pid}/ns/{kind}")
    except OSError:
        return ""


def shared_memory_in_namespace(pid: int) -> int:
    """Resident bytes of the System V segments in the IPC namespace of `pid`:
    read by a child that joins that namespace (/proc/sysvipc shows the
    reader's own)."""
    if not hasattr(os, "setns"):
        return 0
    read, write = os.pipe()
    child = os.fork()
    if child == 0:
        total = 0
        try:
            os.close(read)
            fd = os.open(f"/proc/{pid}/ns/ipc", os.O_RDONLY)
            os.setns(fd, os.CLONE_NEWIPC)
            total = sum(int(fields.get("rss", 0)) for fields in sysvipc("shm"))
        except (OSError, ValueError):
            pass
        finally:
            os.write(write, str(total).encode())
            os._exit(0)
    os.close(write)
    with os.fdopen(read) as f:
        text = f.read()
    os.waitpid(child, 0)
    return int(text) if text.isdigit() else 0


def protect_grader_from_oom() -> None:
    """The grader and what it starts outside the sandbox (the judge) are never
    the kernel's choice when memory runs out (the sandbox's processes are, at
    +1000). Needs root; elsewhere the scores stay as they are."""
    try:
        Path("/proc/self/oom_score_adj").write_text("-1000")
    except OSError:
        pass


class MemoryWatch:
    """While a sandboxed command runs: every 50 ms, the memory of all the
    sandbox's processes together; over SUBMISSION_MEMORY, every one is killed
    and `exceeded` holds what was seen. (RLIMIT_AS bounds one process; this
    bounds the submission. A poll, not a cgroup — Gradescope's container
    offers none — so a burst can overshoot by what 50 ms of writing adds:
    the room GRADER_MEMORY leaves, and the OOM scores, cover that.)"""

    def __init__(self, active: bool, limit: int = SUBMISSION_MEMORY):
        self.active, self.limit = active, limit
        self.exceeded = 0
        self._stop = threading.Event()
        self._thread = None

    def __enter__(self):
        if self.active:
            self._thread = threading.Thread(target=self._watch, daemon=True)
            self._thread.start()
        return self

    def _watch(self):
        while not self._stop.wait(0.05):
            used = sandbox_memory()
            if used > self.limit:
                self.exceeded = max(self.exceeded, used)
                kill_every_process_of_sandbox()

    def __exit__(self, *_):
        self._stop.set()
        if self._thread:
            self._thread.join()

    def message(self) -> str:
        return (f"the submission's processes together used {self.exceeded / 2**30:.1f} GB of memory, over the "
                f"limit of {self.limit / 2**30:.1f} GB: all were stopped" if self.exceeded else "")
