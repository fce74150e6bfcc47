"""Turning a student's task file into a candidate, for grading.py's Grader.
The file is compiled in the sandbox in three steps (the preprocessor alone,
held to the include rule; to assembly, refusing inline assembly; assembled),
then linked there with the framework and the reference for the other tasks.
No tool the host runs ever reads a byte the student wrote."""
import json
import os
import re
import shlex
import shutil
import tempfile
import time
from pathlib import Path

from tools import pathlab_tasks
from .include_rule import LAYERS, canonical, files_read, system_include_dirs
from .processes import clip, link_command, run
from .sandbox import MemoryWatch

ROOT = Path(__file__).resolve().parents[2]
TASKS = pathlab_tasks.tasks()  # {n: (folder, file)}: the tasks/NN-name folders
MAX_TASK_FILE = 1 << 20      # a task file larger than 1 MB is refused
TOOL_CPU_SECONDS = 120       # CPU seconds of one compiler or linker run in the sandbox
def build_target(build: Path, *targets):
    """The grader's own build of `targets` (judges, libraries): (ok, output). Never a student's byte."""
    code, out = run(["cmake", "--build", str(build), "--target", *targets, "--parallel", str(os.cpu_count() or 2)])
    return code == 0, out


def memory_watch(sandbox) -> MemoryWatch:
    """The submission's memory limit, over all its processes (sandbox.MemoryWatch)."""
    return MemoryWatch(sandbox.root and sandbox.mode in ("bwrap", "uid"))


def compile_command(build: Path, task: int):
    """The compiler line CMake uses for task `task`'s reference file, as a list."""
    directory, file_name = TASKS[task]
    entries = json.loads((build / "compile_commands.json").read_text())
    for entry in entries:
        if entry["file"].endswith(f"solutions/{directory}/{file_name}") or \
           entry["file"].endswith(f"tasks/{directory}/{file_name}"):
            return shlex.split(entry["command"])
    raise RuntimeError(f"no compile command for {file_name} in {build}")


class CandidateBuilder:
    """Compiles and links task files in `sandbox`, with the configured `build` (its compile and link lines),
    `objects` (where the build expects a submission's object) and `work` (the grade's scratch folder)."""

    def __init__(self, build: Path, objects: Path, work: Path, sandbox):
        self.build, self.objects, self.work, self.sandbox = build, objects, work, sandbox
        self.link_recipes = {}  # task: link_recipe(task)
        self._system_dirs = None

    def compile(self, task, source: Path, deadline: float):
        """The student's file compiled in the sandbox: (object path or None, message).
        Compiling counts against the task's time budget (`deadline`)."""
        directory, file_name = TASKS[task]
        if source.stat().st_size > MAX_TASK_FILE:
            return None, f"{file_name} is larger than {MAX_TASK_FILE >> 20} MB"
        scratch = Path(tempfile.mkdtemp(prefix=f"compile-{task}-", dir=self.work))
        os.chmod(scratch, 0o755)
        for layer in LAYERS:  # the framework's headers, by layer, as the build's include folder has them
            (scratch / "include" / layer).mkdir(parents=True)
            for header in (ROOT / "framework" / layer).glob("*.h"):
                shutil.copyfile(header, scratch / "include" / layer / header.name)
        task_dir = scratch / "tasks" / directory
        task_dir.mkdir(parents=True)
        shutil.copyfile(source, task_dir / file_name)
        out = scratch / "out"
        out.mkdir()
        self.sandbox.give(out)
        inside = lambda p: self.sandbox.path(scratch, p)
        skip = False
        compiler, *arguments = compile_command(self.build, task)
        command = [os.path.realpath(shutil.which(compiler) or compiler)]  # /usr/bin/c++ is a link into /etc
        for arg in arguments:
            if skip:
                skip = False
                continue
            if arg in ("-o", "-c", "-MF", "-MT", "-MQ"):
                skip = True
                continue
            if arg in ("-MD", "-MMD"):
                continue
            if arg.startswith("-I"):
                arg = "-I" + inside(scratch / "include")
            if arg.startswith("-fmacro-prefix-map="):
                arg = f"-fmacro-prefix-map={inside(scratch)}/="
            command.append(arg)
        command += pathlab_tasks.SUBMISSION_FLAGS
        source_inside = inside(task_dir / file_name)
        step = lambda arguments, longest: self.run_tool(arguments, scratch, out, longest, deadline, "compiling")
        # 1. The preprocessor alone: which files does the source read? Asked of
        # the compiler, so no spelling (digraphs, line splices, macros that
        # build a path) escapes. Only the framework's headers and the
        # compiler's own may be read; until that is known nothing the
        # preprocessor printed is shown (a diagnostic quotes the file it is about).
        # (-M -MG: a header that does not exist is listed too, as the path the
        # source asked for, so a path outside is refused even where it is missing.)
        code, output, stopped = step(
            command + ["-H", "-M", "-MG", "-MF", self.sandbox.out_path(out, out / "task.d"), source_inside], 150)
        if stopped:
            return None, f"{file_name} was not compiled: {stopped}."
        # Compared resolved: clang names its headers /usr/bin/../lib/gcc/...; a link
        # inside an allowed folder must not lead out of it.
        resolved = lambda f: os.path.normpath(f) if f.startswith("/sandbox/") else canonical(f)
        allowed = tuple(self.system_dirs(command[0], arguments)) + tuple(
            resolved(inside(folder)) + os.sep for folder in (scratch / "include", task_dir))
        outside = sorted({f for f in files_read(output, out / "task.d")
                          if f != source_inside and not resolved(f).startswith(allowed)})
        if outside:
            shown = ", ".join(f.replace(f"{inside(scratch)}/", "") for f in outside[:3])
            return None, (f"{file_name} includes files other than the framework's headers "
                          f"({', '.join(layer + '/...' for layer in LAYERS)}) and the compiler's own, or files "
                          f"that do not exist: {shown}. A task file may include only those headers.")
        if code != 0:
            return None, f"{file_name} did not compile:\n" + clip(re.sub(r"^\.+ .*\n?", "", output, flags=re.M)
                                                                 .replace(f"{inside(scratch)}/", ""))

        # 2. Compile to assembly (what the preprocessor read is allowed, so its
        # diagnostics may be shown); inline assembly is refused: `.incbin` and
        # its kin read files in the assembler, where no include check sees them.
        asm = out / "task.s"
        code, output, stopped = step(command + ["-S", source_inside, "-o", self.sandbox.out_path(out, asm)], 300)
        output = output.replace(f"{inside(scratch)}/", "")
        if stopped:
            return None, f"{file_name} was not compiled: {stopped}.\n" + clip(output)
        if code != 0 or not asm.exists():
            return None, f"{file_name} did not compile:\n" + clip(output)
        with open(asm, errors="replace") as text:
            # GCC marks inline assembly #APP (ELF) or /APP (Windows), clang "InlineAsm Start".
            if any(line.startswith(("#APP", "/APP")) or "InlineAsm Start" in line for line in text):
                return None, f"{file_name} contains inline assembly (asm), which a task file may not use."

        # 3. Assemble.
        obj = out / "task.o"
        code, output, stopped = step(
            [command[0], "-c", self.sandbox.out_path(out, asm), "-o", self.sandbox.out_path(out, obj)], 120)
        if stopped:
            return None, f"{file_name} was not assembled: {stopped}."
        if code != 0 or not obj.exists():
            return None, f"{file_name} did not assemble:\n" + clip(output)
        return obj, ""

    def run_tool(self, arguments, scratch, out, longest, deadline, what):
        """One untrusted tool run (the compiler, the linker) in the sandbox, `out` its only writable folder,
        within `longest` seconds and the time left before `deadline`: (exit code, output, why it stopped or "")."""
        left = min(longest, deadline - time.time())
        if left < 1:
            return None, "", f"the time budget was used up before {what} finished"
        with memory_watch(self.sandbox) as watch:
            code, output = run(self.sandbox.command(arguments, scratch, writable=out, cpu_seconds=TOOL_CPU_SECONDS),
                               timeout=left)
        if watch.exceeded:
            return None, output, f"{what} " + watch.message()
        if code is None:
            return None, output, f"{what} took longer than {left:.0f} s" + (" (the time budget)" if left < longest else "")
        return code, output, ""

    def link_recipe(self, task):
        """How the candidate of `task` is linked: (argv, inputs), the link command the build system would run
        for candidate-NN-submission (read from build.ninja, never run by the host: the sandbox links, in
        link_in_sandbox) and the files of the build folder it reads (the framework's libraries, the request
        loop, the suite's calls, the other tasks' reference objects), built here from the grader's own sources.
        The submission's object appears in argv as its placeholder path, the output as -o's argument."""
        if task in self.link_recipes:
            return self.link_recipes[task]
        directory, _ = TASKS[task]
        argv = link_command(self.build, f"candidate-{directory}-submission")
        output = argv[argv.index("-o") + 1]
        placeholder = (self.objects / f"task-{task}.o").resolve()
        inputs = [a for a in argv[1:] if not a.startswith("-") and a != output and not Path(a).is_absolute()
                  and (self.build / a).resolve() != placeholder]
        if not any((self.build / a).resolve() == placeholder for a in argv) or not inputs:
            raise RuntimeError(f"the link of candidate-{directory}-submission does not name {placeholder}")
        ok, out = build_target(self.build, *inputs)
        if not ok:
            raise RuntimeError(f"building the parts of candidate-{directory}-submission failed:\n" + clip(out))
        self.link_recipes[task] = argv, inputs
        return argv, inputs

    def link_in_sandbox(self, task, obj: Path, deadline: float):
        """The candidate linked from the submission's object `obj` in the sandbox, as the compiler ran: the
        linker (and anything it would start: GCC's LTO plugin reads sections of the object) acts on bytes
        the student controls, so it runs as the sandbox uid, within the task's time, its output in obj's
        folder. (candidate path or None, message)."""
        directory, file_name = TASKS[task]
        argv, inputs = self.link_recipe(task)
        scratch = Path(tempfile.mkdtemp(prefix=f"link-{task}-", dir=self.work))
        os.chmod(scratch, 0o755)
        for name in inputs:  # the grader's files, copied: the sandbox reads neither the build nor the repository
            (scratch / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(self.build / name, scratch / name)
        out = obj.parent
        candidate = out / "candidate"
        placeholder = (self.objects / f"task-{task}.o").resolve()
        output = argv[argv.index("-o") + 1]
        # The driver's temporary files go to `out` (uid mode closes /tmp to the sandbox uid).
        command = ["/usr/bin/env", f"TMPDIR={self.sandbox.out_path(out, out)}",
                   os.path.realpath(shutil.which(argv[0]) or argv[0])]
        for arg in argv[1:]:
            if arg == output:
                arg = self.sandbox.out_path(out, candidate)
            elif arg in inputs:
                arg = self.sandbox.path(scratch, scratch / arg)
            elif not arg.startswith("-") and (self.build / arg).resolve() == placeholder:
                arg = self.sandbox.out_path(out, obj)
            command.append(arg)
        # No link-time optimisation: nothing in the object may start a compiler at link time.
        command += ["-fno-lto"] + (["-fno-use-linker-plugin"] if "clang" not in Path(command[2]).name else [])
        code, output_text, stopped = self.run_tool(command, scratch, out, 120, deadline, "linking")
        shutil.rmtree(scratch, ignore_errors=True)
        if stopped:
            return None, f"{file_name} was not linked: {stopped}."
        if code != 0 or not candidate.exists():
            # The linker's own lines (the command line names the grader's folders).
            said = [l for l in output_text.splitlines()
                    if re.search(r"undefined reference|multiple definition|ld: |error:", l)]
            return None, (f"{file_name} did not link on its own (the reference for the other tasks, the "
                          "framework): does it use a function written in another task's file?\n" +
                          clip("\n".join(said) if said else output_text))
        return candidate, ""

    def link(self, task, obj: Path, deadline: float):
        """(the linked candidate or None, message). In the sandbox (link_in_sandbox); only tools/check on
        Windows, with no sandbox and the student's own bytes on the student's own machine, lets the build
        system link (its link lines there are not the POSIX ones link_recipe reads)."""
        if os.name != "nt":
            return self.link_in_sandbox(task, obj, deadline)
        directory, file_name = TASKS[task]
        (self.objects / f"task-{task}.o").write_bytes(obj.read_bytes())
        ok, out = build_target(self.build, f"candidate-{directory}-submission")
        if not ok:
            return None, f"{file_name} did not link on its own:\n" + clip(out)
        return self.build / "tests" / f"candidate-{directory}-submission.exe", ""

    def system_dirs(self, compiler, arguments):
        if self._system_dirs is None:
            self._system_dirs = system_include_dirs(compiler, arguments)
        return self._system_dirs
