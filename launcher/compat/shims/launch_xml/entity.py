"""launch_xml.Entity: one XML element, attributes typed by coercion (`'3'` → 3 for int)."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any

from launch.frontend.entity import Entity as BaseEntity
from launch.frontend.entity import LauncherEntity
from launch.frontend.type_utils import check_is_list_entity
from launch.utilities.type_utils import get_typed_value

from launcher.frontend.entity import Entity as RawEntity
from launcher.frontend.xml_loader import load_xml

__all__ = ["Entity"]


class Entity(LauncherEntity):
    """An element of an XML launch file: one that launcher's XML loader read, or an
    `xml.etree` element. `name-sep="…"` makes the attribute `name` a list, split at it."""

    def __init__(self, xml_element: RawEntity | ET.Element | None = None, *,
                 parent: BaseEntity | None = None) -> None:
        if isinstance(xml_element, ET.Element):
            xml_element = _from_element(xml_element)
        if not isinstance(xml_element, RawEntity):
            raise TypeError(f"launch_xml.Entity: expected an XML element, got "
                            f"{type(xml_element).__name__}")
        super().__init__(xml_element, parent)
        self._read_children: set[str] = set()

    @property
    def children(self) -> list[BaseEntity]:
        self._read_children = {child.tag for child in self.raw.children}
        return [Entity(child, parent=self) for child in self.raw.children]

    def assert_entity_completely_parsed(self) -> None:
        tags = {child.tag for child in self.raw.children} - self._read_children
        if tags:
            raise ValueError(f"Unexpected nested tag(s) found in `{self.type_name}`: {tags}")
        unread = self._unread_attributes()
        if unread:
            raise ValueError(f"Unexpected attribute(s) found in `{self.type_name}`: {unread}")

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False,
                 can_be_str: bool = True) -> Any:
        """See launch.frontend.Entity.get_attr; text is coerced to `data_type` (TypeError if
        it cannot be)."""
        if check_is_list_entity(data_type):
            nested = [child for child in self.raw.children if child.tag == name]
            if not nested:
                return self._missing(name, data_type, optional)
            self._read_children.add(name)
            return [Entity(child, parent=self) for child in nested]
        attribute = self.raw.attributes.get(name)
        if attribute is None or not isinstance(attribute.value, str):
            return self._missing(name, data_type, optional)
        value: str | list[str] = attribute.value
        separator = self.raw.attributes.get(f"{name}-sep")
        if separator is not None and isinstance(separator.value, str):
            self._read.add(f"{name}-sep")
            value = attribute.value.split(separator.value)
        self._read.add(name)
        try:
            return get_typed_value(value, data_type, can_be_str=can_be_str)
        except ValueError:
            raise TypeError(f"Attribute '{name}' of Entity '{self.type_name}' expected to be "
                            f"of type '{data_type}'.'{value}' can not be converted to one of "
                            "those types") from None


def _from_element(element: ET.Element) -> RawEntity:
    """An xml.etree element as launcher's XML loader reads it (within a <launch> root)."""
    text = ET.tostring(element)
    if element.tag == "launch":
        return load_xml(text, "<xml>")
    return load_xml(b"<launch>" + text + b"</launch>", "<xml>").children[0]
