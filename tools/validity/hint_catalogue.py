"""The catalogue of each suite's hints (tests/NN-name/hints.md, beside the
suite; docs/hints.md says how to read them): for every graded test, its
fixed hint and each check it makes, with the hint that check's failure
prints. Read from the suites' source (tests/NN-name/test_*.cpp), not from a
build.

A test with several checks must say what each one points to: every check
it reaches (in its body, or in a helper of its file it calls) lies under a
HINT(...) (grading.h), in the helper or around the call. A test with one
check keeps its fixed hint. No hint may hold a raw pointer or an ellipsis
that reads as a cut.

  tools/hint-catalogue            rewrite every suite's tests/NN-name/hints.md
  tools/hint-catalogue --check    exit 1 naming each test that breaks a rule, or a stale or missing
                                  tests/NN-name/hints.md (CTest hint-catalogue)
  tools/hint-catalogue --self-test  the rules catch what they should in a made-up suite"""
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

from tools import pathlab_tasks
from tools.cpp_tokens import Token, lex, string_value

ROOT = pathlab_tasks.ROOT
CHECK_MACROS = re.compile(r"(CHECK|REQUIRE|FAIL_CHECK|FAIL)(_[A-Z]+)*$")
KEYWORDS = {"if", "for", "while", "switch", "return", "catch", "sizeof", "decltype", "static_cast", "TEST_CASE"}


def tokens(source: str):
    """The suite's tokens (cpp_tokens.lex), each string literal (adjacent ones joined: "a" "b" is "ab") one
    token of kind "text" holding its characters."""
    out = []
    for t in lex(source):
        if t.kind == "string" and not t.text.startswith("'"):
            if out and out[-1].kind == "text":
                out[-1].text += string_value(t.text)
                out[-1].end = t.end
                continue
            t = Token("text", string_value(t.text), t.start, t.end, t.line)
        out.append(t)
    return out


@dataclass
class Check:
    line: int
    text: str           # the check as written, on one line
    hint: str | None    # the HINT in force, if any


@dataclass
class Body:
    name: str
    checks: list = field(default_factory=list)
    calls: list = field(default_factory=list)  # (callee name, hint in force at the call)
    computed: bool = False                      # calls hintForFailure


@dataclass
class TestCase:
    name: str
    points: int
    hint: str
    line: int
    body: Body


def matching(toks, i, open_char, close_char):
    """The index of the token closing the one at i."""
    depth = 0
    for j in range(i, len(toks)):
        if toks[j].kind == "op" and toks[j].text == open_char:
            depth += 1
        elif toks[j].kind == "op" and toks[j].text == close_char:
            depth -= 1
            if depth == 0:
                return j
    raise SystemExit(f"hint-catalogue: unmatched {open_char} at line {toks[i].line}")


def spelled(source, toks, start, end):
    """Tokens start..end as written, on one line."""
    return " ".join(source[toks[start].start:toks[end].end].split())


def read_body(name, source, toks, open_brace):
    """The checks, helper calls and HINTs of the block opening at open_brace."""
    body = Body(name)
    close = matching(toks, open_brace, "{", "}")
    scopes = [[]]  # per open block, the HINTs declared in it so far
    i = open_brace + 1
    while i < close:
        t = toks[i]
        if t.kind == "op" and t.text == "{":
            scopes.append([])
        elif t.kind == "op" and t.text == "}":
            scopes.pop()
        elif t.kind == "name" and i + 1 < close and toks[i + 1].text == "(":
            in_force = next((h for scope in reversed(scopes) for h in reversed(scope)), None)
            end = matching(toks, i + 1, "(", ")")
            if t.text == "HINT":
                literal = toks[i + 2]
                if literal.kind != "text" or end != i + 3:
                    raise SystemExit(f"hint-catalogue: {name}: HINT at line {t.line} takes one string literal")
                scopes[-1].append(literal.text)
                i = end
            elif CHECK_MACROS.fullmatch(t.text):
                body.checks.append(Check(t.line, spelled(source, toks, i, end), in_force))
                i = end
                continue
            elif t.text == "hintForFailure":
                body.computed = True
            elif t.text not in KEYWORDS and (i == 0 or toks[i - 1].text not in (".", "->", ">", ">>")):
                body.calls.append((t.text, in_force))
        i += 1
    return body, close


def parse(path: Path):
    """(test cases, helpers by name) of one suite file."""
    source = path.read_text()
    toks = tokens(source)
    tests, helpers = [], {}
    i = 0
    while i < len(toks):
        t = toks[i]
        if t.kind == "name" and t.text == "TEST_CASE" and toks[i + 1].text == "(":
            end = matching(toks, i + 1, "(", ")")
            name = toks[i + 2].text
            grading = next(j for j in range(i, end) if toks[j].text == "grading")
            points, hint = int(toks[grading + 2].text), toks[grading + 4].text
            body, close = read_body(name, source, toks, end + 1)
            tests.append(TestCase(name, points, hint, t.line, body))
            i = close + 1
            continue
        if t.kind == "op" and t.text == "{" and i > 0 and toks[i - 1].text in (")", "const", "override"):
            # A function's body at namespace scope (or a method's): its name precedes its parameters.
            j = i - 1
            while toks[j].text != ")":
                j -= 1
            depth, k = 0, j
            while True:
                if toks[k].text == ")":
                    depth += 1
                elif toks[k].text == "(":
                    depth -= 1
                    if depth == 0:
                        break
                k -= 1
            name = toks[k - 1].text if toks[k - 1].kind == "name" else "(lambda)"
            body, close = read_body(name, source, toks, i)
            if name not in KEYWORDS:
                helpers.setdefault(name, []).append(body)
            i = close + 1
            continue
        i += 1
    return tests, helpers


def reached(body, helpers, hint_at_call=None, seen=None):
    """Every check a body reaches, with the hint in force: its own HINT, else
    one around the call that reached it."""
    seen = set() if seen is None else seen
    out, computed = [], body.computed
    for check in body.checks:
        out.append((body.name, check, check.hint or hint_at_call))
    for callee, hint in body.calls:
        for helper in helpers.get(callee, []):
            if id(helper) in seen:
                continue
            seen.add(id(helper))
            more, more_computed = reached(helper, helpers, hint or hint_at_call, seen)
            out += more
            computed = computed or more_computed
    return out, computed


def problems_of_text(text):
    if re.search(r"0x[0-9a-fA-F]{4,}|%p", text):
        return ["holds a raw pointer"]
    if re.search(r"(\.\.\.|…)\s*$", text):
        return ["ends in an ellipsis, as if cut"]
    return []


def file_report(path: Path, shown: str):
    """(markdown lines, problems) for one suite file; `shown` names it in problems."""
    lines, problems = [], []
    tests, helpers = parse(path)
    for test in tests:
        checks, computed = reached(test.body, helpers)
        lines += [f"### {test.name} ({test.points} pts)", "", f"Fixed hint: {test.hint}", ""]
        for problem in problems_of_text(test.hint):
            problems.append(f"{shown}:{test.line}: {test.name}: its hint {problem}")
        sites = {(where, c.line): (where, c, hint) for where, c, hint in checks}
        for where, check, hint in sites.values():
            place = "" if where == test.name else f" (in {where})"
            lines.append(f"- line {check.line}{place}: `{check.text.replace('`', '')}`")
            lines.append(f"  - {hint if hint else '(the fixed hint)'}")
            if hint:
                for problem in problems_of_text(hint):
                    problems.append(f"{shown}:{check.line}: a HINT {problem}")
            elif len(sites) > 1:
                problems.append(f"{shown}:{check.line}: {test.name}: one of its {len(sites)} checks has no HINT "
                                f"(it would print the test's fixed hint)")
        if computed:
            lines.append("- computed hints (hintForFailure), by what failed together")
        if not sites:
            lines.append("- (its checks are in tests/support, shared by the suites)")
        lines.append("")
    return lines, problems


def catalogue():
    """({tests/NN-name/hints.md path: markdown}, problems): one page per suite."""
    pages, problems = {}, []
    for number, (folder, _) in sorted(pathlab_tasks.tasks().items()):
        files = sorted((ROOT / "tests" / folder).glob("test_*.cpp"))
        if not files:
            continue
        lines = [f"# Task {number}'s hints ({folder})", "",
                 "Generated by `tools/hint-catalogue` from this suite's source ([docs/hints.md](../../docs/hints.md)",
                 "says how to read it); CTest `hint-catalogue` checks it is current.", ""]
        for path in files:
            more_lines, more_problems = file_report(path, str(path.relative_to(ROOT)))
            lines += more_lines
            problems += more_problems
        pages[ROOT / "tests" / folder / "hints.md"] = "\n".join(lines)
    return pages, problems


SELF_TEST = r'''
namespace {
void helper(int x) { CHECK(x > 0); }
void hinted(int x) {
  HINT("x must be positive");
  CHECK(x > 0);
}
}  // namespace
TEST_CASE("T0.1 one check keeps its fixed hint" * grading(1, "fixed")) { CHECK(1 == 1); }
TEST_CASE("T0.2 two checks, one without a HINT" * grading(1, "fixed")) {
  { HINT("scoped"); CHECK(2 == 2); }
  helper(3);  // its check, under no HINT
}
TEST_CASE("T0.3 all hinted, a helper's own and one around a call" * grading(1, "fixed")) {
  const char* json = R"js({ "not": "a check: CHECK(x)" })js";
  HINT("around the call");
  helper(1);
  hinted(2);
}
TEST_CASE("T0.4 a pointer in a hint" * grading(1, "fixed")) {
  HINT("at 0x7ffd1234abcd");
  CHECK(1 == 1);
  HINT("cut...");
  CHECK(2 == 2);
}
'''


def self_test() -> int:
    """The rules fail what they should, on a made-up suite."""
    import tempfile
    with tempfile.TemporaryDirectory() as scratch:
        path = Path(scratch) / "test_made_up.cpp"
        path.write_text(SELF_TEST)
        _, problems = file_report(path, "made-up")
    expected = {("T0.2", "has no HINT"), ("T0.4", "raw pointer"), ("T0.4", "ellipsis")}
    got = set()
    for p in problems:
        for test, what in expected:
            if what in p and (test in p or what != "has no HINT"):
                got.add((test, what))
    unexpected = [p for p in problems if "T0.1" in p or "T0.3" in p]
    if got != expected or unexpected or len(problems) != 3:
        print("hint-catalogue self-test failed:", *problems, sep="\n  ", file=sys.stderr)
        return 1
    print("hint-catalogue self-test: the made-up suite's 3 problems found, nothing else")
    return 0


def main() -> int:
    if "--self-test" in sys.argv[1:]:
        return self_test()
    check = "--check" in sys.argv[1:]
    pages, problems = catalogue()
    for p in problems:
        print(p, file=sys.stderr)
    for out, text in pages.items():
        if not check:
            out.write_text(text)
        elif not out.exists() or out.read_text() != text:
            print(f"hint-catalogue: {out.relative_to(ROOT)} is stale: run tools/hint-catalogue", file=sys.stderr)
            problems.append(out)
    if problems:
        print(f"hint-catalogue: {len(problems)} problem(s)", file=sys.stderr)
        return 1
    print(f"hint-catalogue: {len(pages)} suites' hints {'current' if check else 'written'}")
    return 0
