"""What a judge tells the grader, read from grader/suite/verdicts.json, the
one definition the judge's C++ is made from too (grader/CMakeLists.txt
writes suite/verdicts.h from it). CTest verdict-round-trip checks that this
side reads what the judge writes.

  the listing:   JUDGE --list-test-cases prints "TEST <points> <visibility> <name>" per test case
  the verdicts:  $PATHLAB_VERDICT_FILE gets "PASS|FAIL <points> <name>" per test case run, "END" when the
                 run finished, and "LEADERBOARD asc|desc <value> <name>" per entry a test records"""
import json
import re
from pathlib import Path

SPEC = json.loads((Path(__file__).resolve().parents[1] / "suite" / "verdicts.json").read_text())
CANDIDATE = SPEC["environment"]["candidate"]  # the candidate program (or its launcher) the judge starts
VERDICT_FILE = SPEC["environment"]["verdict_file"]  # the file the judge writes its verdicts to
IMAGE_FAILURES_DIR = SPEC["environment"]["image_failures_dir"]  # where a failed image test writes its pictures
VISIBILITIES = tuple(SPEC["visibility"])
VISIBLE = VISIBILITIES[0]


def parse_listing(listing: str):
    """[(name, points, visibility)] of a judge's --list-test-cases output, in its order."""
    pattern = rf"^{re.escape(SPEC['listing'])} (\d+) (\w+) (.*)$"
    return [(m.group(3), int(m.group(1)), m.group(2)) for m in re.finditer(pattern, listing, re.M)]


def test_case_filter(name: str) -> str:
    """doctest's --test-case= value that selects exactly the test case `name` (a comma and a backslash
    escaped, a wildcard's characters matched by '?')."""
    return "".join("\\" + c if c in ",\\" else ("?" if c in "*[]" else c) for c in name)


class Verdicts:
    """One judge run's verdict file, read: `ran` holds (passed, points, name) per test case it judged,
    `finished` whether the run reached its end, `leaderboard` {name: entry} in Gradescope's
    results.json form. A line that follows no rule is ignored (the file is the judge's alone)."""

    def __init__(self, lines):
        self.ran, self.leaderboard, self.finished = [], {}, bool(lines) and lines[-1] == SPEC["end"]
        orders = {SPEC["lower_is_better"]: "asc", SPEC["higher_is_better"]: "desc"}
        for line in lines:
            parts = line.split(" ", 2)
            if parts[0] in (SPEC["pass"], SPEC["fail"]) and len(parts) == 3 and parts[1].isdigit():
                self.ran.append((parts[0] == SPEC["pass"], int(parts[1]), parts[2]))
            parts = line.split(" ", 3)
            if parts[0] == SPEC["leaderboard"] and len(parts) == 4 and parts[1] in orders:
                try:
                    self.leaderboard[parts[3]] = {"name": parts[3], "value": float(parts[2]), "order": orders[parts[1]]}
                except ValueError:
                    pass

    @classmethod
    def read(cls, path: Path):
        return cls(path.read_text(errors="replace").splitlines() if path.exists() else [])

    def passed_alone(self) -> bool:
        """The run judged exactly one test case, which passed, and finished."""
        return len(self.ran) == 1 and self.ran[0][0] and self.finished
