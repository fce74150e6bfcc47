"""Hostile submissions made mechanically (tools/adversary; the attack suite
grader/tests/test_attacks.py and the host-programs test use the object-file
part): what a student could hand in to make the grader act on bytes they
control, or to earn points the work behind them does not.

This part: object files carrying sections that a toolchain acts on. A task
file may hold any bytes in a section of any name (an array with a section
attribute: no inline assembly), so its object can carry GCC's LTO IR, which
a linker's LTO plugin would compile at link time."""
import json
import os
import re
import shlex
import struct
import subprocess
import tempfile
from pathlib import Path

from tools import pathlab_tasks
from grader.driver import verdicts as verdict_format
from grader.driver.processes import link_command

ROOT = Path(__file__).resolve().parents[2]


def compile_argv(build: Path, task: int):
    """How `build` compiles task `task`'s file (compile_commands.json), as a list; run it in `build`."""
    folder, file_name = pathlab_tasks.tasks()[task]
    entry = next(e for e in json.loads((build / "compile_commands.json").read_text())
                 if e["file"].endswith(f"/{folder}/{file_name}"))
    return shlex.split(entry["command"])


def elf_sections(data: bytes):
    """(name, contents) of each section of a 64-bit little-endian ELF object."""
    offset, = struct.unpack_from("<Q", data, 0x28)
    entry_size, count, names = struct.unpack_from("<HHH", data, 0x3A)
    headers = [struct.unpack_from("<IIQQQQIIQQ", data, offset + i * entry_size) for i in range(count)]
    strings = headers[names][4]
    for name_at, _, _, _, at, size, *_ in headers:
        yield data[strings + name_at:data.index(b"\0", strings + name_at)].decode(), data[at:at + size]


def section_arrays(sections, prefix="section") -> str:
    """C++ that puts each (name, contents) into a section of that name, as a used constant array."""
    return "\n".join(f'__attribute__((section("{name}"), used)) const unsigned char {prefix}{i}[{len(body)}] = '
                     f'{{{",".join(map(str, body))}}};' for i, (name, body) in enumerate(sections))


def lto_sections(source: str, compile_command, scratch: Path) -> str:
    """`source` compiled by `compile_command` (compile_argv) with -flto into GCC's LTO IR alone, and the
    object's .gnu.lto_* sections written back as C++ arrays in sections of the same names."""
    scratch.mkdir(parents=True, exist_ok=True)
    (scratch / "ir.cpp").write_text(source)
    argv = list(compile_command)
    argv[argv.index("-o") + 1], argv[argv.index("-c") + 1] = str(scratch / "ir.o"), str(scratch / "ir.cpp")
    subprocess.run(argv + ["-w", "-flto", "-fno-fat-lto-objects"], check=True, capture_output=True)
    lto = [(name, body) for name, body in elf_sections((scratch / "ir.o").read_bytes()) if name.startswith(".gnu.lto_")]
    if not lto:
        raise RuntimeError("the compiler wrote no LTO sections")
    return section_arrays(lto, "lto")


# Sections a linker or a loader acts on, besides GCC's LTO IR: a warning ld prints, an interpreter and
# init functions the loader uses, a debug link, LLVM bitcode (the gold plugin's), debug info to parse.
TOOLCHAIN_SECTIONS = [(".gnu.warning.main", b"a linker warning a student wrote\0"),
                      (".interp", b"/tmp/pathlab-interpreter\0"),
                      (".init_array", bytes(8)),
                      (".gnu_debuglink", b"reference.debug\0" + bytes(4)),
                      (".llvm.lto", b"BC\xc0\xde" + bytes(28)),
                      (".debug_info", bytes(range(64)))]


def toolchain_sections_source(task: int, build: Path, scratch: Path) -> str:
    """Task `task`'s stub whose object carries its own code as GCC LTO IR and every TOOLCHAIN_SECTIONS."""
    folder, file_name = pathlab_tasks.tasks()[task]
    stub = (ROOT / "tasks" / folder / file_name).read_text()
    return "\n".join([stub, lto_sections(stub, compile_argv(build, task), scratch), section_arrays(TOOLCHAIN_SECTIONS)])


# ---------------------------------------------------------------------------
# Hostile answers made from the wire schema (tools/adversary): the stub's
# answers, rewritten by a proxy between the judge and the stub's server
# (tools/validity/adversary_proxy.inc), one strategy per candidate.

PROXY = Path(__file__).resolve().parent / "adversary_proxy.inc"
COMPACT = {"f32": "f", "f64": "d", "i8": "b", "u8": "B", "i16": "h", "u16": "H", "i32": "i", "u32": "I",
           "i64": "l", "u64": "L", "bool": "?"}
FLOAT_VALUES = ["nan", "inf", "-inf", "zero", "negzero", "big", "negbig", "tiny", "one", "negone"]
INTEGER_VALUES = ["zero", "one", "max", "min", "big"]
BOOL_VALUES = ["zero", "one", "invalid"]


def compact(schema: dict) -> str:
    """A schema (grader/wire/wire_schema.h's JSON) in the proxy's compact form."""
    kind = schema["t"]
    if kind == "tuple":
        return "(" + "".join(compact(s) for s in schema["of"]) + ")"
    if kind == "optional":
        return "o" + compact(schema["of"])
    if kind == "vector":
        return "*" + compact(schema["of"])
    if kind == "string":
        return "s"
    return COMPACT[kind]


def nodes(schema: dict, path: str = ""):
    """[(path, schema)] of every number, optional, vector and string, numbered as the proxy numbers them."""
    kind = schema["t"]
    if kind == "tuple":
        names = schema.get("names") or [str(i) for i in range(len(schema["of"]))]
        found = []
        for name, part in zip(names, schema["of"]):
            found += nodes(part, f"{path}.{name}" if path else name)
        return found
    here = [(path or "answer", schema)]
    if kind == "optional":
        return here + nodes(schema["of"], path + "?")
    if kind == "vector":
        return here + nodes(schema["of"], path + "[]")
    return here


def has_floats(schema: dict) -> bool:
    if schema["t"] in ("f32", "f64"):
        return True
    return any(has_floats(s) for s in schema.get("of", [])) if schema["t"] == "tuple" else \
        schema["t"] in ("optional", "vector") and has_floats(schema["of"])


def strategies(calls: dict):
    """Every strategy for a suite's calls ({id: {"name", "answer"}}, a candidate's --wire-schema), as
    (strategy string, description): each field of each answer given each extreme value, each optional
    flipped, each list's count forged, noise concentrated in one element, a quarter, a sixteenth or seven
    sixteenths of each list, every float echoed from the request or from the judge's last reply, a byte short or long."""
    found = []
    for call, info in sorted(calls.items(), key=lambda item: int(item[0])):
        name = info["name"]
        for index, (path, schema) in enumerate(nodes(info["answer"])):
            kind = schema["t"]
            at = f"call={call} node={index}"
            if kind in ("f32", "f64"):
                found += [(f"{at} kind=leaf value={v}", f"{name} {path} = {v}") for v in FLOAT_VALUES]
            elif kind == "bool":
                found += [(f"{at} kind=leaf value={v}", f"{name} {path} = {v}") for v in BOOL_VALUES]
            elif kind in COMPACT:
                found += [(f"{at} kind=leaf value={v}", f"{name} {path} = {v}") for v in INTEGER_VALUES]
            elif kind == "optional":
                found += [(f"{at} kind=flag value={v}", f"{name} {path}: {v}") for v in ("flip", "invalid")]
            else:
                found += [(f"{at} kind=count value={v}", f"{name} {path}: count {v}")
                          for v in ("plus", "minus", "zero", "huge")]
                if kind == "vector" and has_floats(schema["of"]):
                    found += [(f"{at} kind=spike value={v}", f"{name} {path}: noise in {v}")
                              for v in ("first", "every4", "every16", "seven16")]
        found += [(f"call={call} kind=echo value={v}", f"{name}: every float from the judge's {v}")
                  for v in ("request", "reply")]
        found += [(f"call={call} kind=bytes value={v}", f"{name}: a byte {v}") for v in ("short", "long")]
    return found


def wire_schema(candidate: Path) -> dict:
    """The calls a candidate serves and their answers' schemas (`candidate --wire-schema`)."""
    out = subprocess.run([str(candidate), "--wire-schema"], capture_output=True, text=True, timeout=60, check=True)
    return json.loads(out.stdout)


def adversary_source(task: int, calls: dict, strategy: str) -> str:
    """A task file: the stub, then the proxy, then its schema table and the strategy compiled in."""
    folder, file_name = pathlab_tasks.tasks()[task]
    table = "\n".join(f'    case {call}: return "{compact(info["answer"])}";' for call, info in
                      sorted(calls.items(), key=lambda item: int(item[0])))
    return ((ROOT / "tasks" / folder / file_name).read_text() + "\n" + PROXY.read_text() +
            f'\nnamespace pathlab_adversary {{\nconst char* const kAdversaryStrategy = "{strategy}";\n'
            f"const char* schemaOf(uint32_t call) {{\n  switch (call) {{\n{table}\n    default: return nullptr;\n"
            "  }\n}\n}  // namespace pathlab_adversary\n")


class Arena:
    """Builds each task's adversary candidate (the stub and the proxy, strategy chosen at run time by
    PATHLAB_ADVERSARY) in `build`, a Ninja build with the reference, learns which test cases make which
    calls, and judges strategies with the task's judge: a test case that passes is a survivor (the stub
    passes none)."""

    def __init__(self, build: Path, work: Path):
        self.build, self.work = build, work
        self.tasks = pathlab_tasks.tasks()
        self.candidates, self.calls_of_test, self.schemas = {}, {}, {}

    def prepare(self, task: int):
        folder, file_name = self.tasks[task]
        stub = self.build / "tests" / f"candidate-{folder}-stub"
        self.schemas[task] = wire_schema(stub if stub.exists() else self.build / "tests" / f"candidate-{folder}")
        reference = next(shlex.split(e["command"]) for e in json.loads((self.build / "compile_commands.json").read_text())
                         if e["file"] == str(ROOT / "solutions" / folder / file_name))
        reference_object = reference[reference.index("-o") + 1]
        scratch = self.work / folder
        scratch.mkdir(parents=True, exist_ok=True)
        source, obj, exe = scratch / file_name, scratch / "task.o", scratch / "candidate"
        source.write_text(adversary_source(task, self.schemas[task], "kind=none"))
        argv = list(reference)
        argv[argv.index("-o") + 1], argv[argv.index("-c") + 1] = str(obj), str(source)
        subprocess.run(argv + ["-w"] + pathlab_tasks.SUBMISSION_FLAGS, check=True, cwd=self.build, capture_output=True)
        link = [str(obj) if a == reference_object else a for a in link_command(self.build, str(Path("tests") / f"candidate-{folder}"))]
        link[link.index("-o") + 1] = str(exe)
        subprocess.run(link, check=True, cwd=self.build, capture_output=True)
        self.candidates[task] = exe
        # Which calls each test case makes, and that the stub's answers pass none of them.
        log = scratch / "calls.log"
        self.calls_of_test[task] = {}
        for name, _, _ in self.manifest(task):
            log.unlink(missing_ok=True)
            passed = self.judge(task, "kind=none", [name], log=log)
            if passed:
                raise RuntimeError(f"task {task}: the stub passes '{name}': the adversary has no baseline")
            self.calls_of_test[task][name] = set(log.read_text().split()) if log.exists() else set()
        # The proxy must rewrite what it is told to: every answer a byte long, which every judge refuses
        # (the message longer than its request allows, or a byte left over).
        tests = [name for name, calls in self.calls_of_test[task].items() if calls]
        self.judge(task, "call=0 kind=bytes value=long", tests[:1])
        if tests and not re.search(r"bytes too many|is over the limit", self.last_output):
            raise RuntimeError(f"task {task}: the proxy did not rewrite the answers of '{tests[0]}'")

    def manifest(self, task: int):
        folder, _ = self.tasks[task]
        listing = subprocess.run([str(self.build / "tests" / f"test-{folder}"), "--list-test-cases"],
                                 capture_output=True, text=True, timeout=60).stdout
        return verdict_format.parse_listing(listing)

    def judge(self, task: int, strategy: str, tests, log: Path = None, timeout: float = 300):
        """The test cases of `tests` that pass with this strategy."""
        folder, _ = self.tasks[task]
        handle, name = tempfile.mkstemp(prefix="verdicts-", dir=self.work / folder)  # judges run side by side
        os.close(handle)
        verdicts = Path(name)
        env = {k: v for k, v in os.environ.items() if not k.startswith("PATHLAB_")}
        env.update({verdict_format.CANDIDATE: str(self.candidates[task]), "PATHLAB_ADVERSARY": strategy,
                    verdict_format.VERDICT_FILE: str(verdicts),
                    verdict_format.IMAGE_FAILURES_DIR: str(self.work / "pictures")})
        if log:
            env["PATHLAB_ADVERSARY_LOG"] = str(log)
        escaped = ",".join(verdict_format.test_case_filter(name) for name in tests)
        try:
            run = subprocess.run([str(self.build / "tests" / f"test-{folder}"), f"--test-case={escaped}",
                                  "--no-version", "--no-intro"], env=env, cwd=self.work, capture_output=True,
                                 text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return []
        if "ADVERSARY: " in run.stdout:
            raise RuntimeError(f"task {task}, {strategy}: " + run.stdout.split("ADVERSARY: ", 1)[1].splitlines()[0])
        self.last_output = run.stdout
        judged = verdict_format.Verdicts.read(verdicts)
        verdicts.unlink()
        return [name for passed, _, name in judged.ran if passed]

    def tests_making(self, task: int, strategy: str):
        call = re.search(r"call=(\d+)", strategy).group(1)
        return [name for name, calls in self.calls_of_test[task].items() if call == "0" or call in calls]
