"""launch_yaml.Entity: one YAML map, its values typed as YAML wrote them (checked, not
coerced: `3` is an int, `'3'` a str)."""

from __future__ import annotations

from typing import Any

import yaml
from launch.frontend.entity import Entity as BaseEntity
from launch.frontend.entity import LauncherEntity
from launch.frontend.type_utils import check_is_list_entity
from launch.utilities.type_utils import is_instance_of

from launcher.frontend.entity import Attribute
from launcher.frontend.entity import Entity as RawEntity
from launcher.frontend.yaml_loader import load_yaml

__all__ = ["Entity"]


class Entity(LauncherEntity):
    """A tag of a YAML launch file: one that launcher's YAML loader read, or the data
    (`element`, a map or a list of children) of a tag named `type_name`."""

    def __init__(self, element: RawEntity | dict | list, type_name: str | None = None, *,
                 parent: BaseEntity | None = None) -> None:
        if not isinstance(element, RawEntity):
            element = _from_data(element, type_name)
        super().__init__(element, parent)
        self._children_read = False

    @property
    def children(self) -> list[BaseEntity]:
        self._children_read = True
        return [Entity(child, parent=self) for child in self.raw.children]

    def assert_entity_completely_parsed(self) -> None:
        unread = self._unread_attributes()
        if self.raw.children and not self._children_read:
            unread.add("children")
        if unread:
            raise ValueError(f"Unexpected key(s) found in `{self.type_name}`: {unread}")

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False,
                 can_be_str: bool = True) -> Any:
        """See launch.frontend.Entity.get_attr; the value must already be of `data_type`
        (a str too, with `can_be_str`), else TypeError."""
        attribute = self.raw.attributes.get(name)
        if attribute is None:
            return self._missing(name, data_type, optional)
        self._read.add(name)
        if check_is_list_entity(data_type):
            if isinstance(attribute.value, list) and attribute.value:
                return [Entity(item, parent=self) for item in attribute.value]
            raise TypeError(f"Attribute '{name}' of Entity '{self.type_name}' expected to be a "
                            "list of dictionaries.")
        data = _value(attribute)
        if not is_instance_of(data, data_type, can_be_str=can_be_str):
            raise TypeError(f"Attribute '{name}' of Entity '{self.type_name}' expected to be of "
                            f"type '{data_type}', got '{type(data)}'")
        return data


def _value(attribute: Attribute) -> Any:
    """The value as YAML typed it (the loader keeps its text, and whether it was a string)."""
    if isinstance(attribute.value, list):
        return [_item(item) for item in attribute.value]
    if attribute.string:
        return attribute.value
    try:
        return yaml.safe_load(attribute.value)
    except yaml.YAMLError:
        return attribute.value


def _item(item: RawEntity) -> Any:
    """A plain list's scalar (the loader wraps each as {value: …}); a map stays an entity."""
    only = item.attributes.get("value")
    if len(item.attributes) == 1 and only is not None and isinstance(only.value, str):
        return _value(only)
    return item


def _from_data(element: Any, type_name: str | None) -> RawEntity:
    """Loaded YAML data (`yaml.safe_load`'s) as launcher's YAML loader reads the same text."""
    if type_name is None:
        raise TypeError("launch_yaml.Entity: a map or list element needs its type_name")
    if type_name == "launch":
        return load_yaml(yaml.safe_dump({"launch": element}), "<yaml>")
    return load_yaml(yaml.safe_dump({"launch": [{type_name: element}]}), "<yaml>").children[0]
