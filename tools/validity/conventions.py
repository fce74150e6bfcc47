"""Convention alternates of a reference file, for tools/mutate: edits that
keep it correct, which every suite must give full marks."""
import re

from tools.cpp_tokens import Parsed, function_bodies, parse, statement_end
from tools.validity.mutants import Variants


# ---------------------------------------------------------------------------
# Convention alternates: one edit at a time of the reference that keeps it
# correct, as a student's differently written but right answer would be. A
# suite must give each full marks; a test that fails one pins a convention.
#   mirror-u   a random number u in [0, 1) of a sampler, mirrored on entry:
#              u -> ALMOST_ONE - u, which maps [0, 1) onto itself (1 - u
#              would reach 1 at u = 0)
#   swap-u     the two random numbers of a 2D sample exchanged on entry
#   coin       one comparison of a random number against a probability
#              decided by the mirrored number (u < p -> 1 - u < p: the same
#              probability, the other end of [0, 1))
#   draw       a sampler's draw mirrored or its two numbers exchanged where
#              the code takes it (sampler.next1D(), sampler.next2D())
#   reorder    two neighbouring statements that share no variable one of
#              them writes, exchanged
#   wrap       a coordinate kept below 1 by std::min(x, 1-) wrapped instead
#              (x < 1 ? x : x - 1): right for a periodic coordinate (an
#              angle's fraction), where 1 and 0 name the same place; listed
#              for review, since a clamp need not be periodic
# Each is correct by construction for uniform, independent random numbers,
# except a coin whose number the function uses again (then the two ends of
# [0, 1) are not interchangeable): those are listed for review with the
# suite's verdict. tests/mutants/conventions.txt lists the alternates that
# are not correct after all, with why; any other alternate that loses a
# point fails the run.

ALMOST_ONE = "0x1.fffffep-1f"  # the largest float below 1


RANDOM_NAME = re.compile(r"u\d?")


def random_operand(tokens, k, forward, randoms):
    """(first, last) token indices of a random number next to a comparison at k, or None:
    u, u.x, u.y (u a random parameter) or X.next1D()."""
    if forward:
        a = k + 1
        if a + 2 < len(tokens) and tokens[a].text in randoms and tokens[a + 1].text == "." and \
                tokens[a + 2].text in ("x", "y"):
            return a, a + 2
        if a + 4 < len(tokens) and tokens[a + 1].text == "." and tokens[a + 2].text == "next1D" and \
                tokens[a + 3].text == "(" and tokens[a + 4].text == ")":
            return a, a + 4
        if a < len(tokens) and tokens[a].text in randoms and tokens[a + 1].text not in (".", "(", "["):
            return a, a
        return None
    b = k - 1
    if b >= 2 and tokens[b].text in ("x", "y") and tokens[b - 1].text == "." and tokens[b - 2].text in randoms:
        return b - 2, b
    if b >= 4 and tokens[b].text == ")" and tokens[b - 1].text == "(" and tokens[b - 2].text == "next1D" and \
            tokens[b - 3].text == ".":
        return b - 4, b
    if b >= 0 and tokens[b].text in randoms and tokens[b - 1].text not in (".", "->"):
        return b, b
    return None


def written_names(tokens, pairs, first, last):
    """Names a statement may write: its first name (what an assignment assigns, or a declaration's type),
    every name before an assignment or a constructor's brackets, every object a method is called on, every
    operand of ++ and --."""
    names = {next((tokens[k].text for k in range(first, last + 1) if tokens[k].kind == "name"), "")}
    if last - 1 > first and tokens[last - 1].kind == "name":  # T name;
        names.add(tokens[last - 1].text)
    k = first
    while k <= last:
        text = tokens[k].text
        if text in ("=", "+=", "-=", "*=", "/=", "%=", "|=", "&=", "^=", "<<=", ">>=") and k > first:
            names.add(tokens[k - 1].text)
        if text in ("(", "{") and k > first and tokens[k - 1].kind == "name" and \
                k - 2 >= first and (tokens[k - 2].kind == "name" or tokens[k - 2].text in (",", ">")):
            names.add(tokens[k - 1].text)
        if text in (".", "->") and k + 2 <= last and tokens[k + 2].text == "(":
            names.add(tokens[k - 1].text)
            j = k - 1
            while j > first and tokens[j - 1].text in (".", "->"):
                j -= 2
            names.add(tokens[j].text)
        if text in ("++", "--"):
            names.update(tokens[j].text for j in (k - 1, k + 1) if first <= j <= last and tokens[j].kind == "name")
        if text in "([{" and k in pairs and k > first and tokens[k - 1].kind != "name":
            k = pairs[k]
        k += 1
    return {n for n in names if n and n not in NOT_WRITTEN and not n[0].isupper() and not n.endswith("_t")}


# Keywords and built-in types: never what a statement writes (a type's name
# starts with a capital letter, or ends in _t).
NOT_WRITTEN = {"const", "constexpr", "static", "auto", "float", "double", "int", "unsigned", "bool", "char", "long",
               "short", "size_t", "std", "glm", "void", "new", "delete", "return", "sizeof"}


def generate_conventions(task: int, folder: str, source: str):
    parsed = parse(source)
    variants = Variants(task, folder, parsed)
    for name, params, body_open, body_close in function_bodies(parsed.tokens, parsed.pairs, parsed.code):
        randoms = {p for t, p in params if RANDOM_NAME.fullmatch(p) and t.split()[-1] in ("float", "Vec2")}
        edits = [mirrors(parsed, name, params, randoms, body_open)]
        body = range(body_open + 1, body_close)
        for k in body:
            edits += [coins(parsed, name, k, body, randoms), draws(parsed, name, k), wraps(parsed, name, k)]
        edits.append(statement_swaps(parsed, name, body_open, body_close))
        for edit in (e for step in edits for e in step):
            variants.add(*edit)
    return variants.edited(lambda m: f"{folder}: {m.description}")


def mirrors(parsed: Parsed, name: str, params, randoms: set, body_open: int):
    """Each random parameter mirrored (u -> 1- - u) or, a Vec2, its numbers exchanged, on entry."""
    at = parsed.tokens[body_open].end  # a statement inserted at the top of the body
    for kind, u in ((t.split()[-1], p) for t, p in params if p in randoms):
        if kind == "float":
            yield "mirror-u", at, at, f" {u} = {ALMOST_ONE} - {u};", f"{name}: `{u}` -> `1 - {u}`"
        else:
            for c in ("x", "y"):
                yield "mirror-u", at, at, f" {u}.{c} = {ALMOST_ONE} - {u}.{c};", f"{name}: `{u}.{c}` -> `1 - {u}.{c}`"
            yield "swap-u", at, at, f" {u} = Vec2({u}.y, {u}.x);", f"{name}: `{u}.x` <-> `{u}.y`"


def coins(parsed: Parsed, name: str, k: int, body: range, randoms: set):
    """A coin: a comparison at token k with a random number on one side, decided by the number mirrored."""
    tokens = parsed.tokens
    if tokens[k].kind != "op" or tokens[k].text not in ("<", "<=", ">", ">=") or k in parsed.angles:
        return
    for forward in (False, True):
        side = random_operand(tokens, k, forward, randoms)
        if side is None:
            continue
        a, b = side
        number = parsed.spelled(a, b)
        uses = sum(1 for j in body if tokens[j].text == tokens[a].text)
        reused = tokens[a].text in randoms and uses > 1
        yield ("coin", tokens[a].start, tokens[b].end, f"({ALMOST_ONE} - {number})",
               f"{name}: the coin `{number}` mirrored", reused)


def draws(parsed: Parsed, name: str, k: int):
    """A draw, sampler.next1D() or next2D() at token k, mirrored or its two numbers exchanged where the code
    takes it."""
    tokens, text = parsed.tokens, parsed.tokens[k].text
    if text not in ("next1D", "next2D") or k < 2 or tokens[k - 1].text != "." or \
            k + 2 >= len(tokens) or tokens[k + 1].text != "(" or tokens[k + 2].text != ")":
        return
    start, end = tokens[k - 2].start, tokens[k + 2].end
    draw = parsed.source[start:end]
    if text == "next1D":
        if not any(tokens[j].text in ("<", "<=", ">", ">=") for j in (k - 3, k + 3) if 0 <= j < len(tokens)):
            yield "draw", start, end, f"({ALMOST_ONE} - {draw})", f"{name}: `{draw}` mirrored"
    else:
        yield ("draw", start, end, f"[](Vec2 v) {{ return Vec2(v.y, v.x); }}({draw})",
               f"{name}: the two numbers of `{draw}` exchanged")
        yield ("draw", start, end, f"[](Vec2 v) {{ return Vec2({ALMOST_ONE}) - v; }}({draw})",
               f"{name}: both numbers of `{draw}` mirrored")


def wraps(parsed: Parsed, name: str, k: int):
    """A clamp below 1 made a wrap: std::min(x, 1-) at token k -> x < 1 ? x : x - 1."""
    tokens, pairs = parsed.tokens, parsed.pairs
    if tokens[k].text != "min" or k < 2 or tokens[k - 1].text != "::" or tokens[k - 2].text != "std" or \
            k + 1 >= len(tokens) or tokens[k + 1].text != "(" or k + 1 not in pairs:
        return
    close = pairs[k + 1]
    commas = [j for j in range(k + 2, close) if tokens[j].text == "," and not any(
        o < j < pairs[o] for o in range(k + 2, j) if o in pairs)]
    if len(commas) == 1 and parsed.spelled(commas[0] + 1, close - 1) == ALMOST_ONE:
        x = parsed.spelled(k + 2, commas[0] - 1)
        yield ("wrap", tokens[k - 2].start, tokens[close].end, f"[](float v) {{ return v < 1.0f ? v : v - 1.0f; }}({x})",
               f"{name}: `{x[:40]}` wrapped at 1, not clamped below it", True)


def simple_statements(parsed: Parsed, body_open: int, body_close: int) -> list:
    """The body's statements in order: (first, last token) of a simple one (no control flow, no lambda or
    type), None for anything else (a brace, a label, an if and what it guards)."""
    tokens, pairs = parsed.tokens, parsed.pairs
    statements, k = [], body_open + 1
    while k < body_close:
        text = tokens[k].text
        if text in ("{", "}", "else", "do", "case", "default", ":"):
            statements.append(None)
            k += 1
            continue
        if text in ("if", "for", "while", "switch"):  # its condition, then a block or one statement
            statements.append(None)
            k += 1
            if k in pairs and tokens[k].text == "(":
                k = pairs[k] + 1
            if k < body_close and tokens[k].text != "{":
                end = statement_end(tokens, k, pairs)
                k = body_close if end is None else end + 1
            continue
        end = statement_end(tokens, k, pairs)
        if end is None or end >= body_close:
            break
        inner = {tokens[j].text for j in range(k, end)}
        simple = text not in ("return", "break", "continue", "goto", "struct", "class", "enum", "using",
                              "static_assert", "throw") and end > k and "[" + "&" not in inner
        lambda_or_type = "{" in inner and ("[" in inner or text in ("struct", "class"))
        statements.append((k, end) if simple and not lambda_or_type else None)
        k = end + 1
    return statements


def statement_swaps(parsed: Parsed, name: str, body_open: int, body_close: int):
    """Neighbouring simple statements in the same block exchanged, neither writing a name the other uses."""
    tokens, pairs, source = parsed.tokens, parsed.pairs, parsed.source
    statements = simple_statements(parsed, body_open, body_close)
    for first, second in zip(statements, statements[1:]):
        if first is None or second is None:
            continue
        names_a = {tokens[j].text for j in range(first[0], first[1] + 1) if tokens[j].kind == "name"}
        names_b = {tokens[j].text for j in range(second[0], second[1] + 1) if tokens[j].kind == "name"}
        writes_a, writes_b = written_names(tokens, pairs, *first), written_names(tokens, pairs, *second)
        if writes_a & names_b or writes_b & names_a:
            continue
        a, b = parsed.spelled(*first), parsed.spelled(*second)
        between = source[tokens[first[1]].end:tokens[second[0]].start]
        yield ("reorder", tokens[first[0]].start, tokens[second[1]].end, b + between + a,
               f"{name}: `{a[:40]}` and `{b[:40]}` exchanged")
