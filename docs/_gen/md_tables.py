"""Small Markdown helpers the generated pages share."""

from __future__ import annotations

from collections.abc import Iterable, Sequence


def cell(text: object) -> str:
    """Text safe inside a table cell: no pipes or line breaks, and `<` outside code spans
    (`share/<package>`) written as text, not taken for HTML."""
    parts = " ".join(str(text).split()).replace("|", "\\|").split("`")
    return "`".join(p.replace("<", "&lt;") if i % 2 == 0 else p for i, p in enumerate(parts))


def table(header: Sequence[str], rows: Iterable[Sequence[object]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + " --- |" * len(header)]
    lines += ["| " + " | ".join(cell(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def code(text: object) -> str:
    """Inline code, safe for text holding backticks."""
    text = str(text)
    fence = "``" if "`" in text else "`"
    return f"{fence}{text}{fence}" if text else ""


def anchor(text: str) -> str:
    """The id a heading gets (as Python-Markdown's toc makes it)."""
    keep = "".join(c if c.isalnum() or c in " -_" else "" for c in text.lower())
    return "-".join(keep.split())
