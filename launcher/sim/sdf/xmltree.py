"""SDF's XML as a tree whose elements can say where they are (file:line:column).

The tree is ElementTree's, built by its C parser (loading is benchmarked), with elements of
a subclass that adds SDF's helpers (`value` gives a child's text stripped; `text` is raw).
ElementTree keeps no line numbers: an element's place is found only when a message needs
it, by reading its document once more with expat and counting elements in document order.

Custom elements (SDFormat's `<prefix:name>`, and Gazebo's `<gz::system_priority>`) are kept
as libsdformat keeps them, names as written, with no XML namespace processing: the colons of
element and attribute names are read as NAME_COLON (a name character XML accepts), whether
or not the file declares the prefix with `xmlns:` (Gazebo's own worlds write `<gz:policies>`
undeclared, and `::`, which a namespace-aware parser refuses).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections import deque
from xml.parsers import expat

from launcher.errors import LaunchError, Location

_RECENT = 64  # documents whose elements can still be placed
NAME_COLON = "\u00b7"  # stands for ':' in element and attribute names
_NAMED_COLON = re.compile(r"<\/?[A-Za-z_][\w.-]*:|\s[A-Za-z_][\w.-]*:[\w.:-]*\s*=")
_TAG = re.compile(r"<(/?)([A-Za-z_][^\s/>]*)((?:[^>\"']|\"[^\"]*\"|'[^']*')*)>")
_QUOTED = re.compile(r"(\"[^\"]*\"|'[^']*')")
_COLON_NAME = re.compile(r"[A-Za-z_][\w.-]*(?::+[\w.-]+)+")
_DECLARED = re.compile(r"\sxmlns:([A-Za-z_][\w.-]*)\s*=")


class SdfError(LaunchError):
    """An SDF world or model that cannot be loaded."""


class Element(ET.Element):
    __slots__ = ()

    @property
    def stripped(self) -> str:
        return self.text.strip() if self.text else ""

    @property
    def children(self) -> list[Element]:
        return list(self)

    def value(self, tag: str, default: str | None = None) -> str | None:
        """The text of the first child `tag`, or `default` when there is none."""
        child = self.find(tag)
        if child is None:
            return default
        return child.text.strip() if child.text else ""

    def path(self, *tags: str) -> Element | None:
        """The element at `tags` below this one (`path('surface', 'friction', 'ode')`)."""
        found: Element | None = self
        for tag in tags:
            found = found.find(tag) if found is not None else None
        return found

    @property
    def location(self) -> Location:
        return _place(self)

    def error(self, message: str) -> SdfError:
        return SdfError(message, self.location)


class _Document:
    def __init__(self, text: str, label: str, root: Element) -> None:
        self.text, self.label, self.root = text, label, root
        self._places: dict[int, tuple[int, int]] | None = None
        self.declared: set[str] = set()  # the prefixes the file declares (xmlns:prefix)

    def place(self, element: Element) -> Location | None:
        if self._places is None:
            order = {id(e): i for i, e in enumerate(self.root.iter())}
            positions = _positions(self.text)
            self._places = {key: positions[i] for key, i in order.items() if i < len(positions)}
        found = self._places.get(id(element))
        return Location(self.label, *found) if found else None


_documents: deque[_Document] = deque(maxlen=_RECENT)


def _document(element: Element) -> _Document | None:
    for document in reversed(_documents):
        if any(e is element for e in document.root.iter(element.tag)):
            return document
    return None


def _place(element: Element) -> Location:
    document = _document(element)
    found = document.place(element) if document is not None else None
    return found or Location("<sdf>")


def _positions(text: str) -> list[tuple[int, int]]:
    """(line, column) of every element's start, in document order."""
    parser = expat.ParserCreate()
    found: list[tuple[int, int]] = []

    def start(_tag: str, _attrib: dict[str, str]) -> None:
        found.append((parser.CurrentLineNumber, parser.CurrentColumnNumber + 1))

    parser.StartElementHandler = start
    parser.Parse(text, True)
    return found


def parse(text: str, label: str) -> Element:
    """The root element of `text`; malformed XML is an SdfError at its line and column."""
    declared = set(_DECLARED.findall(text))
    text = _plain_names(_blank_comments(text))
    parser = ET.XMLParser(target=ET.TreeBuilder(element_factory=Element))  # type: ignore
    try:
        parser.feed(text)
        root = parser.close()
    except ET.ParseError as exc:
        line, column = exc.position
        raise SdfError(f"not valid XML: {expat.ErrorString(exc.code)}",
                       Location(label, line, column + 1)) from None
    document = _Document(text, label, root)
    document.declared = declared
    _documents.append(document)
    return root


def _plain_names(text: str) -> str:
    """`text` with the colons of its element and attribute names read as NAME_COLON (never in
    attribute values, text or CDATA; a document with none is returned as it is)."""
    if not _NAMED_COLON.search(text):
        return text
    pieces, position = [], 0
    for cdata in [*_CDATA.finditer(text), None]:
        end = cdata.start() if cdata is not None else len(text)
        pieces.append(_TAG.sub(_plain_tag, text[position:end]))
        if cdata is not None:
            pieces.append(cdata.group(0))
            position = cdata.end()
    return "".join(pieces)


def _plain_tag(tag: re.Match[str]) -> str:
    slash, name, rest = tag.groups()
    parts = _QUOTED.split(rest)  # odd parts are quoted values: left as they are
    rest = "".join(_COLON_NAME.sub(_colons, part) if i % 2 == 0 else part
                   for i, part in enumerate(parts))
    return f"<{slash}{_COLON_NAME.sub(_colons, name)}{rest}>"


def _colons(name: re.Match[str]) -> str:
    return name.group(0).replace(":", NAME_COLON)


def custom(element: Element) -> tuple[str, str, bool] | None:
    """For a custom element (`<prefix:name>`): its name as written, its prefix, and whether
    its file declares the prefix; None for one of SDF's own."""
    if NAME_COLON not in element.tag:
        return None
    name = element.tag.replace(NAME_COLON, ":")
    prefix = name.partition(":")[0]
    document = _document(element)
    return name, prefix, document is not None and prefix in document.declared


def after_prologue(text: str) -> str:
    """The text from its root element on: past the XML declaration, processing instructions
    and comments, so the root's tag tells the format (`<sdf`, `<robot`, `<mujoco`)."""
    head = text.lstrip()
    while head.startswith(("<?", "<!--")):
        end = "?>" if head.startswith("<?") else "-->"
        head = head[head.find(end) + len(end):].lstrip() if end in head else ""
    return head


_CDATA = re.compile(r"<!\[CDATA\[.*?\]\]>", re.S)


def _blank_comments(text: str) -> str:
    """Comments as blank lines: Gazebo's parser accepts `--` inside them (gz-sim's own worlds
    have it), XML does not; line numbers stay the file's."""
    start = text.find("<!--")
    if start < 0:
        return text
    pieces, position = [], 0
    while start >= 0:
        cdata = text.rfind("<![CDATA[", position, start)
        if cdata >= 0 and text.find("]]>", cdata) > start:  # inside CDATA: not a comment
            end = text.find("]]>", cdata) + 3
            pieces.append(text[position:end])
            position = end
        else:
            end = text.find("-->", start + 4)
            if end < 0:
                break  # an unclosed comment: the parser reports it
            pieces.append(text[position:start])
            pieces.append("\n" * text.count("\n", start, end))
            position = end + 3
        start = text.find("<!--", position)
    pieces.append(text[position:])
    return "".join(pieces)
