"""XML launch files: a `<launch>` root; attributes are strings; nested entities are child tags.

expat is used directly so that every element keeps its line and column.
"""

from __future__ import annotations

from xml.parsers import expat

from launcher.errors import Location, ParseError
from launcher.frontend.entity import Attribute, Entity

MAX_DEPTH = 100  # elements within elements: far past any launch file, and safe to recurse


def load_xml(data: bytes, file: str) -> Entity:
    """Parse an XML launch file into its root `launch` entity."""
    parser = expat.ParserCreate()
    stack: list[Entity] = []
    roots: list[Entity] = []

    def start(tag: str, attrs: dict[str, str]) -> None:
        where = Location(file, parser.CurrentLineNumber, parser.CurrentColumnNumber + 1)
        if len(stack) >= MAX_DEPTH:
            raise ParseError(f"<{tag}> is nested {len(stack) + 1} elements deep; launcher reads "
                             f"launch files nested up to {MAX_DEPTH} deep", where)
        entity = Entity(tag, where, nested_in_children=True)
        entity.attributes = {k: Attribute(v, where) for k, v in attrs.items()}
        (stack[-1].children if stack else roots).append(entity)
        stack.append(entity)

    texts: list[list[str]] = []

    def end(_tag: str) -> None:
        entity = stack.pop()
        text = "".join(texts.pop())
        if entity.tag == "rosparam" and text.strip():  # roslaunch's inline YAML
            entity.attributes["#text"] = Attribute(text, entity.location)

    def character_data(text: str) -> None:
        texts[-1].append(text)

    def begin(tag: str, attrs: dict[str, str]) -> None:
        texts.append([])
        start(tag, attrs)

    parser.StartElementHandler = begin
    parser.EndElementHandler = end
    parser.CharacterDataHandler = character_data
    try:
        parser.Parse(data, True)
    except expat.ExpatError as exc:
        where = Location(file, exc.lineno, exc.offset + 1)
        raise ParseError(f"malformed XML: {expat.ErrorString(exc.code)}", where) from None
    except (LookupError, UnicodeError) as exc:  # the declaration names an unknown encoding
        raise ParseError(f"cannot decode the file: {exc}; expected UTF-8 (or an encoding the "
                         f"XML declaration names and Python knows)",
                         Location(file, parser.CurrentLineNumber or 1, 1)) from None
    root = roots[0]
    if root.tag != "launch":
        raise ParseError(f"the root element is <{root.tag}>; expected <launch>", root.location)
    # (version, deprecated: roslaunch's; extensions: launcher's, see builder.py)
    unexpected = sorted(set(root.attributes) - {"version", "deprecated", "extensions"})
    if unexpected:
        raise ParseError(f"<launch> takes no attribute '{unexpected[0]}'", root.location)
    return root
