"""Compile files of a build with -fsyntax-only: the build's own compiler and
flags (its compile_commands.json), no object written. CI's ASan stage builds
three suites per commit and checks the others' sources this way, so every
suite compiles under Clang with libc++ on every commit (tools/hardening.sh).

  tools/syntax-check BUILD PATTERN...   (a file matches a pattern when its path contains it)"""
import json
import os
import shlex
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

def check(entry):
    argv = shlex.split(entry["command"]) if "command" in entry else list(entry["arguments"])
    at = argv.index("-o")
    del argv[at:at + 2]
    return entry["file"], subprocess.run(argv + ["-fsyntax-only"], cwd=entry["directory"], capture_output=True,
                                         text=True)


def main() -> int:
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    build, patterns = Path(sys.argv[1]), sys.argv[2:]
    commands = json.loads((build / "compile_commands.json").read_text())
    chosen = [c for c in commands if any(p in c["file"] for p in patterns)]
    if not chosen:
        raise SystemExit(f"tools/syntax-check: no file in {build}/compile_commands.json matches {patterns}")
    with ThreadPoolExecutor(os.cpu_count() or 2) as pool:
        results = list(pool.map(check, chosen))
    for f, r in results:
        if r.stderr.strip():  # a warning is shown as the build shows it; an error fails
            print(f"{f}:\n{r.stderr[-3000:]}", file=sys.stderr)
    failed = sum(r.returncode != 0 for _, r in results)
    print(f"syntax-check: {len(results) - failed} of {len(results)} files compile")
    return 1 if failed else 0
