"""The mutants of a task file, for tools/mutate: the first-order operators
(one token or constant changed, a statement removed) and the higher-order
ones (a whole call, operand or refinement replaced by a neighbour)."""
import hashlib
import re
from dataclasses import dataclass, field

from tools.cpp_tokens import (CONTROL, VALUE_TOKENS, Parsed, argument_spans, declared_functions,
                                       function_bodies, ordinal, parse, plain_type, statement_end)


@dataclass
class Mutant:
    task: int
    folder: str
    operator: str
    start: int          # the edit: source[start:end] becomes replacement
    end: int
    replacement: str
    line: int
    site: str           # the stripped text of the edited line
    description: str    # e.g. "`<` -> `<=`"
    key: str = ""
    source: str = field(default="", repr=False)
    needs_review: bool = False  # a convention alternate that is not correct by construction

    @property
    def id(self) -> str:
        return f"T{self.task}-{hashlib.sha1(self.key.encode()).hexdigest()[:8]}"


FLOAT_TYPES = {"float": "double", "double": "float"}


MINMAX = {"min": "max", "max": "min", "fmin": "fmax", "fmax": "fmin", "fminf": "fmaxf", "fmaxf": "fminf"}


def float_literal(value: float, like: str) -> str:
    suffix = "f" if like.lower().endswith("f") else ""
    text = repr(float(value))
    if "e" not in text and "." not in text:
        text += ".0"
    return text + suffix


def constant_mutations(text: str):
    """Replacements for one numeric literal."""
    body = text.rstrip("fFlLuU")
    if re.fullmatch(r"\d+", body) or re.fullmatch(r"0[xX][0-9a-fA-F]+", body):
        value = int(body, 0)
        suffix = text[len(body):]
        out = [str(value + 1) + suffix]
        if value > 0:
            out.append(str(value - 1) + suffix)
        return out
    try:
        value = float.fromhex(body) if body.lower().startswith("0x") else float(body)
    except ValueError:
        return []
    out = []
    if value == 0.0:
        out.append(float_literal(1e-6, text))
    elif abs(value) < 1e-2:
        out.append(float_literal(0.0, text))
    if value == 1.0:
        out += [float_literal(1.01, text), float_literal(0.99, text)]
    elif abs(value - 1.0) < 1e-3:  # just below or above 1 (0x1.fffffep-1f): exactly 1
        out.append(float_literal(1.0, text))
    if value != 0.0:
        out += [float_literal(value * 2.0, text), float_literal(value / 2.0, text)]
    return list(dict.fromkeys(o for o in out if o != text))


class Variants:
    """The edits of one source, in the order found, as Mutants of task `task`."""

    def __init__(self, task: int, folder: str, parsed: Parsed):
        self.task, self.folder, self.parsed, self.found = task, folder, parsed, []

    def add(self, operator, start, end, replacement, description, needs_review=False):
        line = self.parsed.line_of(start)
        self.found.append(Mutant(self.task, self.folder, operator, start, end, replacement, line,
                                 self.parsed.lines[line - 1].strip(), description, needs_review=needs_review))

    def edited(self, key_of) -> list:
        """Each edit applied to the source and keyed by key_of(mutant) (a repeated key gets "[2nd]", ...);
        edits that change nothing dropped."""
        source, seen = self.parsed.source, {}
        for m in self.found:
            m.source = source[:m.start] + m.replacement + source[m.end:]
            base = key_of(m)
            seen[base] = seen.get(base, 0) + 1
            m.key = base if seen[base] == 1 else f"{base}  [{ordinal(seen[base])}]"
        return [m for m in self.found if m.source != source]


def generate(task: int, folder: str, source: str, header: str = ""):
    parsed = parse(source)
    variants = Variants(task, folder, parsed)
    for i in range(len(parsed.tokens)):
        for edit in operator_edits(parsed, i):
            variants.add(*edit)
        if i in parsed.code:
            for step in (negations, deletion, argument_swaps):
                for edit in step(parsed, i):
                    variants.add(*edit)
    visible = {**declared_functions(header), **declared_functions(source)}
    for edit in higher_order(parsed.tokens, parsed.pairs, parsed.code, source, visible):
        variants.add(*edit)
    return variants.edited(lambda m: line_key(m, folder, parsed.lines))


def line_key(m: Mutant, folder: str, lines: list) -> str:
    """A stable, readable key: the task and the edited line as the mutant has
    it (and which copy of the line, if the reference has it twice)."""
    same_line = [n for n, text in enumerate(lines, 1) if text.strip() == m.site]
    line_occurrence = same_line.index(m.line) + 1 if m.line in same_line else 1
    now = m.source.splitlines()[m.line - 1].strip()
    base = f"{folder}: {now}" if now else f"{folder}: deleted: {m.site}"
    return base + (f"  [line copy {line_occurrence}]" if line_occurrence > 1 else "")


SWAPS = {"<": "<=", "<=": "<", ">": ">=", ">=": ">", "==": "!=", "!=": "==",
         "&&": "||", "||": "&&", "+=": "-=", "-=": "+=", "*=": "/=", "/=": "*=", "++": "--", "--": "++"}


def operator_edits(parsed: Parsed, i: int):
    """Token i's own edits, (operator, start, end, replacement, description): operators swapped, unary minus
    removed, min <-> max, abs removed, constants nudged, float <-> double."""
    tokens, source = parsed.tokens, parsed.source
    t, text = tokens[i], tokens[i].text
    if t.kind == "op" and text in SWAPS and i not in parsed.angles:
        kind = "relational" if text in ("<", "<=", ">", ">=", "==", "!=") else \
            "logical" if text in ("&&", "||") else "arithmetic"
        yield kind, t.start, t.end, SWAPS[text], f"`{text}` -> `{SWAPS[text]}`"
    elif t.kind == "op" and text in "+-*/" and len(text) == 1:
        if value_before(tokens, i):
            opposite = {"+": "-", "-": "+", "*": "/", "/": "*"}[text]
            yield "arithmetic", t.start, t.end, opposite, f"`{text}` -> `{opposite}`"
        elif text == "-":
            yield "sign", t.start, t.end, "", "unary `-` removed"
    if t.kind == "name" and text in MINMAX and i + 1 < len(tokens) and tokens[i + 1].text in ("(", "<"):
        yield "minmax", t.start, t.end, MINMAX[text], f"`{text}` -> `{MINMAX[text]}`"
    if t.kind == "name" and text in ("abs", "fabs", "fabsf") and i + 1 < len(tokens) and tokens[i + 1].text == "(":
        first = i - 2 if i >= 2 and tokens[i - 1].text == "::" else i
        yield "abs", tokens[first].start, t.end, "", f"`{source[tokens[first].start:t.end]}` removed"
    # (Not the operand of == or !=: an equality nudged to another exact
    # value tests a different point of measure zero, never a mistake.)
    equality = (i > 0 and tokens[i - 1].text in ("==", "!=")) or \
        (i + 1 < len(tokens) and tokens[i + 1].text in ("==", "!="))
    if t.kind == "number" and not equality:
        for replacement in constant_mutations(text):
            yield "constant", t.start, t.end, replacement, f"`{text}` -> `{replacement}`"
    if t.kind == "name" and text in FLOAT_TYPES:
        yield "precision", t.start, t.end, FLOAT_TYPES[text], f"`{text}` -> `{FLOAT_TYPES[text]}`"


def value_before(tokens, i: int) -> bool:
    """A value ends just before token i (so a + or - there is binary)."""
    return i > 0 and (tokens[i - 1].kind in VALUE_TOKENS or tokens[i - 1].text in (")", "]")) and \
        tokens[i - 1].text not in CONTROL and tokens[i - 1].text not in ("return", "case")


def negations(parsed: Parsed, i: int):
    """The condition of an if, a while or a ?: at token i negated."""
    tokens, pairs, text = parsed.tokens, parsed.pairs, parsed.tokens[i].text
    if text in ("if", "while") and i + 1 < len(tokens) and tokens[i + 1].text == "(" and i + 1 in pairs:
        open_, close = i + 1, pairs[i + 1]
        if close > open_ + 1 and not (text == "while" and tokens[open_ + 1].text == "true"):
            yield ("negate", tokens[open_ + 1].start, tokens[close - 1].end,
                   f"!({parsed.spelled(open_ + 1, close - 1)})", f"`{text}` condition negated")
    if text == "?":
        j = i - 1
        while j >= 0:
            u = tokens[j].text
            if u in ")]":
                j = pairs.get(j, j) - 1
                continue
            if u in ("(", "[", "{", "=", ",", ";", "return", "?", ":", "&&", "||") or u.endswith("="):
                if u in ("==", "!=", "<=", ">="):
                    j -= 1
                    continue
                break
            j -= 1
        start = j + 1
        if start < i:
            yield ("negate", tokens[start].start, tokens[i - 1].end, f"!({parsed.spelled(start, i - 1)})",
                   "`?:` condition negated")


KEEP_STATEMENT = {"const", "constexpr", "static", "auto", "else", "do", "case", "default", "break", "continue"}


def deletion(parsed: Parsed, i: int):
    """The statement that starts at token i deleted (an assignment, a call, an increment, a break, a
    return after a condition)."""
    tokens, pairs, t, text = parsed.tokens, parsed.pairs, parsed.tokens[i], parsed.tokens[i].text
    previous = tokens[i - 1].text if i else ""
    opened_by = tokens[pairs[i - 1] - 1].text if previous == ")" and i - 1 in pairs and pairs[i - 1] > 0 else ""
    starts = previous in (";", "{", "}", "else") or (previous == ")" and opened_by in ("if", "for", "while"))
    if not starts or i + 1 >= len(tokens):
        return
    nxt = tokens[i + 1].text
    deletable = (t.kind == "name" and text not in CONTROL and text not in KEEP_STATEMENT and
                 nxt in (".", "=", "(", "+=", "-=", "*=", "/=", "++", "--", "[", "->", ",")) or \
        text in ("++", "--", "break", "continue") or \
        (text == "return" and (previous == ")" or previous == "else"))
    if text == "std" and nxt == "::":  # std::swap(a, b); and the like
        deletable = True
    end = statement_end(tokens, i, pairs) if deletable else None
    if end is not None:
        yield ("delete", t.start, tokens[end].end, ";" if previous in (")", "else") else "",
               f"`{parsed.source[t.start:tokens[end].end][:60]}` deleted")


def argument_swaps(parsed: Parsed, i: int):
    """Neighbouring arguments of the call (or braced initialiser) opened at token i exchanged."""
    tokens, pairs, source = parsed.tokens, parsed.pairs, parsed.source
    if tokens[i].text not in ("(", "{") or i not in pairs or i == 0 or not \
            (tokens[i - 1].kind == "name" and tokens[i - 1].text not in CONTROL or tokens[i - 1].text == ">"):
        return
    args = argument_spans(tokens, pairs, i)
    for k in range(len(args) - 1):
        (a0, a1), (b0, b1) = args[k], args[k + 1]
        first, second = parsed.spelled(a0, a1), parsed.spelled(b0, b1)
        if first != second:
            yield ("swap-args", tokens[a0].start, tokens[b1].end,
                   second + source[tokens[a1].end:tokens[b0].start] + first,
                   f"arguments {k + 1} and {k + 2} of `{tokens[i - 1].text}` swapped")


# ---------------------------------------------------------------------------
# Higher-order operators: a whole call, operand or refinement replaced by a
# neighbour of the same type, as a student's slip of the formula would be.
#   call      a call to a function replaced by another of the same signature
#             that the file can see: a maths neighbour (sin <-> cos, floor <->
#             ceil, asin <-> acos, exp <-> log, dot -> distance) or another
#             function the task's file or header declares with the same
#             parameter and return types
#   operand   a variable read replaced by another variable of the same type
#             in scope (declared before it in an enclosing block, or a
#             parameter of the function)
#   component a vector's .x, .y or .z read replaced by the next one
#   refine    a refinement dropped: normalize(x) -> x, clamp(x, a, b) -> x,
#             max(C, x) / min(C, x) with a constant C -> x

MATH_NEIGHBOURS = {
    "sin": ("cos",), "cos": ("sin",), "tan": ("sin",), "asin": ("acos",), "acos": ("asin",),
    "floor": ("ceil",), "ceil": ("floor",), "round": ("floor",), "exp": ("log",), "log": ("exp",),
    "sqrt": ("cbrt",), "dot": ("distance",), "distance": ("dot",),
}


REFINEMENTS = ("normalize", "clamp", "min", "max", "fmin", "fmax")


def declarations(tokens, pairs, body_open, body_close, params):
    """[(index of the name, name, type, closing brace of the block it lives in)] of a function body's
    parameters and local variables (T name = ..., T name(...), T name{...}, T name;)."""
    out = [(body_open, name, plain_type(type_.split()), body_close) for type_, name in params]
    blocks = [body_close]
    k = body_open + 1
    while k < body_close:
        text = tokens[k].text
        if text == "{" and k in pairs:
            blocks.append(pairs[k])
        elif text == "}":
            blocks.pop()
        elif tokens[k].kind == "name" and k + 1 < body_close and tokens[k + 1].text in ("=", ";", "{", "(", ",", ":") \
                and tokens[k - 1].kind == "name" and tokens[k - 1].text not in ("return", "else", "case", "goto") \
                or tokens[k].kind == "name" and tokens[k - 1].text in ("&", "*") and tokens[k + 1].text in ("=", ":"):
            j = k - 1
            while j > body_open and (tokens[j].kind == "name" or tokens[j].text in ("&", "*", "::")):
                j -= 1
            if tokens[j].text in (";", "{", "}", "(", ")"):
                type_ = plain_type(x.text for x in tokens[j + 1:k])
                if type_ and type_ not in CONTROL and type_ not in ("return", "else", "auto"):
                    # A for loop's variable lives in the loop's statement.
                    end = blocks[-1]
                    if tokens[j].text == "(" and j in pairs and j > 0 and tokens[j - 1].text == "for":
                        after = pairs[j] + 1
                        end = pairs[after] if tokens[after].text == "{" and after in pairs else statement_end(tokens, after, pairs)
                    out.append((k, tokens[k].text, type_, end))
        k += 1
    return out


def higher_order(tokens, pairs, code, source, visible):
    """(operator, start, end, replacement, description) of each higher-order mutant."""
    edits = []
    by_signature = {}
    for name, signature in visible.items():
        by_signature.setdefault(signature, []).append(name)

    for i, t in enumerate(tokens):
        if i not in code or t.kind != "name" or i + 1 >= len(tokens) or tokens[i + 1].text != "(" or i + 1 not in pairs:
            continue
        qualified = i >= 2 and tokens[i - 1].text == "::" and tokens[i - 2].text in ("std", "glm")
        member = tokens[i - 1].text in (".", "->")
        # A call replaced by a neighbour of the same signature.
        if qualified and t.text in MATH_NEIGHBOURS:
            for other in MATH_NEIGHBOURS[t.text]:
                if other == "distance" and tokens[i - 2].text != "glm" or other == "cbrt" and tokens[i - 2].text != "std":
                    continue
                if other == "dot" and tokens[i - 2].text != "glm":
                    continue
                edits.append(("call", t.start, t.end, other, f"`{t.text}` -> `{other}`"))
        elif not qualified and not member and t.text in visible:
            for other in by_signature.get(visible[t.text], []):
                if other != t.text:
                    edits.append(("call", t.start, t.end, other, f"`{t.text}` -> `{other}`"))
        # A refinement dropped.
        if qualified and t.text in REFINEMENTS:
            args = argument_spans(tokens, pairs, i + 1)
            keep = None
            if t.text == "normalize" and len(args) == 1 or t.text == "clamp" and len(args) == 3:
                keep = args[0]
            elif t.text != "clamp" and t.text != "normalize" and len(args) == 2:
                constant = [a for a in args if a[0] == a[1] and tokens[a[0]].kind == "number" or
                            a[1] == a[0] + 1 and tokens[a[0]].text == "-" and tokens[a[1]].kind == "number"]
                if len(constant) == 1:
                    keep = args[1] if constant[0] == args[0] else args[0]
            if keep:
                kept = source[tokens[keep[0]].start:tokens[keep[1]].end]
                edits.append(("refine", tokens[i - 2].start, tokens[pairs[i + 1]].end, f"({kept})",
                              f"`{source[tokens[i - 2].start:tokens[i].end]}` dropped"))

    # Components: .x -> .y -> .z -> .x, where read (not assigned).
    for i, t in enumerate(tokens):
        if i in code and t.text in ("x", "y", "z") and tokens[i - 1].text == "." and i + 1 < len(tokens) and \
                tokens[i + 1].text not in ("=", "+=", "-=", "*=", "/=", "(") and tokens[i - 2].text != "{":
            other = {"x": "y", "y": "z", "z": "x"}[t.text]
            edits.append(("component", t.start, t.end, other, f"`.{t.text}` -> `.{other}`"))

    # Operands: a variable read replaced by another of its type in scope.
    for name, params, body_open, body_close in function_bodies(tokens, pairs, code):
        declared = declarations(tokens, pairs, body_open, body_close, params)
        names = {d[1] for d in declared}
        for k in range(body_open + 1, body_close):
            t = tokens[k]
            if t.kind != "name" or t.text not in names or tokens[k - 1].text in (".", "->", "::") or \
                    tokens[k + 1].text in ("=", "+=", "-=", "*=", "/=", "++", "--", "(") or \
                    tokens[k - 1].text in ("++", "--", "&") and tokens[k - 2].text in ("(", ",", "="):
                continue
            here = [d for d in declared if d[0] < k <= d[3] and d[1] == t.text]
            if not here or here[-1][0] == k:
                continue
            type_ = here[-1][2]
            others = []
            for d in declared:
                ready = d[0] == body_open or (statement_end(tokens, d[0], pairs) or body_close) < k
                if ready and d[0] < k <= d[3] and d[2] == type_ and d[1] != t.text and d[1] not in others:
                    others.append(d[1])
            for other in others:
                edits.append(("operand", t.start, t.end, other, f"`{t.text}` -> `{other}`"))
    return edits
