#!/usr/bin/env python3
"""The dependency direction (docs/architecture.md, "Layers").

The framework's folders are its layers: framework/util/, framework/core/, ...
Each is declared once, in framework/CMakeLists.txt, with the layers it sits
on (`pathlab_add_layer(render ON tasks)`); CMake hands the declarations to
this check. A file's layer is its folder, so a new file needs no entry
anywhere:
  framework/LAYER/*                  LAYER
  tasks/NN-name/debugger.cpp         debug (a task's debugger is a view)
  lab/*, tasks/NN-name/lab_warps.cpp lab: the sampling lab and the lecture demos'
                                     library, on top of every framework layer
                                     (a task's warps in the lab)
  tasks/NN-name/*.cpp, solutions/    tasks (task files)
  --variants DIR: DIR/*/NN-name/*.cpp
                                     tasks (the validity matrix's mutants and
                                     alternates, which a build generates)
  apps/, tests/, grader/             on top: may include any layer
An include names its layer: #include "core/scene.h" is framework/core/scene.h.
A file of a layer includes only framework headers, and a file of the lab
also lab/'s by their names (#include "lab_support.h"): never a header of
apps/, of grader/ (the wire protocol), of tests/ (the suites) or anything else
the build's include paths might find.

Fails on
  - an include of a layer the file's layer does not sit on, directly or
    through the layers below (an upward or sideways include);
  - an include of a framework header that does not exist;
  - in a layer's file (the framework, a task, the lab), an include of
    anything but the framework's headers (and, in the lab, lab/'s): an
    include from a task into apps/, or from the engine into the grader;
  - a folder in framework/ that is not a declared layer;
  - a cycle among the framework's headers, or among the declared layers;
  - a layer library (or, for the task APIs, the reference task objects)
    that uses a pathlab:: symbol that neither it nor a layer below defines:
    a call upward that an include check cannot see (a declaration written by
    hand).

usage: check_layers.py REPOSITORY --layer NAME:BELOW[,BELOW...][=ARCHIVE] ...
                       [--objects NAME=OBJECT[;OBJECT...]] ... [--variants DIR]
(tests/CMakeLists.txt passes the declarations and the built libraries.)"""
import argparse
import re
import subprocess
import sys
from pathlib import Path

TOP = "(top)"  # apps and tests: may include every layer
LAB = "lab"  # lab/ and the tasks' lab warps: on top of every framework layer, below apps


def parse_layers(specs):
    """{name: set of layers directly below}, {name: [archives/objects]}."""
    below, binaries = {}, {}
    for spec in specs:
        m = re.fullmatch(r"(\w+):([\w,]*)(?:=(.+))?", spec)
        if not m:
            raise SystemExit(f"check_layers: bad --layer {spec!r} (NAME:BELOW,...[=ARCHIVE])")
        below[m[1]] = {b for b in m[2].split(",") if b}
        binaries[m[1]] = [m[3]] if m[3] else []
    return below, binaries


def closure(below):
    """{layer: every layer it may use, itself included}; fails on a cycle."""
    reach = {}

    def visit(layer, path):
        if layer in path:
            raise SystemExit("check_layers: the layers form a cycle: " + " -> ".join(path + [layer]))
        if layer not in reach:
            if layer not in below:
                raise SystemExit(f"check_layers: {path[-1]} sits on {layer}, which is not a declared layer")
            reach[layer] = {layer}.union(*(visit(b, path + [layer]) for b in below[layer]))
        return reach[layer]

    for layer in below:
        visit(layer, [])
    return reach


def layer_of_file(rel: str, layers) -> str:
    parts = rel.split("/")
    if parts[0] == "framework":
        if parts[1] not in layers:
            raise SystemExit(f"check_layers: framework/{parts[1]}/ is not a layer: declare it in "
                             "framework/CMakeLists.txt (pathlab_add_layer) or move its files into one")
        return parts[1]
    if parts[0] == LAB:
        return LAB
    if parts[0] == "tasks":
        return {"debugger.cpp": "debug", "lab_warps.cpp": LAB}.get(parts[-1], "tasks")
    if parts[0] == "solutions":
        return "tasks"
    return TOP


def includes(path: Path):
    """(line number, the folder it names or "", the header) of each #include "..." (not <...>)."""
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
        if m:
            folder = re.match(r"(\w+)/", m.group(1))
            yield number, folder.group(1) if folder else "", m.group(1)


def source_files(root: Path):
    patterns = ("framework/**/*", "tasks/*/*.cpp", "solutions/*/*.cpp", "lab/*.cpp", "lab/*.h", "apps/**/*.cpp", "apps/**/*.h",
                "tests/**/*.cpp", "tests/**/*.h", "grader/**/*.cpp", "grader/**/*.h")
    return sorted({p for pattern in patterns for p in root.glob(pattern)
                   if p.is_file() and p.suffix in (".h", ".cpp", ".in")})


def header_exists(framework: Path, header: str) -> bool:
    return (framework / header).is_file() or (framework / (header + ".in")).is_file()  # .in: made by CMake


def find_cycles(graph):
    problems, state = [], {}

    def visit(node, stack):
        state[node] = 1
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                problems.append("include cycle: " + " -> ".join(stack[stack.index(nxt):] + [nxt]))
            elif state.get(nxt) is None:
                visit(nxt, stack + [nxt])
        state[node] = 2

    for node in sorted(graph):
        if state.get(node) is None:
            visit(node, [node])
    return problems


def symbols(binaries):
    """(defined, used) pathlab:: symbols of archives or object files."""
    defined, used = set(), set()
    if not binaries:
        return defined, used
    listing = subprocess.run(["nm", "-C", *binaries], check=True, capture_output=True, text=True).stdout
    for line in listing.splitlines():
        m = re.match(r"\s*(?:[0-9a-fA-F]+\s+)?([A-Za-z])\s+(pathlab::.*)$", line)
        if m:
            (used if m.group(1) == "U" else defined).add(m.group(2))
    return defined, used


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("root", type=Path)
    parser.add_argument("--layer", action="append", default=[])
    parser.add_argument("--objects", action="append", default=[])
    parser.add_argument("--variants", type=Path, help="the generated mutants and alternates (BUILD/tests/validity)")
    args = parser.parse_args()
    root = args.root.resolve()
    framework = root / "framework"
    below, binaries = parse_layers(args.layer)
    if not below:
        raise SystemExit("check_layers: no --layer given")
    for spec in args.objects:
        name, _, files = spec.partition("=")
        binaries.setdefault(name, []).extend(f for f in files.split(";") if f)
    reach = closure(below)
    reach[LAB] = set(below) | {LAB}
    problems = []
    for folder in sorted(p.name for p in framework.iterdir() if p.is_dir() and any(p.rglob("*.*"))):
        if folder not in below:
            problems.append(f"framework/{folder}/ is not a declared layer (framework/CMakeLists.txt: pathlab_add_layer)")

    files = source_files(root)
    variants = sorted((root / args.variants).glob("*/*/*.cpp")) if args.variants else []
    graph = {}
    for path in files + variants:
        rel = str(path.relative_to(root)) if path.is_relative_to(root) else str(path)
        layer = "tasks" if path in variants else layer_of_file(rel, below)
        for number, target, header in includes(path):
            if target not in below:
                # Not the framework's: apps and tests may (a suite's calls.h), the lab its own headers.
                if layer == LAB and "/" not in header and (root / "lab" / header).is_file():
                    continue
                if layer != TOP:
                    problems.append(f"{rel}:{number} ({layer}) includes {header}, which is not a framework header"
                                    + (" or one of lab/'s" if layer == LAB else "")
                                    + ": a layer includes only the layers below it")
                continue
            if not header_exists(framework, header):
                problems.append(f"{rel}:{number} includes {header}, which is not in framework/")
            if rel.startswith("framework/"):
                graph.setdefault(rel.removeprefix("framework/").removesuffix(".in"), set()).add(header)
            if layer != TOP and target not in reach[layer]:
                problems.append(f"{rel}:{number} ({layer}) includes {header} ({target}): {layer} sits on "
                                f"{', '.join(sorted(reach[layer] - {layer})) or 'nothing'}")
    problems += find_cycles(graph)

    checked = []
    listed = {name: symbols(built) for name, built in binaries.items()}  # (defined, used), one nm per layer
    for name, built in sorted(binaries.items()):
        if not built:
            continue
        checked.append(name)
        allowed = set().union(*(listed[layer][0] for layer in reach[name] if layer in listed))
        used = listed[name][1]
        problems += [f"{name}: {Path(built[0]).name} uses {symbol}, which no layer it sits on defines"
                     for symbol in sorted(used - allowed)]
    for p in problems:
        print(p)
    print(f"{len(below)} layers ({' < '.join(order(below))}), {len(files) + len(variants)} files' includes, "
          f"symbols of {', '.join(checked) or 'no library'}: {len(problems)} problems")
    return 1 if problems else 0


def order(below):
    """The layers bottom to top (a topological order, declaration order among equals)."""
    done = []
    while len(done) < len(below):
        done += [n for n in below if n not in done and below[n] <= set(done)][:1]
    return done


if __name__ == "__main__":
    sys.exit(main())
