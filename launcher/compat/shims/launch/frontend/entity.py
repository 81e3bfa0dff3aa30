"""launch.frontend.Entity: one tag of a launch file, as an action's `parse(entity, parser)`
reads it; and launch's view of the entities launcher's own XML and YAML loaders make."""

from __future__ import annotations

from typing import Any

from launcher.errors import Location
from launcher.frontend.entity import Entity as RawEntity


class Entity:
    """A frontend's entity (launch's abstract base): its type, parent, children and
    attributes, each frontend reading and typing them its own way."""

    @property
    def type_name(self) -> str:
        raise NotImplementedError

    @property
    def parent(self) -> Entity | None:
        raise NotImplementedError

    @property
    def children(self) -> list[Entity]:
        raise NotImplementedError

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False,
                 can_be_str: bool = True) -> Any:
        """The attribute `name` as `data_type` (a scalar type, `List[x]`, `List[Entity]` for
        nested entities, None for YAML's reading); None when absent and `optional`.

        Raises AttributeError when absent, TypeError or ValueError when not of the type."""
        raise NotImplementedError

    def assert_entity_completely_parsed(self) -> None:
        """Raise ValueError if an attribute or nested entity was never read."""
        raise NotImplementedError


class LauncherEntity(Entity):
    """What launch_xml's and launch_yaml's entities share: a view of one of launcher's
    entities (launcher.frontend.entity), remembering which attributes were read."""

    def __init__(self, raw: RawEntity, parent: Entity | None = None) -> None:
        self.raw = raw
        self._parent = parent
        self._read: set[str] = set()

    @property
    def type_name(self) -> str:
        return self.raw.tag

    @property
    def parent(self) -> Entity | None:
        return self._parent

    @property
    def location(self) -> Location:
        return self.raw.location

    def mark_read(self, *names: str) -> None:
        """Count attributes as read (launcher's builder reads `if` and `unless` itself)."""
        self._read.update(names)

    def _missing(self, name: str, data_type: Any, optional: bool) -> None:
        if not optional:
            raise AttributeError(f"Attribute '{name}' of type '{data_type}' not found in "
                                 f"Entity '{self.type_name}'")

    def _unread_attributes(self) -> set[str]:
        return set(self.raw.attributes) - self._read
