#!/usr/bin/env python3
"""The include direction (docs/architecture.md, "Layers"): core depends on
nothing above it, the task APIs and task files on core only, the render
layer (and the apps) on anything below. Reads every `#include "pathlab/..."`
of the framework, the task files, the reference solutions and the apps;
fails on an upward include that is not in PENDING, on a PENDING entry that
no longer occurs (remove it: the list only shrinks), and on an include cycle
among the framework's headers.

usage: check_layers.py REPOSITORY"""
import re
import sys
from pathlib import Path

CORE, TASKS, RENDER, APPS = 0, 1, 2, 3
NAMES = ["core", "tasks", "render", "apps"]

# Headers by layer; tasks/*.h are the task APIs. Anything not listed is an error.
CORE_HEADERS = {"math.h", "ray.h", "random.h", "image.h", "scene.h", "camera.h", "frame.h", "hit.h", "aabb.h",
                "distribution.h", "error.h", "input_file.h", "todo.h", "parallel.h", "progress.h", "bsdf_sample.h"}
RENDER_HEADERS = {"accelerator.h", "leaf_geometry.h", "lights.h", "bsdf.h", "trace.h", "render.h",
                  "scene_intersect.h", "inspect.h", "debug_views.h", "draw.h", "scene_io.h", "obj_file.h",
                  "procedural.h"}

# Upward includes that exist today, each to be removed by issue 18's layering
# (file, included header). The check fails when one disappears, so this only shrinks.
PENDING = {
    ("framework/include/pathlab/tasks/bvh.h", "leaf_geometry.h"),
    ("framework/include/pathlab/tasks/direct_lighting.h", "bsdf.h"),
    ("framework/include/pathlab/tasks/direct_lighting.h", "lights.h"),
    ("framework/include/pathlab/tasks/direct_lighting.h", "trace.h"),
    ("framework/include/pathlab/tasks/path_tracing.h", "trace.h"),
    ("solutions/05-path-tracing/path_tracing.cpp", "bsdf.h"),
    ("tasks/05-path-tracing/path_tracing.cpp", "bsdf.h"),
}


def layer_of_header(name: str) -> int:
    if name.startswith("tasks/"):
        return TASKS
    if name in CORE_HEADERS:
        return CORE
    if name in RENDER_HEADERS:
        return RENDER
    raise SystemExit(f"check_layers: pathlab/{name} has no layer: add it to CORE_HEADERS or RENDER_HEADERS")


def layer_of_file(rel: str) -> int:
    if rel.startswith("apps/"):
        return APPS
    if rel.startswith("framework/include/pathlab/"):
        return layer_of_header(rel.removeprefix("framework/include/pathlab/"))
    if rel.startswith("framework/src/"):
        stem = Path(rel).stem
        if stem == "default_scene":
            return RENDER
        return layer_of_header(stem + ".h") if (stem + ".h") in CORE_HEADERS | RENDER_HEADERS else RENDER
    if rel.startswith(("tasks/", "solutions/")):
        return RENDER if rel.endswith("debugger.cpp") else TASKS  # a task's debugger is a view
    raise SystemExit(f"check_layers: {rel} has no layer")


def includes(path: Path):
    for line in path.read_text(errors="replace").splitlines():
        m = re.match(r'\s*#\s*include\s+"pathlab/([^"]+)"', line)
        if m:
            yield m.group(1)


def main() -> int:
    root = Path(sys.argv[1]).resolve()
    files = [p for pattern in ("framework/include/pathlab/**/*.h", "framework/src/*.cpp", "tasks/*/*.cpp",
                               "solutions/*/*.cpp", "apps/**/*.cpp", "apps/**/*.h") for p in root.glob(pattern)]
    found, problems = set(), []
    graph = {}
    for path in sorted(files):
        rel = str(path.relative_to(root))
        layer = layer_of_file(rel)
        for header in includes(path):
            target = layer_of_header(header)
            if rel.startswith("framework/include/pathlab/"):
                graph.setdefault(rel.removeprefix("framework/include/pathlab/"), set()).add(header)
            if target > layer:
                found.add((rel, header))
                if (rel, header) not in PENDING:
                    problems.append(f"{rel} ({NAMES[layer]}) includes pathlab/{header} ({NAMES[target]}): upward")
    for rel, header in sorted(PENDING - found):
        problems.append(f"PENDING lists {rel} -> {header}, which is gone: remove it from the list")
    # A cycle among headers: depth-first search with colours.
    state = {}

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
    for p in problems:
        print(p)
    pending = len(PENDING & found)
    print(f"{len(files)} files: {len(problems)} problems; {pending} upward includes still pending (issue 18)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
