#!/usr/bin/env python3
"""What each task says about itself is well formed and names what exists:
its handout's title line and tasks/NN-name/task.json (tools/pathlab_tasks.py
checks the keys and their types), README.md's task table made from them,
each write-up figure's scene file and, for a view, a view that task has (`pathlab debug --list` of this build), and its
screenshot's scene and the views its script selects. The GUI and the
generated C++ take the same names (core/task_list.h), so a task whose
manifest passes here shows everywhere.

usage: check_task_manifests.py REPOSITORY PATHLAB"""
import re
import shlex
import subprocess
import sys
from pathlib import Path


def main() -> int:
    root, pathlab = Path(sys.argv[1]), sys.argv[2]
    sys.path.insert(0, str(root))  # the repository: the import root (docs/architecture.md)
    from tools import pathlab_tasks
    listing = subprocess.run([pathlab, "debug", "--list"], capture_output=True, text=True, check=True).stdout
    views = set(re.findall(r"^--task (\d+) --view (\S+)", listing, re.M))
    problems, labels = [], {}
    for n, (folder, _) in pathlab_tasks.tasks(root).items():
        where = f"tasks/{folder}/task.json"
        try:
            pathlab_tasks.title(n, root)
            manifest = pathlab_tasks.manifest(n, root)
        except SystemExit as e:
            problems.append(str(e))
            continue
        labels.setdefault(manifest["label"], []).append(n)

        def scene_of(words, what):
            for word in words:
                if word.endswith((".json", ".dae")) and not (root / word).is_file():
                    problems.append(f"{where}: {what} names {word}, which does not exist")

        for i, figure in enumerate(manifest["writeup"]):
            words = shlex.split(figure["args"])
            scene_of(words, f"writeup[{i}]")
            if figure["kind"] == "view":
                if "--task" in words:
                    problems.append(f"{where}: writeup[{i}]: a view's args leave out --task (tools/writeup adds it)")
                name = words[words.index("--view") + 1] if "--view" in words[:-1] else None
                if (str(n), name) not in views:
                    problems.append(f"{where}: writeup[{i}] shows view {name!r}, which task {n} does not have")
        scene_of([manifest["screenshot"]["scene"]] if manifest["screenshot"]["scene"] else [], "screenshot")
        for line in manifest["screenshot"]["script"]:
            verb, *args = line.split()
            if verb == "view" and (str(n), args[0] if args else "") not in views:
                problems.append(f"{where}: the screenshot selects view {args!r}, which task {n} does not have")
            if verb in ("panel", "quit", "screenshot"):
                problems.append(f"{where}: the screenshot's script has '{verb}' (tools/make-gui-screenshots adds it)")
    # The README's task table is the task folders' (a release rewrites its withheld tasks' rows).
    if not (root / pathlab_tasks.HANDED_OUT_FILE).exists() and not problems:
        readme = (root / "README.md").read_text()
        if pathlab_tasks.readme_with_task_table(readme, root) != readme:
            problems.append("README.md's task table is not the task folders' summary and contents "
                            "(python3 tools/pathlab_tasks.py readme-table writes it)")
    for label, tasks in labels.items():
        if len(tasks) > 1:
            problems.append(f"tasks {tasks} share the label {label!r}: the GUI could not tell their panels apart")
    for p in problems:
        print(p)
    print(f"{len(pathlab_tasks.tasks(root))} task manifests, {len(views)} views: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
