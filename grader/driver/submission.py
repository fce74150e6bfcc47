"""A submission as the grader takes it in (grading.py): a zip
unpacked within bounds, and each task's file found by its name."""
import stat
import os
import zipfile
import zlib
from pathlib import Path

from tools import pathlab_tasks

TASKS = pathlab_tasks.tasks()  # {n: (folder, file)}: the tasks/NN-name folders
MAX_ZIP_BYTES = 64 << 20     # what a submission zip may unpack to


def unpack_zip(path: Path, into: Path):
    """Unpacks what can be unpacked safely; returns a note per member left out
    (links, names that climb out or are too long, clashes, unreadable data).
    A zip that cannot be read at all raises ValueError."""
    notes = []
    try:
        archive = zipfile.ZipFile(path)
        members = archive.infolist()
    except (zipfile.BadZipFile, OSError, ValueError, RuntimeError, EOFError) as e:
        raise ValueError(f"{path.name} is not a readable zip archive ({e})") from None
    total = 0
    with archive:
        for info in members:
            name = Path(info.filename)
            shown = info.filename[:80]
            if info.is_dir():
                continue
            if name.is_absolute() or ".." in name.parts or stat.S_ISLNK(info.external_attr >> 16):
                notes.append(f"{shown}: left out (a link, or a path that leaves the archive)")
                continue
            if any(len(part.encode()) > 200 for part in name.parts) or len(info.filename.encode()) > 1000:
                notes.append(f"{shown}...: left out (a name too long)")
                continue
            target = into / name
            created = False
            try:
                target.parent.mkdir(parents=True, exist_ok=True)
                with archive.open(info) as src, open(target, "xb") as dst:
                    created = True
                    while chunk := src.read(1 << 16):
                        total += len(chunk)
                        if total > MAX_ZIP_BYTES:
                            raise ValueError(f"{path.name} unpacks to more than {MAX_ZIP_BYTES >> 20} MB")
                        dst.write(chunk)
            except ValueError:
                raise
            except (zipfile.BadZipFile, zlib.error, OSError, RuntimeError, EOFError, NotImplementedError) as e:
                # Corrupt or encrypted data, or a file where a folder of the same name is (or the reverse).
                reason = e.strerror if isinstance(e, OSError) and e.strerror else str(e)[:100]  # no grader paths
                notes.append(f"{shown}: left out ({type(e).__name__}: {reason})")
                if created:  # what this member began to write (never an earlier member of the same name)
                    target.unlink(missing_ok=True)
    return notes


def find_task_files(folder: Path):
    """For each task, the file graded and a note on what else was found."""
    by_name = {}
    for dirpath, dirnames, filenames in os.walk(folder):  # symbolic links are not followed
        dirnames[:] = sorted(d for d in dirnames if not d.startswith("."))
        for name in filenames:
            by_name.setdefault(name, []).append(Path(dirpath) / name)
    found = {}
    for task, (directory, file_name) in TASKS.items():
        paths = [p for p in by_name.get(file_name, []) if p.is_file() and not p.is_symlink()]
        if not paths:
            continue
        # A repository's tasks/NN-name/ copy first, then the shallowest.
        paths.sort(key=lambda p: (p.parent.name != directory, len(p.relative_to(folder).parts), str(p)))
        note = f" ({len(paths) - 1} other {file_name} ignored)" if len(paths) > 1 else ""
        found[task] = (paths[0], note)
    return found
