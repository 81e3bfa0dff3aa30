"""The `$(name arg …)` grammar of ROS 2 launch files.

    text      := (literal | "$(" call ")")*      `$` not followed by `(` is literal; `\\$` is `$`
    call      := NAME (SPACE+ argument)* SPACE*
    argument  := (literal-word | 'single quoted' | "double quoted" | "$(" call ")")+

Quotes may hold substitutions; `\\` escapes the next character inside a call. The result is a
tuple of parts, each a plain string or a `Call`; the builder maps calls to substitutions.
"""

from __future__ import annotations

import re
from typing import NamedTuple

from launcher.errors import ParseError

_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_\-]*")


class Call(NamedTuple):
    name: str
    args: tuple[tuple[str | Call, ...], ...]
    offset: int  # index of the `$` in the source text


Part = str | Call


class SubstitutionSyntaxError(ParseError):
    """A syntax error at `offset` inside the text; the builder turns it into file:line:col."""

    def __init__(self, message: str, offset: int) -> None:
        super().__init__(message)
        self.offset = offset


def parse_text(text: str) -> tuple[Part, ...]:
    """Split `text` into literal strings and substitution calls."""
    if "$" not in text:
        return (text,) if text else ()
    parser = _Parser(text)
    parts = parser.top()
    return tuple(parts)


class _Parser:
    def __init__(self, text: str) -> None:
        self.text = text
        self.pos = 0

    def top(self) -> list[Part]:
        out: list[Part] = []
        buf: list[str] = []
        text = self.text
        while self.pos < len(text):
            ch = text[self.pos]
            if ch == "\\" and text.startswith("$", self.pos + 1):
                buf.append("$")
                self.pos += 2
            else:
                self.take(buf, out)
        _flush(buf, out)
        return out

    def take(self, buf: list[str], out: list[Part]) -> None:
        """The character at pos: a `$(…)` call's start, or text."""
        if self.text.startswith("$(", self.pos):
            _flush(buf, out)
            out.append(self.call())
        else:
            buf.append(self.text[self.pos])
            self.pos += 1

    def call(self) -> Call:
        start = self.pos
        self.pos += 2  # "$("
        match = _NAME.match(self.text, self.pos)
        if not match:
            raise SubstitutionSyntaxError(
                "expected a substitution name after '$(' (like $(var name))", start
            )
        self.pos = match.end()
        if match.group() == "eval":
            raw = self.raw_expression()
            if raw is not None:  # roslaunch's `$(eval arg('x') * 2)`: the rest is the expression
                return Call("eval", ((raw,),), start)
        args: list[tuple[Part, ...]] = []
        while True:
            self.skip_spaces()
            if self.pos >= len(self.text):
                raise SubstitutionSyntaxError(
                    f"unclosed '$({match.group()}': expected ')'", start
                )
            if self.text[self.pos] == ")":
                self.pos += 1
                return Call(match.group(), tuple(args), start)
            args.append(self.argument())

    def raw_expression(self) -> str | None:
        """An unquoted `$(eval …)` holding no substitution, as roslaunch writes it: the text up to
        the matching ')' (parentheses and quotes inside counted). None for ROS 2's quoted form
        (or one with substitutions), which the usual grammar reads."""
        text, pos = self.text, self.pos
        while pos < len(text) and text[pos] in " \t\n":
            pos += 1
        if pos >= len(text) or text[pos] in "'\")":
            return None
        depth, quote, begin = 0, "", pos
        while pos < len(text):
            ch = text[pos]
            if quote:
                quote = "" if ch == quote else quote
            elif ch in "'\"":
                quote = ch
            elif ch == "(":
                depth += 1
            elif ch == ")":
                if depth == 0:
                    expression = text[begin:pos]
                    if "$(" in expression:
                        return None
                    self.pos = pos + 1
                    return expression.strip()
                depth -= 1
            pos += 1
        return None

    def skip_spaces(self) -> None:
        while self.pos < len(self.text) and self.text[self.pos] in " \t\n":
            self.pos += 1

    def argument(self) -> tuple[Part, ...]:
        out: list[Part] = []
        buf: list[str] = []
        text = self.text
        while self.pos < len(text):
            ch = text[self.pos]
            if ch in " \t\n)":
                break
            if ch == "\\" and self.pos + 1 < len(text):
                buf.append(text[self.pos + 1])
                self.pos += 2
            elif ch in "'\"":
                _flush(buf, out)
                out.extend(self.quoted(ch))
            else:
                self.take(buf, out)
        _flush(buf, out)
        return tuple(out)

    def quoted(self, quote: str) -> list[Part]:
        start = self.pos
        self.pos += 1
        out: list[Part] = []
        buf: list[str] = []
        text = self.text
        while self.pos < len(text):
            ch = text[self.pos]
            if ch == quote:
                self.pos += 1
                _flush(buf, out)
                return out or [""]
            if ch == "\\" and self.pos + 1 < len(text) and text[self.pos + 1] in (quote, "\\"):
                buf.append(text[self.pos + 1])
                self.pos += 2
            else:
                self.take(buf, out)
        raise SubstitutionSyntaxError(f"unclosed quote {quote}", start)


def _flush(buf: list[str], out: list[Part]) -> None:
    if buf:
        out.append("".join(buf))
        buf.clear()
