"""Each grading platform's run of a handin, on this machine, as the platform
runs it: tools/try-platform's steps, and CTest platforms' and new-task's
(docs/ta-guide.md, "Try a handin on each platform").

  Gradescope    the zip (make-zip.sh) unpacked in a folder standing in for
                /autograder, setup.sh once, then run_autograder on the
                handin's files put flat in submission/; it reads
                results/results.json.
  Autolab       the image's files (the package's tree in IMAGE/opt/pathlab,
                tools/autolab/image-setup), an assessment (make-autograder);
                each job as Tango runs it: the handin, the autograde-Makefile
                and autograde.tar in a job folder owned by an unprivileged
                uid, `make` run as that uid with Tango's limits, no network,
                killed at the assessment's timeout, the output cut as
                autodriver cuts it; it reads the output's last line.
  PrairieLearn  the same image, a question per task (make-course); each job
                in /grade's layout (a scratch folder, PL_GRADE_ROOT), the
                question's entrypoint as root, no network, killed at its
                timeout; it reads results/results.json.
  Classroom     the workflow's steps (make-workflow): tools/check on the
                handin, then tools/classroom/report; the classroom records
                the total it prints ("Points X/Y").

Everything but Classroom runs as root (the grader's sandbox, a setuid helper,
jobs under another uid), on Linux, with the packages of tools/packages.sh."""
import json
import os
import shutil
import subprocess
import sys
import tarfile
import time
import zipfile
from dataclasses import dataclass
from pathlib import Path

from tools import pathlab_tasks

# Stands in for Tango's "autograde" user (PATHLAB_PLATFORMS_UID: tests running side by side use their own).
TANGO_UID = int(os.environ.get("PATHLAB_PLATFORMS_UID", "64995"))
TANGO_NPROC, TANGO_FSIZE, TANGO_OUTPUT = 100, 100 << 20, 1000 * 1024  # Tango's defaults
PL_RESULTS_BYTES = 1 << 20                                        # PrairieLearn reads at most 1 MB


class PlatformError(Exception):
    """A step of a platform's run failed: the package could not be made, or a job gave nothing readable."""


def run(argv, what, timeout=1800, quiet=False, **kw):
    started = time.time()
    p = subprocess.run([str(a) for a in argv], capture_output=True, text=True, timeout=timeout, **kw)
    if not quiet:
        print(f"  {what}: exit {p.returncode}, {time.time() - started:.0f} s", flush=True)
    return p


def compiler_cache(env: dict, tree: Path) -> dict:
    """The compiler cache's paths relative to the package's tree, as to the repository's."""
    if "CCACHE_BASEDIR" in env:
        env["CCACHE_BASEDIR"] = str(tree)
    elif shutil.which("ccache") and "CMAKE_CXX_COMPILER_LAUNCHER" not in env:
        env["CMAKE_CXX_COMPILER_LAUNCHER"] = "ccache"
    return env


def handin_files(tree: Path, tasks, handin) -> list:
    """[(the name a student hands in, the file)] for `tasks`: "stubs" and "reference" are the package's
    own (tasks/ and solutions/); a folder holds the student's files by their names (those it lacks are
    not handed in); a file is one task's file."""
    folders = pathlab_tasks.tasks(tree)
    if handin in ("stubs", "reference"):
        return [(folders[n][1], tree / ("tasks" if handin == "stubs" else "solutions") / folders[n][0] / folders[n][1])
                for n in tasks]
    handin = Path(handin)
    if handin.is_file():
        return [(handin.name, handin)]
    return [(folders[n][1], handin / folders[n][1]) for n in tasks if (handin / folders[n][1]).is_file()]


# ---------------------------------------------------------------- the Autolab and PrairieLearn image

@dataclass
class Image:
    """The image's root in a scratch folder: the tree where both Dockerfiles put it, and Autolab's helper."""
    root: Path

    @property
    def tree(self) -> Path:
        return self.root / "opt/pathlab"

    @property
    def helper(self) -> Path:
        return self.root / "usr/local/bin/pathlab-autolab-grade"


def make_image(source: Path, root: Path, tasks=None) -> Image:
    """The image as the Dockerfiles make it: the course's tree as every packager packages it
    (tools/package-tree), then tools/autolab/image-setup (the judges built; the helper setuid root).
    The packages must be installed (PATHLAB_SKIP_APT=1). Every folder down to the tree is readable by
    others, as a Dockerfile's COPY makes it, for the job's unprivileged uid."""
    image = Image(root)
    listed = ["--tasks", ",".join(map(str, tasks))] if tasks else []
    packaged = run([sys.executable, source / "tools/package-tree", image.tree, *listed], "package-tree", quiet=True)
    if packaged.returncode != 0:
        raise PlatformError(packaged.stderr.strip())
    print(f"  {packaged.stderr.strip()}")  # the tree packaged, and how it differs from HEAD
    env = compiler_cache(dict(os.environ, PATHLAB_SKIP_APT="1", PATHLAB_IMAGE_PREFIX=str(root)), image.tree)
    made = run(["bash", image.tree / "tools/autolab/image-setup"], "image: tools/autolab/image-setup", env=env)
    if made.returncode != 0:
        raise PlatformError(f"the image's set-up failed:\n{made.stdout[-3000:]}{made.stderr[-3000:]}")
    mode = image.helper.stat()
    if not (mode.st_mode & 0o4000 and mode.st_uid == 0):
        raise PlatformError(f"{image.helper} is not setuid root")
    for folder in [root, *root.parents][:-1]:
        if folder.stat().st_mode & 0o005 != 0o005:
            raise PlatformError(f"{folder} is not readable by others: the grading uid cannot reach the image")
    return image


# ---------------------------------------------------------------- Autolab

@dataclass
class Assessment:
    folder: Path      # the assessment as Autolab imports it
    name: str
    problems: list    # [(name, max_score)], the yml's
    handin: str       # the handin's file name
    timeout: int
    columns: list     # the scoreboard's
    yml: dict


def autolab_assessment(image: Image, out: Path, tasks, per: str) -> Assessment:
    """tools/autolab/make-autograder's tarball, unpacked as Autolab imports it; its yml read with a YAML parser."""
    import yaml  # Debian's python3-yaml (tools/packages.sh)
    made = run([sys.executable, image.tree / "tools/autolab/make-autograder", out, "--tasks", ",".join(map(str, tasks)),
                "--per", per, "--build-dir", image.tree / "build-grade"],
               f"make-autograder --tasks {','.join(map(str, tasks))} --per {per}")
    if made.returncode != 0:
        raise PlatformError(f"make-autograder:\n{made.stderr[-2000:]}")
    name = "pathlab-tasks-" + "-".join(map(str, tasks))
    with tarfile.open(out / f"{name}.tar") as tar:
        tar.extractall(out / "imported")
    folder = out / "imported" / name
    yml = yaml.safe_load((folder / f"{name}.yml").read_text())
    return Assessment(folder, name, [(p["name"], float(p["max_score"])) for p in yml["problems"]],
                      yml["general"]["handin_filename"], yml["autograder"]["autograde_timeout"],
                      json.loads(yml["scoreboard"]["colspec"])["scoreboard"], yml)


def tango_cut(output: bytes) -> bytes:
    """What autodriver keeps of a job's output: all of it, or its first and last halves of the limit."""
    if len(output) <= TANGO_OUTPUT:
        return output
    half = TANGO_OUTPUT // 2
    return output[:half] + b"\n...[excess bytes elided]...\n" + output[-half:]


@dataclass
class AutolabJob:
    autoresult: object  # the last line, decoded (None when it is not JSON)
    feedback: str       # what the student reads: the output as autodriver keeps it
    feedback_file: Path
    timed_out: bool
    seconds: float


def autolab_job(image: Image, assessment: Assessment, files, job: Path, uid: int = TANGO_UID) -> AutolabJob:
    """One job as Tango runs it. `files` is None for a missing handin; several files are zipped."""
    shutil.rmtree(job, ignore_errors=True)
    job.mkdir(parents=True)
    shutil.copy(assessment.folder / "autograde-Makefile", job / "Makefile")
    shutil.copy(assessment.folder / "autograde.tar", job / "autograde.tar")
    if files:
        if assessment.handin.endswith(".zip"):
            with zipfile.ZipFile(job / assessment.handin, "w") as z:
                for name, source in files:
                    z.write(source, name)
        else:
            shutil.copy(files[0][1], job / assessment.handin)
    for path in [job, *job.rglob("*")]:
        os.chown(path, uid, uid)
    env = {"PATH": "/usr/bin:/bin", "LANG": "C.UTF-8", "PATHLAB_AUTOLAB_GRADE": str(image.helper),
           "PATHLAB_SANDBOX": "uid",  # Docker's seccomp denies bubblewrap's namespaces: the grader's uid mode
           "PATHLAB_SANDBOX_UID": os.environ.get("PATHLAB_SANDBOX_UID", "")}
    started = time.time()
    try:
        p = subprocess.run(["unshare", "--net", "setpriv", f"--reuid={uid}", f"--regid={uid}", "--clear-groups",
                            "prlimit", f"--nproc={TANGO_NPROC}", f"--fsize={TANGO_FSIZE}", "--", "make"],
                           cwd=job, env=env, capture_output=True, timeout=assessment.timeout)
        output, timed_out = tango_cut(p.stdout + p.stderr), False
    except subprocess.TimeoutExpired as stopped:
        output, timed_out = tango_cut((stopped.stdout or b"") + (stopped.stderr or b"")), True
    text = output.decode(errors="replace")
    feedback_file = job.parent / f"{job.name}.feedback.txt"
    feedback_file.write_text(text)
    last = text.rstrip("\n").rsplit("\n", 1)[-1]
    try:
        autoresult = json.loads(last)
    except ValueError:
        autoresult = None
    return AutolabJob(autoresult, text, feedback_file, timed_out, time.time() - started)


# ---------------------------------------------------------------- PrairieLearn

def prairielearn_course(image: Image, out: Path, tasks) -> dict:
    """tools/prairielearn/make-course's questions: {task: its folder}."""
    made = run([sys.executable, image.tree / "tools/prairielearn/make-course", out, "--tasks",
                ",".join(map(str, tasks))], f"make-course --tasks {','.join(map(str, tasks))}")
    if made.returncode != 0:
        raise PlatformError(f"make-course:\n{made.stderr[-2000:]}")
    folders = pathlab_tasks.tasks(image.tree)
    return {n: out / "questions/pathlab" / folders[n][0] for n in tasks}


@dataclass
class PrairieLearnJob:
    results: object     # results.json, decoded (None when missing, over 1 MB or not JSON)
    results_file: Path
    size: int
    timed_out: bool
    seconds: float


def prairielearn_job(image: Image, question: Path, files, grade: Path) -> PrairieLearnJob:
    """One job as PrairieLearn runs it: /grade's layout in `grade`, the entrypoint as root, no network."""
    info = json.loads((question / "info.json").read_text())["externalGradingOptions"]
    shutil.rmtree(grade, ignore_errors=True)
    for sub in ("student", "serverFilesCourse", "data", "results"):
        (grade / sub).mkdir(parents=True)
    shutil.copytree(question / "tests", grade / "tests")
    for name, source in files:
        shutil.copy(source, grade / "student" / name)
    (grade / "data/data.json").write_text(json.dumps({"params": {}, "correct_answers": {}, "submitted_answers": {
        "_files": [{"name": n} for n, _ in files]}, "gradable": True}))
    entrypoint = image.root / info["entrypoint"].lstrip("/")
    env = {"PATH": "/usr/bin:/bin", "LANG": "C.UTF-8", "PL_GRADE_ROOT": str(grade), "PATHLAB_SANDBOX": "uid",
           "PATHLAB_SANDBOX_UID": os.environ.get("PATHLAB_SANDBOX_UID", "64990")}
    started, timed_out = time.time(), False
    try:
        subprocess.run(["unshare", "--net", str(entrypoint)], env=env, capture_output=True, timeout=info["timeout"])
    except subprocess.TimeoutExpired:
        timed_out = True
    out = grade / "results/results.json"
    size = out.stat().st_size if out.exists() else 0
    results = None
    if out.exists() and size <= PL_RESULTS_BYTES:
        try:
            results = json.loads(out.read_text())
        except ValueError:
            pass
    return PrairieLearnJob(results, out, size, timed_out, time.time() - started)


# ---------------------------------------------------------------- Gradescope

def unpack(archive: Path, into: Path) -> None:
    """Like unzip: the files and their permission bits (zipfile.extractall drops them)."""
    with zipfile.ZipFile(archive) as z:
        for info in z.infolist():
            target = Path(z.extract(info, into))
            mode = (info.external_attr >> 16) & 0o7777
            if mode and not info.is_dir():
                os.chmod(target, mode)


def gradescope_setup(source: Path, autograder: Path, tasks) -> dict:
    """The zip for `tasks` (make-zip.sh), unpacked in `autograder`/source as Gradescope unpacks it,
    setup.sh run there once and run_autograder copied beside it; the environment of its runs."""
    archive = autograder / "autograder.zip"
    autograder.mkdir(parents=True, exist_ok=True)
    made = run(["bash", source / "tools/gradescope/make-zip.sh", archive, "--tasks", ",".join(map(str, tasks))],
               f"make-zip.sh --tasks {','.join(map(str, tasks))}")
    if made.returncode != 0:
        raise PlatformError(f"make-zip.sh:\n{made.stderr[-2000:]}")
    print("".join(f"  {line}\n" for line in made.stderr.splitlines() if line.startswith("package-tree:")), end="")
    unpack(archive, autograder / "source")
    env = compiler_cache(dict(os.environ, AUTOGRADER_ROOT=str(autograder), PATHLAB_SKIP_APT="1"),
                         autograder / "source/source")
    setup = run(["bash", "./setup.sh"], "setup.sh", cwd=autograder / "source", env=env)
    if setup.returncode != 0:
        raise PlatformError(f"setup.sh:\n{setup.stdout[-3000:]}{setup.stderr[-2000:]}")
    shutil.copy(autograder / "source/run_autograder", autograder / "run_autograder")  # as Gradescope does
    return env


def gradescope_job(autograder: Path, env: dict, files, timeout: int = 900) -> Path:
    """run_autograder on `files` put flat in submission/; the results.json Gradescope reads."""
    submission, results = autograder / "submission", autograder / "results"
    for folder in (submission, results):
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir()
    for name, source in files:
        shutil.copy(source, submission / name)
    with open(results / "stdout", "w") as log:  # as Gradescope's harness keeps it
        subprocess.run([str(autograder / "run_autograder")], cwd=autograder, env=env, stdout=log,
                       stderr=subprocess.STDOUT, timeout=timeout)
    return results / "results.json"


# ---------------------------------------------------------------- GitHub Classroom

def classroom_job(source: Path, tasks, files, work: Path, build_dir=None):
    """The workflow's steps on the handin: tools/check, then tools/classroom/report (its log, and the
    total the classroom records); (report's output, the results tools/check wrote)."""
    submission = work / "submission"
    shutil.rmtree(submission, ignore_errors=True)
    submission.mkdir(parents=True)
    for name, path in files:
        shutil.copy(path, submission / name)
    out = work / "pathlab-results.json"
    listed = ",".join(map(str, tasks))
    build = ["--build-dir", build_dir] if build_dir else []
    run([sys.executable, source / "tools/check", submission, "--tasks", listed, "--out", out, *build],
        f"tools/check --tasks {listed}")
    report = run([sys.executable, source / "tools/classroom/report", out, "--tasks", listed],
                 "tools/classroom/report")
    return report.stdout + report.stderr, out
