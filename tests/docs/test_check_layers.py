#!/usr/bin/env python3
"""check_layers.py, tested: a small tree of layers that passes, and one
violation at a time that must fail with the line that names it (an upward,
a sideways and a task file's include, an include from a task or the lab
into apps/ or from the engine into the grader, a missing header, an undeclared
folder, a header cycle, a layer cycle, and calls upward that only the
libraries' symbols show).

usage: test_check_layers.py CHECK_LAYERS_PY CXX AR"""
import subprocess
import sys
import tempfile
from pathlib import Path

# The paths below name a made-up tree (check_doc_paths: not checked).
check, cxx, ar = sys.argv[1:4]
LAYERS = ["util:", "core:util", "tasks:core", "scene:core", "render:tasks", "debug:render"]

# A tree that obeys the layers: each layer's header includes the one below.
BASE = {
    "framework/util/maths.h": "#pragma once\nnamespace pathlab { int twice(int x); }\n",
    "framework/util/maths.cpp": '#include "util/maths.h"\nnamespace pathlab { int twice(int x) { return 2 * x; } }\n',
    "framework/core/scene.h": '#pragma once\n#include "util/maths.h"\nnamespace pathlab { int scene(); }\n',
    "framework/core/scene.cpp": '#include "core/scene.h"\nnamespace pathlab { int scene() { return twice(1); } }\n',
    "framework/core/list.h.in": "#pragma once\n",
    "framework/tasks/api.h": '#pragma once\n#include "core/scene.h"\nnamespace pathlab { int task(); }\n',
    "framework/scene/load.h": '#pragma once\n#include "core/scene.h"\n',
    "framework/scene/load.cpp": '#include "scene/load.h"\n',
    "framework/render/render.h": '#pragma once\n#include "tasks/api.h"\nnamespace pathlab { int render(); }\n',
    "framework/render/render.cpp": '#include "render/render.h"\nnamespace pathlab { int render() { return task() + scene(); } }\n',
    "framework/debug/view.h": '#pragma once\n#include "render/render.h"\n',
    "tasks/01-one/one.cpp": '#include "tasks/api.h"\nnamespace pathlab { int task() { return scene(); } }\n',
    "tasks/01-one/debugger.cpp": '#include "debug/view.h"\n#include "render/render.h"\n',
    "solutions/01-one/one.cpp": '#include "tasks/api.h"\nnamespace pathlab { int task() { return scene(); } }\n',
    "tasks/01-one/lab_warps.cpp": '#include "lab_support.h"\n#include "render/render.h"\n',
    "lab/lab_support.h": '#pragma once\n#include "debug/view.h"\n',
    "lab/lab.cpp": '#include "lab_support.h"\n#include "scene/load.h"\n',
    "apps/main.cpp": '#include "debug/view.h"\n#include "scene/load.h"\n#include "core/list.h"\n#include "cli.h"\n',
    "apps/cli.h": '#pragma once\n#include "lab_support.h"\n',
    "tests/test.cpp": '#include "render/render.h"\n#include "calls.h"\n',
}

# (name, changed files, extra arguments, the line the check must print); None: must pass.
CASES = [
    ("the layered tree", {}, [], None),
    ("an upward include", {"framework/core/scene.cpp": '#include "render/render.h"\n'}, [],
     "framework/core/scene.cpp:1 (core) includes render/render.h (render)"),
    ("a sideways include", {"framework/scene/load.cpp": '#include "tasks/api.h"\n'}, [],
     "framework/scene/load.cpp:1 (scene) includes tasks/api.h (tasks)"),
    ("a task file including the render layer", {"tasks/01-one/one.cpp": '#include "render/render.h"\n'}, [],
     "tasks/01-one/one.cpp:1 (tasks) includes render/render.h (render)"),
    ("a generated mutant including the debug layer", {"build/tests/validity/mutants/01-one/m.cpp": '#include "debug/view.h"\n'},
     ["--variants", "build/tests/validity"],
     "build/tests/validity/mutants/01-one/m.cpp:1 (tasks) includes debug/view.h (debug)"),
    ("a task's lab warps including an app's header", {"tasks/01-one/lab_warps.cpp": '#include "cli.h"\n'}, [],
     "tasks/01-one/lab_warps.cpp:1 (lab) includes cli.h, which is not a framework header or one of lab/'s"),
    ("a task file including the lab", {"tasks/01-one/one.cpp": '#include "lab_support.h"\n'}, [],
     "tasks/01-one/one.cpp:1 (tasks) includes lab_support.h, which is not a framework header"),
    ("the engine including the grader's protocol", {"framework/core/list.h.in": '#pragma once\n#include "wire/wire.h"\n'},
     [], "framework/core/list.h.in:2 (core) includes wire/wire.h, which is not a framework header"),
    ("the lab including an app", {"lab/lab.cpp": '#include "../apps/cli.h"\n'}, [],
     "lab/lab.cpp:1 (lab) includes ../apps/cli.h, which is not a framework header or one of lab/'s"),
    ("an include of a header that is gone", {"apps/main.cpp": '#include "core/gone.h"\n'}, [],
     "apps/main.cpp:1 includes core/gone.h, which is not in framework/"),
    ("a folder that is no layer", {"framework/extra/x.h": "#pragma once\n"}, [],
     "framework/extra/ is not a layer"),
    ("a header cycle", {"framework/util/more.h": '#pragma once\n#include "util/other.h"\n',
                        "framework/util/other.h": '#pragma once\n#include "util/more.h"\n'}, [],
     "include cycle: util/more.h -> util/other.h -> util/more.h"),
    ("a layer cycle", {}, ["--layer", "util:debug"], "the layers form a cycle"),
    ("core calling the render layer (symbols only)",
     {"framework/core/scene.cpp": 'namespace pathlab { int render(); int scene() { return render(); } }\n'}, [],
     "core: libcore.a uses pathlab::render(), which no layer it sits on defines"),
    ("core calling a task (symbols only)",
     {"framework/core/scene.cpp": 'namespace pathlab { int task(); int scene() { return task(); } }\n'}, [],
     "core: libcore.a uses pathlab::task(), which no layer it sits on defines"),
    ("a task calling the render layer (symbols only)",
     {"solutions/01-one/one.cpp": 'namespace pathlab { int render(); int task() { return render(); } }\n'}, [],
     "tasks: one.o uses pathlab::render(), which no layer it sits on defines"),
]


def run_case(files, extra):
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        for rel, text in {**BASE, **files}.items():
            (root / rel).parent.mkdir(parents=True, exist_ok=True)
            (root / rel).write_text(text)
        args = []
        for spec in LAYERS:
            name = spec.split(":")[0]
            sources = sorted((root / "framework" / name).glob("*.cpp"))
            if sources:
                objects = []
                for source in sources:
                    obj = root / f"{name}-{source.stem}.o"
                    subprocess.run([cxx, "-c", "-I", str(root / "framework"), str(source), "-o", str(obj)], check=True)
                    objects.append(str(obj))
                archive = root / f"lib{name}.a"
                subprocess.run([ar, "qc", str(archive), *objects], check=True)
                spec += f"={archive}"
            args += ["--layer", spec]
        task_object = root / "one.o"
        subprocess.run([cxx, "-c", "-I", str(root / "framework"), str(root / "solutions/01-one/one.cpp"),
                        "-o", str(task_object)], check=True)
        args += ["--objects", f"tasks={task_object}"]
        result = subprocess.run([sys.executable, check, str(root), *args, *extra], capture_output=True, text=True)
        return result.returncode, result.stdout + result.stderr


def main() -> int:
    failures = 0
    for name, files, extra, expected in CASES:
        code, output = run_case(files, extra)
        if expected is None:
            ok = code == 0
        else:
            ok = code != 0 and expected in output
        print(f"{'ok  ' if ok else 'FAIL'} {name}")
        if not ok:
            failures += 1
            print(f"     exit {code}; expected {'a pass' if expected is None else repr(expected)}; printed:")
            print("     " + output.strip().replace("\n", "\n     "))
    print(f"{len(CASES)} cases, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
