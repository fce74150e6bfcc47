"""C++ source as the tools read it, one lexer for all: tools/mutate (its
mutation sites: comments, strings and preprocessor lines are never
mutated; brackets matched, statements and function bodies found),
tools/hint-catalogue (a suite's test cases, checks and hints) and the
grader's check that suites call the candidate (the source with comments
and literals blanked)."""
import re
from dataclasses import dataclass


# ---------------------------------------------------------------------------
# A C++ lexer good enough for these tools, not a compiler's: raw strings,
# comments and preprocessor lines (indented ones too: a space token ends at
# each line's end) are whole tokens; anything it does not know is an "other"
# token of one character.

TOKEN = re.compile(r"""
    (?P<preprocessor>^[ \t]*\#[^\n]*(?:\\\n[^\n]*)*)
  | (?P<space>[ \t\r\f\v]*\n|[ \t\r\f\v]+)
  | (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<string>R"(?P<delimiter>[^()\\\s"]{0,16})\(.*?\)(?P=delimiter)"|"(?:\\.|[^"\\\n])*"|'(?:\\.|[^'\\\n])*')
  | (?P<number>0[xX][0-9a-fA-F.]+(?:[pP][+-]?\d+)?[fFlLuU]*|(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?[fFlLuU]*)
  | (?P<name>[A-Za-z_]\w*)
  | (?P<op><<=|>>=|->\*|\.\.\.|::|->|\+\+|--|<<|>>|<=|>=|==|!=|&&|\|\||\+=|-=|\*=|/=|%=|&=|\|=|\^=|[-+*/%<>=!&|^~?:;,.(){}\[\]])
  | (?P<other>.)
""", re.S | re.M | re.X)


@dataclass
class Token:
    kind: str   # name, number, string (a string or character literal as written), op, other
    text: str
    start: int  # where it is in the source, and just past it
    end: int
    line: int = 0


def scan(source: str):
    """Every match of TOKEN in order, spaces, comments and preprocessor lines included, with its line."""
    position, line = 0, 1
    while position < len(source):
        match = TOKEN.match(source, position)
        yield match, line
        line += match.group().count("\n")
        position = match.end()


def lex(source: str):
    """The tokens of the code: no spaces, comments or preprocessor lines."""
    return [Token(match.lastgroup, match.group(), match.start(), match.end(), line) for match, line in scan(source)
            if match.lastgroup not in ("space", "comment", "preprocessor")]


def blank_comments_and_literals(source: str) -> str:
    """The source with its comments and string and character literals turned into spaces (lines kept)."""
    return "".join(re.sub(r"[^\n]", " ", m.group()) if m.lastgroup in ("comment", "string") else m.group()
                   for m, _ in scan(source))


def string_value(text: str) -> str:
    """A string literal's characters: a raw string's as written; an escaped quote or backslash unescaped,
    other escapes kept as written."""
    if text.startswith("R"):
        return text[text.index("(") + 1:text.rindex(")")]
    return text[1:-1].replace('\\"', '"').replace("\\\\", "\\")


VALUE_TOKENS = ("name", "number", "string")


@dataclass
class Parsed:
    """A source as the generators read it: its tokens, their bracket pairs and
    template angles, which tokens are code (not in a declaration's head), its lines."""
    source: str
    tokens: list
    pairs: dict
    angles: set
    code: set
    lines: list

    def line_of(self, offset: int) -> int:
        return self.source.count("\n", 0, offset) + 1

    def spelled(self, first: int, last: int) -> str:
        """Tokens first..last as written."""
        return self.source[self.tokens[first].start:self.tokens[last].end]


def parse(source: str) -> Parsed:
    tokens = lex(source)
    pairs = match_brackets(tokens)
    return Parsed(source, tokens, pairs, template_brackets(tokens), code_tokens(tokens, pairs), source.splitlines())


CONTROL = {"if", "while", "for", "switch", "return", "sizeof", "alignof", "decltype", "static_assert", "catch"}


def match_brackets(tokens):
    """{index of an opening bracket: index of its closing one} and back."""
    pairs, stack = {}, []
    for i, t in enumerate(tokens):
        if t.text in "([{":
            stack.append(i)
        elif t.text in ")]}" and stack:
            j = stack.pop()
            pairs[j], pairs[i] = i, j
    return pairs


def template_brackets(tokens):
    """Indices of < and > that bracket template arguments (never mutated)."""
    angle = set()
    for i, t in enumerate(tokens):
        if t.text != "<" or i == 0 or tokens[i - 1].kind != "name":
            continue
        depth, j = 1, i + 1
        while j < len(tokens) and depth > 0:
            text = tokens[j].text
            if text == "<":
                depth += 1
            elif text == ">":
                depth -= 1
            elif text == ">>":
                depth -= 2
            elif tokens[j].kind not in ("name", "number") and text not in ("::", ",", "*", "&", "const"):
                break
            j += 1
        if depth <= 0:
            angle.update({i, j - 1})
    return angle


def code_tokens(tokens, pairs):
    """Indices of tokens inside a function body (where statements live)."""
    inside, stack = set(), []
    for i, t in enumerate(tokens):
        if t.text == "{":
            before = tokens[i - 1].text if i else ""
            stack.append(bool(stack and stack[-1]) or before in (")", "const", "noexcept", "mutable", "override", "else"))
        elif t.text == "}" and stack:
            stack.pop()
        if stack and stack[-1]:
            inside.add(i)
    return inside


def ordinal(k: int) -> str:
    return {1: "1st", 2: "2nd", 3: "3rd"}.get(k, f"{k}th")


def argument_spans(tokens, pairs, open_):
    """The arguments between bracket `open_` and its match, each (first, last) token index;
    commas inside nested brackets do not split."""
    args, begin, j, close = [], open_ + 1, open_ + 1, pairs[open_]
    while j < close:
        if tokens[j].text in "([{" and j in pairs:
            j = pairs[j] + 1
            continue
        if tokens[j].text == ",":
            args.append((begin, j - 1))
            begin = j + 1
        j += 1
    if begin < close:
        args.append((begin, close - 1))
    return args


def statement_end(tokens, i, pairs):
    """Index of the ; ending the statement that starts at token i (paren depth 0)."""
    j = i
    while j < len(tokens):
        text = tokens[j].text
        if text in "([{" and j in pairs:
            j = pairs[j] + 1
            continue
        if text == ";":
            return j
        if text == "}":
            return None
        j += 1
    return None


TYPE_WORDS = {"const", "constexpr", "static", "inline", "&", "&&", "*", "[[nodiscard]]"}


def plain_type(parts):
    """A declared type without const, references or pointers: 'const Vec3&' -> 'Vec3'."""
    return " ".join(p for p in parts if p not in TYPE_WORDS)


def parameter_spans(tokens, pairs, open_: int, close: int):
    """(first token, one past the last) of each comma-separated part between the brackets open_ and close."""
    begin, k = open_ + 1, open_ + 1
    while k <= close:
        if k < close and tokens[k].text in "([{<" and k in pairs:
            k = pairs[k] + 1
            continue
        if k == close or tokens[k].text == ",":
            yield begin, k
            begin = k + 1
        k += 1


def declared_functions(source):
    """{name: (return type, (parameter types))} of the functions declared or defined at namespace level."""
    tokens = lex(source)
    pairs = match_brackets(tokens)
    code = code_tokens(tokens, pairs)
    found = {}
    for i, t in enumerate(tokens):
        if t.text != "(" or i not in pairs or i < 2 or tokens[i - 1].kind != "name" or i in code:
            continue
        close = pairs[i]
        after = close + 1
        while after < len(tokens) and tokens[after].text in ("const", "noexcept", "override"):
            after += 1
        if after >= len(tokens) or tokens[after].text not in (";", "{"):
            continue
        j = i - 2  # the return type: back to the previous declaration's end
        while j >= 0 and tokens[j].text not in (";", "}", "{", ")", ":", "public", "private") and tokens[j].kind != "string":
            j -= 1
        returns = plain_type(x.text for x in tokens[j + 1:i - 1])
        if not returns or returns in ("return", "else", "new") or "=" in returns:
            continue
        params = []
        for begin, k in parameter_spans(tokens, pairs, i, close):
            part = [x.text for x in tokens[begin:k]]
            if "=" in part:
                part = part[:part.index("=")]
            if len(part) >= 2 and tokens[k - 1].kind == "name":
                part = part[:-1]  # the parameter's name
            if part:
                params.append(plain_type(part))
        found.setdefault(tokens[i - 1].text, (returns, tuple(params)))
    return found


def function_bodies(tokens, pairs, code):
    """(name, [(type, parameter)], body's {, body's }) of each function defined at namespace level."""
    for i, t in enumerate(tokens):
        if t.text != "(" or i not in pairs or i == 0 or tokens[i - 1].kind != "name" or i in code:
            continue
        close = pairs[i]
        j = close + 1
        while j < len(tokens) and tokens[j].text in ("const", "noexcept", "override"):
            j += 1
        if j >= len(tokens) or tokens[j].text != "{" or j not in pairs:
            continue
        params = []
        for begin, k in parameter_spans(tokens, pairs, i, close):
            part = tokens[begin:k]
            if len(part) >= 2 and part[-1].kind == "name":
                params.append((" ".join(x.text for x in part[:-1]), part[-1].text))
        yield tokens[i - 1].text, params, j, pairs[j]
