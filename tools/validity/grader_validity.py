"""Writes docs/grader-validity.md: for every mutant, its score and the tests
that caught it; for every alternate, its score. Runs the binaries a build
made, on the task files it generated (BUILD_DIR/tests/validity/, from each
task's tests/NN-name/validity.py; ctest -L validity runs the same checks).

usage: tools/grader-validity [BUILD_DIR]    (default: build)"""
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

root = Path(__file__).resolve().parents[2]


def describe(source: Path) -> str:
    first = source.read_text().splitlines()[0]
    text = first.split(":", 1)[1].strip().rstrip(".") if ":" in first else ""
    return text.replace("|", "\\|")  # pipes would break the markdown table


def run(build: Path, addresses: list, kind: str, suite: str, variant: str):
    # The suite's judge, asking the variant's candidate (as ctest -L validity does).
    judge = build / "tests" / f"test-{suite}"
    candidate = build / "tests" / f"candidate-{suite}-{kind}-{variant}"
    p = subprocess.run([str(judge)], capture_output=True, text=True, timeout=600, cwd=build / "tests",
                       env={**os.environ, "PATHLAB_CANDIDATE": str(candidate)})
    score = re.search(r"SCORE (\d+)/(\d+) points", p.stdout)
    caught = re.findall(r"^HINT \((.*?), \d+ pts\):", p.stdout, re.M)
    crashed = p.returncode < 0
    # A message with an address in it ("n = 3040x559f48048232") reads as a wrong number.
    for line in p.stdout.splitlines():
        if re.search(r"0x[0-9a-f]{6,}", line) and "PATHLAB" not in line:
            addresses.append(f"{suite}/{variant}: {line.strip()[:160]}")
    return (score.group(1), score.group(2)) if score else ("0", "?"), caught, crashed


def main() -> int:
    build = Path(sys.argv[1] if len(sys.argv) > 1 else root / "build").resolve()
    addresses = []  # output lines of any run that print a raw pointer
    lines = []  # the intro above the markers is hand-written
    mutants = sorted((build / "tests" / "validity" / "mutants").glob("*/*.cpp"))
    alternates = sorted((build / "tests" / "validity" / "alternates").glob("*/*.cpp"))
    if not mutants:
        raise SystemExit(f"grader-validity: no generated mutants in {build}/tests/validity (a build with the validity matrix)")
    caught_all = True
    lines += [f"## Mutants ({len(mutants)})", "", "| task | mutant | mistake | score | caught by |", "| --- | --- | --- | --- | --- |"]
    for source in mutants:
        suite, variant = source.parent.name, source.stem
        (got, total), caught, crashed = run(build, addresses, "mutants", suite, variant)
        caught_all &= got != total
        first = caught[0] if caught else ("a crash" if crashed else "NOTHING")
        more = f" (+{len(caught) - 1} more)" if len(caught) > 1 else ""
        lines.append(f"| {suite} | {variant} | {describe(source)} | {got}/{total} | {first}{more} |")
    lines += ["", f"## Alternates ({len(alternates)})", "", "| task | alternate | difference | score |", "| --- | --- | --- | --- |"]
    full_all = True
    for source in alternates:
        suite, variant = source.parent.name, source.stem
        (got, total), _, _ = run(build, addresses, "alternates", suite, variant)
        full_all &= got == total
        lines.append(f"| {suite} | {variant} | {describe(source)} | {got}/{total} |")
    lines += ["", f"All mutants lose points: {'yes' if caught_all else 'NO'}. All alternates score full points: {'yes' if full_all else 'NO'}.", ""]

    # Which ceiling each statistic a test judges has on the candidate's noise
    # (tests/support/statistics.h: a mean cannot be judged without one, so every
    # judged mean of every suite is here), from each suite run on the reference.
    lines += ["## Noise ceilings, per test", "",
              "Every mean a test judges within some standard errors, and every image comparison, caps the variance "
              "the candidate's answers show at what a correct answer can have: the largest the reference and the "
              "alternates show (stored by tools/make-reference-images), or a bound the values' range gives. "
              "`MeanEstimate` refuses to judge a mean without a ceiling, so no test can leave one out; this table "
              "is written from each suite run on the reference (`PATHLAB_NOISE_CATALOG`). Tests that judge no mean "
              "(exact values, chi-square counts against the judge's own expectation) are not listed.", "",
              "| test | statistics judged | ceiling |", "| --- | --- | --- |"]
    for folder in sorted(p for p in (root / "tests").iterdir() if re.match(r"\d\d-", p.name)):
        with tempfile.NamedTemporaryFile(mode="r", suffix=".tsv") as catalog:
            subprocess.run([str(build / "tests" / f"test-{folder.name}")], capture_output=True, timeout=900,
                           cwd=build / "tests", env={**os.environ, "PATHLAB_NOISE_CATALOG": catalog.name})
            seen = {}
            for line in catalog.read().splitlines():
                test, _, why = line.partition("\t")
                seen.setdefault(test, {}).setdefault(why, 0)
                seen[test][why] += 1
        for test, whys in seen.items():
            for why, count in whys.items():
                lines.append(f"| {test.replace('|', '/')} | {count} | {why.replace('|', '/')} |")
    lines.append("")
    # This tool owns the section between the validity markers; tools/image-test-seeds
    # and tools/coverage own theirs.
    doc = root / "docs" / "grader-validity.md"
    text = doc.read_text()
    begin, end = "<!-- validity:begin -->", "<!-- validity:end -->"
    head, rest = text.split(begin, 1)
    doc.write_text(head + begin + "\n" + "\n".join(lines) + end + rest.split(end, 1)[1])
    print(f"wrote docs/grader-validity.md: {len(mutants)} mutants ({'all caught' if caught_all else 'NOT all caught'}), "
          f"{len(alternates)} alternates ({'all full marks' if full_all else 'NOT all full marks'})")
    for line in addresses[:20]:
        print(f"a message prints an address: {line}")
    return 0 if caught_all and full_all and not addresses else 1
