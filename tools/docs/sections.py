"""Sections of docs/ that tools write: the lines between <!-- NAME:begin -->
and <!-- NAME:end --> (tools/image-test-seeds, tools/adversary)."""
from pathlib import Path


def replace_section(doc: Path, name: str, body: str):
    """Puts `body` between the markers NAME in `doc`, which must have them."""
    text = doc.read_text()
    begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
    if begin not in text:
        raise SystemExit(f"{doc}: no {begin} marker")
    head, rest = text.split(begin, 1)
    doc.write_text(head + begin + "\n" + body + "\n" + end + rest.split(end, 1)[1])
