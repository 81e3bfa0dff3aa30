"""SDF's XML as a small tree that remembers where each element is (file:line:column).

ElementTree keeps no line numbers, and every SDF message names its place, so the tree is
built from expat's events. Comments and processing instructions are dropped; text (CDATA
included) is kept stripped.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from xml.parsers import expat

from launcher.errors import LaunchError, Location

# Gazebo's parser accepts `--` inside comments (gz-sim's own worlds have it); XML does not.
_COMMENT = re.compile(r"(<!\[CDATA\[.*?\]\]>)|<!--(.*?)-->", re.S)


def _blank_comment(match: re.Match[str]) -> str:
    return match.group(1) or "\n" * match.group(2).count("\n")


class SdfError(LaunchError):
    """An SDF world or model that cannot be loaded."""


@dataclass(eq=False)
class Element:
    tag: str
    attrib: dict[str, str]
    location: Location
    children: list[Element] = field(default_factory=list)
    text: str = ""

    def get(self, name: str, default: str | None = None) -> str | None:
        return self.attrib.get(name, default)

    def find(self, tag: str) -> Element | None:
        return next((c for c in self.children if c.tag == tag), None)

    def findall(self, tag: str) -> list[Element]:
        return [c for c in self.children if c.tag == tag]

    def value(self, tag: str, default: str | None = None) -> str | None:
        """The text of the first child `tag`, or `default` when there is none."""
        child = self.find(tag)
        return child.text if child is not None else default

    def path(self, *tags: str) -> Element | None:
        """The element at `tags` below this one (`path('surface', 'friction', 'ode')`)."""
        found: Element | None = self
        for tag in tags:
            found = found.find(tag) if found is not None else None
        return found

    def error(self, message: str) -> SdfError:
        return SdfError(message, self.location)


def parse(text: str, label: str) -> Element:
    """The root element of `text`; malformed XML is an SdfError at its line and column."""
    text = _COMMENT.sub(_blank_comment, text)
    parser = expat.ParserCreate()
    stack: list[Element] = []
    texts: list[list[str]] = []
    root: list[Element] = []

    def start(tag: str, attrib: dict[str, str]) -> None:
        element = Element(tag, attrib, Location(label, parser.CurrentLineNumber,
                                                parser.CurrentColumnNumber + 1))
        if stack:
            stack[-1].children.append(element)
        else:
            root.append(element)
        stack.append(element)
        texts.append([])

    def end(_tag: str) -> None:
        stack.pop().text = "".join(texts.pop()).strip()

    def data(chunk: str) -> None:
        if texts:
            texts[-1].append(chunk)

    parser.StartElementHandler, parser.EndElementHandler = start, end
    parser.CharacterDataHandler = data
    try:
        parser.Parse(text, True)
    except expat.ExpatError as exc:
        raise SdfError(f"not valid XML: {expat.ErrorString(exc.code)}",
                       Location(label, exc.lineno, exc.offset + 1)) from None
    return root[0]
