"""The include rule of a graded task file (grading.py): it
may read the framework's headers and the compiler's own, nothing else. What
the compiler searches, and every file the preprocessor opened."""
import os
import re
from pathlib import Path

from .processes import clip, run

ROOT = Path(__file__).resolve().parents[2]

# The framework's layer folders (framework/util, framework/core, ...): a task
# file includes their headers as "core/scene.h", and system headers.
LAYERS = sorted(p.name for p in (ROOT / "framework").iterdir() if p.is_dir())


def system_include_dirs(compiler: str, arguments):
    """The compiler's own header folders (#include <...> search list), as it reports them."""
    flags = [a for a in arguments if a.startswith(("-std=", "-stdlib=", "--target", "-nostdinc"))]
    code, out = run([compiler, "-xc++", *flags, "-E", "-v", "-o", os.devnull, os.devnull], timeout=60)
    dirs, inside = [], False
    for line in out.splitlines():
        if line.startswith("#include <...> search starts here"):
            inside = True
        elif line.startswith("End of search list"):
            break
        elif inside and line.startswith(" "):
            dirs.append(canonical(line.split(" (framework directory)")[0].strip()) + os.sep)
    if code != 0 or not dirs:
        raise RuntimeError(f"could not list {compiler}'s header folders:\n" + clip(out, 2000))
    return dirs


def canonical(path: str) -> str:
    """A path as the include check compares it: links resolved (and, on Windows, one case and one separator)."""
    return os.path.normcase(os.path.realpath(path))


def files_read(preprocessor_output: str, dependency_file: Path):
    """Every file the preprocessor opened or asked for: -H lines (". path",
    printed even before an error) and the -M -MG dependency list (which also
    has the implicit ones, and the missing ones)."""
    files = [m.group(1) for m in re.finditer(r"^\.+ (\S.*)$", preprocessor_output, re.M)]
    # A file it could not open stops it before -H or -M name it (uid mode: the repository is unreadable).
    files += re.findall(r"fatal error: (.+?): (?:Permission denied|Is a directory|No such file or directory)$",
                        preprocessor_output, re.M)
    if dependency_file.exists():
        files += dependency_file.read_text(errors="replace").replace("\\\n", " ").split(":", 1)[-1].split()
    return files
