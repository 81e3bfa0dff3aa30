"""launch.frontend's `@expose_action(name)` and `@expose_substitution(name)`: a user's class
(or function) whose `parse` reads an entity, or a substitution's arguments, becomes a tag, or
a `$(name …)`, of launcher's XML and YAML launch files.

Each is added to launcher's registry as a small maker that the builder asks in place of its
declared fields: the user's `parse(entity, parser)` reads launch's view of launcher's entity
(launch_xml's or launch_yaml's Entity), and `parse(data)` the substitutions of the arguments.
"""

from __future__ import annotations

import importlib
import inspect
from collections.abc import Callable
from typing import Any

from launch import Action, Substitution
from launch.frontend.entity import Entity
from launch.frontend.parse_substitution import as_launch_text, instantiate_substitution
from launch.frontend.parser import Parser, instantiate_action
from launcher.description.condition import Condition
from launcher.description.registry import Registry, default_registry
from launcher.description.substitution import Text_
from launcher.errors import LaunchError, Location, ParseError
from launcher.frontend.entity import Entity as RawEntity

__all__ = ["Action", "Substitution", "expose_action", "expose_substitution",
           "instantiate_action", "instantiate_substitution"]

# What a user's parse method may raise about what it read (launch's entities raise these)
_READ_ERRORS = (AttributeError, TypeError, ValueError, RuntimeError)


class ExposedAction:
    """A tag whose entity a user's `parse(entity, parser)` reads into (class, kwargs)."""

    def __init__(self, name: str, parse: Callable[..., Any]) -> None:
        self.name, self.parse = name, parse

    def __repr__(self) -> str:
        return f"{_owner(self.parse)} (exposed as '{self.name}')"

    def launch_parse(self, entity: Entity, parser: Parser) -> tuple[Any, dict[str, Any]]:
        """As launch calls it: parse, then refuse attributes and children left unread."""
        kind, kwargs = self.parse(entity, parser)
        entity.assert_entity_completely_parsed()
        return kind, kwargs

    def from_entity(self, raw: RawEntity, registry: Registry,
                    condition: Condition | None) -> Action:
        """The action for one of launcher's entities (launcher.frontend.builder's hook); its
        `if`/`unless` are the builder's unless the parse method made its own condition."""
        entity = _view(raw)
        entity.mark_read("if", "unless")
        try:
            kind, kwargs = self.launch_parse(entity, Parser(registry=registry,
                                                            where=raw.location))
            if condition is not None and kwargs.get("condition") is None:
                kwargs["condition"] = condition
            action = kind(**kwargs)
        except LaunchError as exc:
            raise exc.at(raw.location) from None
        except _READ_ERRORS as exc:
            raise ParseError(f"{raw.tag}: {exc}", raw.location) from exc
        if getattr(action, "where", None) is None:
            action.where = raw.location  # where its failures at run time are reported
        return action


class ExposedSubstitution:
    """A `$(name …)` whose arguments a user's `parse(data)` reads into (class, kwargs)."""

    def __init__(self, name: str, parse: Callable[..., Any]) -> None:
        self.name, self.parse = name, parse

    def __repr__(self) -> str:
        return f"{_owner(self.parse)} (exposed as '{self.name}')"

    def from_args(self, args: list[Text_], where: Location | None) -> Any:
        """The substitution for `$(name a b …)` (the registry's protocol for substitutions)."""
        try:
            kind, kwargs = self.parse([as_launch_text(arg) for arg in args])
            return kind(**kwargs)
        except LaunchError as exc:
            raise exc.at(where) from None
        except _READ_ERRORS as exc:
            raise ParseError(f"$({self.name}): {exc}", where) from exc


def expose_action(name: str) -> Callable[[Any], Any]:
    """Make the decorated class (by its `parse` classmethod) or function the tag `name`."""
    return _exposer(name, "action", ExposedAction)


def expose_substitution(name: str) -> Callable[[Any], Any]:
    """Make the decorated class (by its `parse` classmethod) or function `$(name …)`."""
    return _exposer(name, "substitution", ExposedSubstitution)


def _exposer(name: str, kind: str, maker: type) -> Callable[[Any], Any]:
    def expose(exposed: Any) -> Any:
        parse = _parse_method(exposed, kind, name)
        registry = default_registry()
        table = registry.actions if kind == "action" else registry.substitutions
        known = table.get(name)
        if not (isinstance(known, maker) and known.parse == parse):  # (exposed again: a no-op)
            registry.add(kind, name, maker(name, parse))
        return exposed

    return expose


def _parse_method(exposed: Any, kind: str, name: str) -> Callable[..., Any]:
    if inspect.isclass(exposed):
        if inspect.ismethod(getattr(exposed, "parse", None)):
            return exposed.parse
        raise RuntimeError("Did not find a class method called 'parse' in the class being "
                           "decorated.")
    if inspect.isfunction(exposed):
        return exposed
    raise RuntimeError(f"Exposed {kind} parser for {name} is not a callable or a class "
                       "containing a parse method")


def _owner(parse: Callable[..., Any]) -> str:
    return getattr(parse, "__qualname__", repr(parse)).removesuffix(".parse")


def _view(raw: RawEntity) -> Any:
    """launch's view of launcher's entity: launch_xml's for XML, launch_yaml's for YAML."""
    frontend = "launch_xml" if raw.nested_in_children else "launch_yaml"
    return importlib.import_module(frontend).Entity(raw)
