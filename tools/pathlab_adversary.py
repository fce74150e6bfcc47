"""Hostile submissions made mechanically (the attack suite
tests/grader/test_attacks.py and the host-programs test use them): what a
student could hand in to make the grader act on bytes they control.

This part: object files carrying sections that a toolchain acts on. A task
file may hold any bytes in a section of any name (an array with a section
attribute: no inline assembly), so its object can carry GCC's LTO IR, which
a linker's LTO plugin would compile at link time."""
import json
import shlex
import struct
import subprocess
from pathlib import Path

import pathlab_tasks

ROOT = Path(__file__).resolve().parent.parent


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
