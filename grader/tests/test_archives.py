"""Submission archives that are broken or hostile: every one must still give
a results.json. A member that cannot be unpacked safely (corrupt or
encrypted data, a link, a name too long, a file where a folder of the same
name is) is left out with a note and the rest is graded; an archive that
cannot be read at all, or unpacks to too much, scores 0 with a message.

usage: test_archives.py REPO_ROOT WORK_DIR GRADE_BUILD_DIR"""
import json
import shutil
import stat
import struct
import subprocess
import sys
import warnings
import zipfile
from pathlib import Path

root, build, grade_build = (Path(a).resolve() for a in sys.argv[1:4])
work = build / "archives"
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
reference = (root / "solutions/01-camera-rays/camera_rays.cpp").read_bytes()


def archive(name, members, deflate=True):
    """members: (name, bytes) or a ZipInfo with its bytes."""
    path = work / f"{name}.zip"
    warnings.filterwarnings("ignore", "Duplicate name")  # duplicates on purpose
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED if deflate else zipfile.ZIP_STORED) as z:
        for info, data in members:
            z.writestr(info, data)
    return path


def corrupt_member(path, member):
    """Overwrites the middle of `member`'s compressed bytes."""
    with zipfile.ZipFile(path) as z:
        info = z.getinfo(member)
    data = bytearray(path.read_bytes())
    name_len, extra_len = struct.unpack("<HH", data[info.header_offset + 26: info.header_offset + 30])
    start = info.header_offset + 30 + name_len + extra_len
    for i in range(start + 10, start + min(60, info.compress_size - 1)):
        data[i] ^= 0x5A
    path.write_bytes(bytes(data))


def set_flag(path, member, flag):
    """Sets a general-purpose flag bit of `member` in both of its headers (0x1: encrypted)."""
    data = bytearray(path.read_bytes())
    with zipfile.ZipFile(path) as z:
        info = z.getinfo(member)
    struct.pack_into("<H", data, info.header_offset + 6, info.flag_bits | flag)
    central = data.rfind(b"PK\x01\x02", 0, data.find(member.encode(), data.find(b"PK\x01\x02")))
    struct.pack_into("<H", data, central + 8, info.flag_bits | flag)
    path.write_bytes(bytes(data))


def link(name, target):
    info = zipfile.ZipInfo(name)
    info.external_attr = (stat.S_IFLNK | 0o777) << 16
    return info, target.encode()


cases = []  # (name, zip, expect full marks?, a phrase results.json must contain)
z = archive("corrupt-member", [("camera_rays.cpp", reference), ("notes.txt", b"hello " * 5000)])
corrupt_member(z, "notes.txt")
cases.append(("corrupt-member", z, True, "notes.txt: left out"))
z = archive("encrypted-member", [("camera_rays.cpp", reference), ("secret.txt", b"x" * 100)])
set_flag(z, "secret.txt", 0x1)
cases.append(("encrypted-member", z, True, "secret.txt: left out"))
cases.append(("long-name", archive("long-name", [("camera_rays.cpp", reference), ("d" * 300 + "/a.txt", b"x")]),
              True, "a name too long"))
cases.append(("file-and-folder", archive("file-and-folder", [("camera_rays.cpp", reference), ("x", b"file"),
                                                             ("x/y.txt", b"in a folder")]), True, "x/y.txt: left out"))
cases.append(("links", archive("links", [("camera_rays.cpp", reference), link("passwd", "/etc/passwd"),
                                         ("../escape.txt", b"x")]), True, "passwd: left out"))
cases.append(("duplicate-names", archive("duplicate-names", [("camera_rays.cpp", reference),
                                                             ("camera_rays.cpp", b"not C++")]), True, "left out"))
z = work / "truncated.zip"
z.write_bytes(archive("whole", [("camera_rays.cpp", reference)]).read_bytes()[:-30])
cases.append(("truncated", z, False, "not a readable zip archive"))
cases.append(("bomb", archive("bomb", [("camera_rays.cpp", reference), ("zeros.bin", bytes(80 << 20))]), False,
              "unpacks to more than"))

failures = []
for name, path, full, phrase in cases:
    out = work / f"{name}.json"
    grade = subprocess.run([sys.executable, str(root / "tools/grade"), str(path), "--tasks", "1", "--out", str(out),
                            "--build-dir", str(grade_build)], capture_output=True, text=True, timeout=900)
    problems = []
    if not out.exists():
        problems.append(f"no results.json (exit {grade.returncode}): {grade.stderr[-400:]}")
    else:
        report = json.loads(out.read_text())
        points = sum(t["max_score"] for t in report["tests"])
        text = out.read_text()
        if full and (points == 0 or report["score"] != points):
            problems.append(f"scored {report['score']:g} of {points:g}: the readable task file was not graded")
        if not full and report["score"] != 0:
            problems.append(f"scored {report['score']:g}, expected 0")
        if phrase not in text:
            problems.append(f"results.json does not say '{phrase}'")
    if (work / "escape.txt").exists() or (build / "escape.txt").exists():
        problems.append("a member was written outside the unpacking folder")
    print(f"{name:18s} {'ok' if not problems else 'FAIL: ' + '; '.join(problems)}")
    failures += problems
print(f"{len(cases) - len({f for f in failures})} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
