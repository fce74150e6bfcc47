"""Grade a handin here as a grading platform would, before students do
(docs/ta-guide.md, "Try a handin on each platform"):

  sudo tools/try-platform PLATFORM --tasks LIST HANDIN... [--per task|test] [--out DIR] [--keep]
                                                             [--build-dir DIR]

PLATFORM is gradescope, autolab, prairielearn or classroom, several joined
by commas, or all (Autolab and PrairieLearn share one image). The package is
made from the working tree as every packager makes it (tools/package-tree;
an uncommitted task is in it), the way that platform is given it: the
Gradescope zip and its setup.sh, the Autolab image and assessment
(make-autograder, --per task or test), the PrairieLearn image and a question
per task, or GitHub Classroom's workflow steps (tools/check, then
tools/classroom/report). Then each HANDIN is graded as the platform runs a
job (tools/release/platforms.py says how, platform by platform):

  HANDIN  a folder with the student's files, named as they hand them in
          (the files of the tasks listed; those it lacks are not handed in),
          or `stubs` or `reference`: the package's own files for the tasks

For each handin it prints the points per task and the tests that lost
points, and copies the file the platform reads into --out (default
try-platform/PLATFORM/): Gradescope's and PrairieLearn's results.json,
Autolab's job output (its last line is the autoresult), Classroom's log and
tools/check's results. `stubs` must get 0 and `reference` every point, or
it says FAIL: run `stubs reference` before handing a package out.

Linux, as root (the grader's sandbox, Autolab's setuid helper and its
unprivileged uid), with PathLab's packages installed (tools/packages.sh);
classroom needs neither. The first grade builds the judges in a scratch
folder (minutes; a configured ccache is used). Exit 0 when every handin was
graded (and the stubs and reference got what they must), 1 otherwise, 2 on
bad arguments."""
import argparse
import json
import os
import shutil
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
from tools.release import platforms as platforms
from tools import pathlab_tasks

PLATFORMS = ("gradescope", "autolab", "prairielearn", "classroom")


def points_by_test(rows) -> dict:
    """[(test or problem name, points, maximum)] -> {task: [earned, possible]}."""
    tasks = {}
    for name, points, maximum in rows:
        n = int(name.split(":")[0].split()[1])  # "Task 3" or "Task 3: ..."
        tasks.setdefault(n, [0.0, 0.0])
        tasks[n][0] += points
        tasks[n][1] += maximum
    return tasks


def grade_gradescope(tasks, handins, work, out):
    env = platforms.gradescope_setup(ROOT, work / "autograder", tasks)
    tree = work / "autograder/source/source"
    for handin in handins:
        results = platforms.gradescope_job(work / "autograder", env, platforms.handin_files(tree, tasks, handin))
        kept = out / f"{label(handin)}.results.json"
        if not results.exists():
            yield handin, None, kept, "run_autograder wrote no results.json"
            continue
        shutil.copy(results, kept)
        report = json.loads(results.read_text())
        yield handin, [(t["name"], t["score"], t["max_score"]) for t in report["tests"]], kept, None


def image_of(work, tasks) -> platforms.Image:
    """The Autolab and PrairieLearn image, made once."""
    if not (work / "image/usr/local/bin/pathlab-autolab-grade").exists():
        return platforms.make_image(ROOT, work / "image", tasks)
    return platforms.Image(work / "image")


def grade_autolab(tasks, handins, work, out, per):
    image = image_of(work, tasks)
    assessment = platforms.autolab_assessment(image, work / "autolab", tasks, per)
    maxima = dict(assessment.problems)
    print(f"  assessment {assessment.name}.tar: {len(maxima)} problems, handin {assessment.handin}, "
          f"timeout {assessment.timeout} s (in {work / 'autolab'})")
    for handin in handins:
        files = platforms.handin_files(image.tree, tasks, handin)
        job = platforms.autolab_job(image, assessment, files, work / "autolab/jobs" / label(handin))
        kept = out / f"{label(handin)}.output.txt"
        shutil.copy(job.feedback_file, kept)
        scores = job.autoresult.get("scores") if isinstance(job.autoresult, dict) else None
        if job.timed_out or not isinstance(scores, dict) or set(scores) != set(maxima):
            yield handin, None, kept, ("the job passed the assessment's timeout" if job.timed_out else
                                       "the output's last line is not an autoresult of the assessment's problems")
            continue
        board = job.autoresult.get("scoreboard")
        print(f"  {label(handin)}: autoresult scoreboard {board}")
        yield handin, [(name, scores[name], maxima[name]) for name in maxima], kept, None


def grade_prairielearn(tasks, handins, work, out):
    image = image_of(work, tasks)
    questions = platforms.prairielearn_course(image, work / "prairielearn", tasks)
    for handin in handins:
        rows, why, kept = [], None, None
        for n in tasks:  # a question per task, the handin's file for it uploaded
            files = platforms.handin_files(image.tree, [n], handin)
            job = platforms.prairielearn_job(image, questions[n], files, work / "prairielearn/jobs" / f"{label(handin)}-{n}")
            kept = out / f"{label(handin)}.task{n}.results.json"
            if job.results_file.exists():
                shutil.copy(job.results_file, kept)
            if job.results is None:
                why = f"task {n}: results.json missing, unreadable or over 1 MB ({job.size} bytes)"
                continue
            if job.results.get("gradable") is False:
                rows.append((f"Task {n}", 0.0, float(pathlab_tasks.handout_points(n, image.tree))))
                print(f"  {label(handin)}, task {n}: not gradable: {job.results.get('message', '')[:200]}")
                continue
            rows += [(t["name"], t["points"], t["max_points"]) for t in job.results["tests"]]
        if len(tasks) > 1:  # a results.json per question
            kept = f"{out}/{label(handin)}.taskN.results.json, N = {', '.join(map(str, tasks))}"
        yield handin, (None if why else rows), kept, why


def grade_classroom(tasks, handins, work, out, build_dir):
    for handin in handins:
        log, results = platforms.classroom_job(ROOT, tasks, platforms.handin_files(ROOT, tasks, handin), work,
                                               build_dir)
        kept = out / f"{label(handin)}.log.txt"
        kept.write_text(log)
        if not results.exists():
            yield handin, None, kept, "tools/check wrote no results"
            continue
        shutil.copy(results, out / f"{label(handin)}.results.json")
        total = next((line for line in log.splitlines() if line.startswith("Total points: ")), "no total")
        print(f"  {label(handin)}: the classroom records {total.removeprefix('Total points: ')}")
        report = json.loads(results.read_text())
        yield handin, [(t["name"], t["score"], t["max_score"]) for t in report["tests"]], kept, None


def label(handin) -> str:
    return handin if handin in ("stubs", "reference") else Path(handin).name


def verdict(handin, rows) -> list:
    """What `stubs` and `reference` must get; the problems."""
    if handin == "stubs" and any(points for _, points, _ in rows):
        return [f"the stubs scored on {[n for n, p, _ in rows if p][:3]}: a stub must score 0"]
    if handin == "reference" and any(points != maximum for _, points, maximum in rows):
        return [f"the reference lost points on {[n for n, p, m in rows if p != m][:3]}"]
    return []


def try_platform(platform, tasks, handins, work, out, args) -> list:
    """Grades each handin on `platform`; the problems."""
    graders = {"gradescope": grade_gradescope, "autolab": lambda *a: grade_autolab(*a, args.per),
               "prairielearn": grade_prairielearn, "classroom": lambda *a: grade_classroom(*a, args.build_dir)}
    problems = []
    out.mkdir(parents=True, exist_ok=True)
    print(f"{platform}: tasks {', '.join(map(str, tasks))}")
    try:
        for handin, rows, kept, why in graders[platform](tasks, handins, work, out):
            if rows is None:
                problems.append(f"{platform} {label(handin)}: {why}")
                print(f"{platform} {label(handin)}: NOT GRADED: {why}; the platform reads {kept}")
                continue
            earned, possible = sum(r[1] for r in rows), sum(r[2] for r in rows)
            per_task = ", ".join(f"task {n} {e:g}/{p:g}" for n, (e, p) in sorted(points_by_test(rows).items()))
            print(f"{platform} {label(handin)}: {earned:g} of {possible:g} points ({per_task}); "
                  f"the platform reads {kept}")
            for name, points, maximum in rows:
                if points < maximum and handin != "stubs":
                    print(f"    {points:g}/{maximum:g}  {name}")
            for problem in verdict(handin, rows):
                problems.append(f"{platform} {label(handin)}: {problem}")
                print(f"  FAIL: {problem}")
    except platforms.PlatformError as error:
        problems.append(f"{platform}: {error}")
        print(f"FAIL: {platform}: {error}")
    return problems


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                                     usage="%(prog)s PLATFORM --tasks LIST HANDIN... [options]")
    parser.add_argument("platform", help=" | ".join(PLATFORMS) + ", several joined by commas, or all")
    parser.add_argument("handins", nargs="+", metavar="HANDIN")
    parser.add_argument("--tasks", required=True)
    parser.add_argument("--per", choices=("task", "test"), default="task", help="Autolab: a problem per task or test")
    parser.add_argument("--out", type=Path, help="where the files the platform reads are copied "
                                                  "(default try-platform/; a folder per platform)")
    parser.add_argument("--build-dir", type=Path, help="classroom: tools/check's build folder (default build-check/)")
    parser.add_argument("--keep", action="store_true", help="keep the scratch folder (the package and every job)")
    args = parser.parse_args()
    chosen = list(PLATFORMS) if args.platform == "all" else args.platform.split(",")
    if not chosen or any(p not in PLATFORMS for p in chosen):
        parser.error(f"PLATFORM {args.platform!r}: one of {', '.join(PLATFORMS)}, several joined by commas, or all")
    tasks = pathlab_tasks.parse_task_list(args.tasks, pathlab_tasks.tasks(ROOT))
    names = [name for _, name in (pathlab_tasks.tasks(ROOT)[n] for n in tasks)]
    for handin in args.handins:
        if handin in ("stubs", "reference"):
            continue
        if not Path(handin).exists():
            parser.error(f"{handin}: no such folder or file (a handin is a folder, a file, `stubs` or `reference`)")
        if not any(Path(handin).name == name or (Path(handin) / name).is_file() for name in names):
            parser.error(f"{handin}: holds none of the tasks' files ({', '.join(names)})")
    if chosen != ["classroom"] and os.geteuid() != 0:
        parser.error("gradescope, autolab and prairielearn run as root, as the platforms' graders do (the sandbox, "
                     "jobs under another uid): sudo tools/try-platform ...")
    if "autolab" in chosen and args.per == "test" and len(tasks) != 1:
        parser.error("--per test grades one task (its file is the handin)")
    out = (args.out or Path("try-platform")).resolve()
    # Outside the repository and readable by others: Autolab's jobs run as an unprivileged uid.
    work = Path(tempfile.mkdtemp(prefix="pathlab-try-platform-"))
    work.chmod(0o755)
    print(f"scratch: {work}")
    handins = [str(Path(h).resolve()) if h not in ("stubs", "reference") else h for h in args.handins]
    problems = []
    try:
        for platform in chosen:
            problems += try_platform(platform, tasks, handins, work, out / platform, args)
    finally:
        if args.keep or problems:
            print(f"scratch kept: {work}")
        else:
            shutil.rmtree(work, ignore_errors=True)
    return 1 if problems else 0
