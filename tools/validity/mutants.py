"""The mutants of a task file, for tools/mutate: the first-order operators
(one token or constant changed, a statement removed) and the higher-order
ones (a whole call, operand or refinement replaced by a neighbour)."""
import hashlib
import re
from dataclasses import dataclass, field

from tools.validity.cpp_tokens import (CONTROL, VALUE_TOKENS, code_tokens, declared_functions, function_bodies, lex,
                                match_brackets, ordinal, plain_type, statement_end, template_brackets,
                                argument_spans)


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


def generate(task: int, folder: str, source: str, header: str = ""):
    tokens = lex(source)
    pairs = match_brackets(tokens)
    angles = template_brackets(tokens)
    code = code_tokens(tokens, pairs)
    line_of = lambda offset: source.count("\n", 0, offset) + 1
    lines = source.splitlines()
    mutants = []

    def add(operator, start, end, replacement, description):
        line = line_of(start)
        mutants.append(Mutant(task, folder, operator, start, end, replacement, line, lines[line - 1].strip(), description))

    def value_before(i):
        return i > 0 and (tokens[i - 1].kind in VALUE_TOKENS or tokens[i - 1].text in (")", "]")) and \
            tokens[i - 1].text not in CONTROL and tokens[i - 1].text not in ("return", "case")

    for i, t in enumerate(tokens):
        text = t.text
        # Relational, logical and arithmetic operators.
        swaps = {"<": "<=", "<=": "<", ">": ">=", ">=": ">", "==": "!=", "!=": "==",
                 "&&": "||", "||": "&&", "+=": "-=", "-=": "+=", "*=": "/=", "/=": "*=", "++": "--", "--": "++"}
        if t.kind == "op" and text in swaps and i not in angles:
            kind = "relational" if text in ("<", "<=", ">", ">=", "==", "!=") else \
                "logical" if text in ("&&", "||") else "arithmetic"
            add(kind, t.start, t.end, swaps[text], f"`{text}` -> `{swaps[text]}`")
        elif t.kind == "op" and text in "+-*/" and len(text) == 1:
            if value_before(i):
                opposite = {"+": "-", "-": "+", "*": "/", "/": "*"}[text]
                add("arithmetic", t.start, t.end, opposite, f"`{text}` -> `{opposite}`")
            elif text == "-":
                add("sign", t.start, t.end, "", "unary `-` removed")
        # min <-> max, abs removed.
        if t.kind == "name" and text in MINMAX and i + 1 < len(tokens) and tokens[i + 1].text in ("(", "<"):
            add("minmax", t.start, t.end, MINMAX[text], f"`{text}` -> `{MINMAX[text]}`")
        if t.kind == "name" and text in ("abs", "fabs", "fabsf") and i + 1 < len(tokens) and tokens[i + 1].text == "(":
            first = i - 2 if i >= 2 and tokens[i - 1].text == "::" else i
            add("abs", tokens[first].start, t.end, "", f"`{source[tokens[first].start:t.end]}` removed")
        # Constants.
        # (Not the operand of == or !=: an equality nudged to another exact
        # value tests a different point of measure zero, never a mistake.)
        equality = (i > 0 and tokens[i - 1].text in ("==", "!=")) or \
            (i + 1 < len(tokens) and tokens[i + 1].text in ("==", "!="))
        if t.kind == "number" and not equality:
            for replacement in constant_mutations(text):
                add("constant", t.start, t.end, replacement, f"`{text}` -> `{replacement}`")
        # float <-> double.
        if t.kind == "name" and text in FLOAT_TYPES:
            add("precision", t.start, t.end, FLOAT_TYPES[text], f"`{text}` -> `{FLOAT_TYPES[text]}`")

        if i not in code:
            continue
        # if / while conditions negated.
        if text in ("if", "while") and i + 1 < len(tokens) and tokens[i + 1].text == "(" and i + 1 in pairs:
            open_, close = i + 1, pairs[i + 1]
            if close > open_ + 1 and not (text == "while" and tokens[open_ + 1].text == "true"):
                inner = source[tokens[open_ + 1].start:tokens[close - 1].end]
                add("negate", tokens[open_ + 1].start, tokens[close - 1].end, f"!({inner})", f"`{text}` condition negated")
        # ?: conditions negated.
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
                inner = source[tokens[start].start:tokens[i - 1].end]
                add("negate", tokens[start].start, tokens[i - 1].end, f"!({inner})", "`?:` condition negated")
        # Statements deleted.
        previous = tokens[i - 1].text if i else ""
        opened_by = tokens[pairs[i - 1] - 1].text if previous == ")" and i - 1 in pairs and pairs[i - 1] > 0 else ""
        starts = previous in (";", "{", "}", "else") or (previous == ")" and opened_by in ("if", "for", "while"))
        if starts and i + 1 < len(tokens):
            nxt = tokens[i + 1].text
            deletable = (t.kind == "name" and text not in CONTROL and text not in ("const", "constexpr", "static", "auto",
                                                                                    "else", "do", "case", "default", "break",
                                                                                    "continue") and
                         nxt in (".", "=", "(", "+=", "-=", "*=", "/=", "++", "--", "[", "->", ",")) or \
                        text in ("++", "--", "break", "continue") or \
                        (text == "return" and (previous == ")" or previous == "else"))
            if text == "std" and nxt == "::":  # std::swap(a, b); and the like
                deletable = True
            if deletable:
                end = statement_end(tokens, i, pairs)
                if end is not None:
                    add("delete", t.start, tokens[end].end, ";" if previous in (")", "else") else "",
                        f"`{source[t.start:tokens[end].end][:60]}` deleted")
        # Neighbouring arguments swapped.
        if text in ("(", "{") and i in pairs and i > 0 and \
                (tokens[i - 1].kind == "name" and tokens[i - 1].text not in CONTROL or tokens[i - 1].text == ">"):
            args = argument_spans(tokens, pairs, i)
            for k in range(len(args) - 1):
                (a0, a1), (b0, b1) = args[k], args[k + 1]
                first = source[tokens[a0].start:tokens[a1].end]
                second = source[tokens[b0].start:tokens[b1].end]
                if first != second:
                    add("swap-args", tokens[a0].start, tokens[b1].end,
                        second + source[tokens[a1].end:tokens[b0].start] + first,
                        f"arguments {k + 1} and {k + 2} of `{tokens[i - 1].text}` swapped")

    visible = {**declared_functions(header), **declared_functions(source)}
    for operator, start, end, replacement, description in higher_order(tokens, pairs, code, source, visible):
        add(operator, start, end, replacement, description)

    # Stable, readable keys: the task and the edited line as the mutant has
    # it (and which copy of the line, if the reference has it twice).
    seen = {}
    for m in mutants:
        m.source = source[:m.start] + m.replacement + source[m.end:]
        same_line = [n for n, text in enumerate(lines, 1) if text.strip() == m.site]
        line_occurrence = same_line.index(m.line) + 1 if m.line in same_line else 1
        now = m.source.splitlines()[m.line - 1].strip()
        base = f"{folder}: {now}" if now else f"{folder}: deleted: {m.site}"
        if line_occurrence > 1:
            base += f"  [line copy {line_occurrence}]"
        seen[base] = seen.get(base, 0) + 1
        m.key = base if seen[base] == 1 else f"{base}  [{ordinal(seen[base])}]"
    return [m for m in mutants if m.source != source]


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
