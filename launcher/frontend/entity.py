"""The format-neutral tree that the YAML and XML loaders produce.

An `Entity` is one tag: its attributes (each with the place it was written) and its child
entities. The builder turns entities into actions; it never looks at YAML or XML itself.
"""

from __future__ import annotations

from launcher.errors import Location
from launcher.records import dataclass, field


@dataclass
class Attribute:
    """One attribute value: a scalar as its source text, or a list of nested entities."""

    value: str | list[Entity]
    location: Location
    # Column offset of the text inside its quotes, so that errors can point into the value.
    # None when the text does not map 1:1 onto the source (block scalars, escapes).
    text_offset: int | None = None
    key_location: Location | None = None  # where the attribute's name is written
    # The format itself made the value a string (a quoted YAML scalar, or plain text YAML
    # reads as one); XML text is typed by YAML's rules where that matters (parameters).
    string: bool = False
    roslaunch: bool = False  # its substitutions are roslaunch's (roslaunch_substitutions.py)
    literal: bool = False  # taken as written, no substitutions (rosparam without subst_value)

    @property
    def name_location(self) -> Location:
        return self.key_location or self.location

    def text_location(self, index: int) -> Location:
        if self.text_offset is None:
            return self.location
        return self.location.shifted(self.text_offset + index)


@dataclass
class Entity:
    tag: str
    location: Location
    attributes: dict[str, Attribute] = field(default_factory=dict)
    # Child entities: for YAML the `children:` list (or the list form of a tag); for XML every
    # child element, nested entities such as <env> included (the builder sorts them out).
    children: list[Entity] = field(default_factory=list)
    # YAML keeps nested entities under attributes; XML keeps them among children.
    nested_in_children: bool = False
