"""launch.frontend.Parser: reads a markup launch file into entities, and entities into
actions, substitutions and descriptions, through launcher's builder and registry (the tags of
launcher's XML and YAML files, and those a user's class exposes)."""

from __future__ import annotations

import importlib
import itertools
import os
import warnings
from importlib.metadata import entry_points
from pathlib import Path
from typing import Any, TextIO

from launch import Action, InvalidLaunchFileError, LaunchDescription, Substitution
from launch.frontend.entity import Entity, LauncherEntity
from launch.frontend.parse_substitution import (
    parse_if_substitutions,
    parse_if_with,
    parse_substitution,
    replace_escaped_characters,
    substitutions_in,
)
from launcher.description.registry import Registry, default_registry
from launcher.errors import Location
from launcher.frontend.builder import build_action, build_description

__all__ = ["Action", "Entity", "InvalidFrontendLaunchFileError", "InvalidLaunchFileError",
           "Parser", "Substitution", "instantiate_action", "parse_if_substitutions",
           "parse_substitution", "replace_escaped_characters"]

# launcher's frontends, by the names their `launch.frontend.parser` entry points have in ROS 2
_IMPLEMENTATIONS = {"xml": "launch_xml", "yaml": "launch_yaml"}


class InvalidFrontendLaunchFileError(InvalidLaunchFileError):
    """No frontend could read the launch file (`likely_errors`: what each one raised)."""


def instantiate_action(entity: Entity, parser: Parser) -> Action:
    """The action for `entity`: built by launcher's builder when it is an entity of launcher's
    loaders, else by the parse method a user's class exposed for its type."""
    if isinstance(entity, LauncherEntity):
        return build_action(entity.raw, parser.registry)
    found = parser.registry.find_action(entity.type_name)
    if not hasattr(found, "launch_parse"):  # launcher's own tags read launcher's entities only
        raise RuntimeError(f"Unrecognized entity of the type: {entity.type_name}")
    kind, kwargs = found.launch_parse(entity, parser)
    return kind(**kwargs)


class Parser:
    """Reads entities into actions and descriptions; its subclasses (launch_xml's and
    launch_yaml's) load files into entities. `registry` holds the tags and substitutions;
    `where` is the place errors in parsed text are reported at."""

    extensions_loaded = False
    frontend_parsers: dict[str, type[Parser]] | None = None

    def __init__(self, *, registry: Registry | None = None,
                 where: Location | None = None) -> None:
        self.registry = registry or default_registry()
        self.where = where

    # --- extensions and implementations -----------------------------------------------------
    @classmethod
    def load_launch_extensions(cls) -> None:
        """Import the launch extensions (`launch.frontend.launch_extension` entry points): their
        exposed actions and substitutions join launcher's registry."""
        if not cls.extensions_loaded:
            default_registry().load_extensions()
            cls.extensions_loaded = True

    @classmethod
    def load_parser_implementations(cls) -> None:
        """The frontends: launcher's XML and YAML, and any `launch.frontend.parser` entry
        point's."""
        if cls.frontend_parsers is not None:
            return
        found = {name: importlib.import_module(module).Parser
                 for name, module in _IMPLEMENTATIONS.items()}
        for point in entry_points(group="launch.frontend.parser"):
            try:
                found[point.name] = point.load()
            except Exception as exc:  # noqa: BLE001 (launch warns and goes on, as here)
                warnings.warn(f"Failed to load the parser extension: {point.name}: {exc}",
                              stacklevel=2)
        cls.frontend_parsers = dict(sorted(found.items()))

    @classmethod
    def get_available_extensions(cls) -> list[str]:
        cls.load_parser_implementations()
        return list(cls.frontend_parsers or ())

    @classmethod
    def is_extension_valid(cls, extension: str) -> bool:
        warnings.warn("Parser.is_extension_valid is deprecated, use Parser.is_filename_valid "
                      "instead", stacklevel=2)
        return extension in cls.get_available_extensions()

    @classmethod
    def get_parser_from_extension(cls, extension: str) -> type[Parser]:
        warnings.warn("Parser.get_parser_from_extension is deprecated, use "
                      "Parser.get_parsers_from_filename instead", stacklevel=2)
        cls.load_parser_implementations()
        if extension not in (cls.frontend_parsers or {}):
            raise RuntimeError("Not recognized frontend implementation")
        return cls.frontend_parsers[extension]  # type: ignore[index]

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        """The file name endings this frontend reads (none for the base)."""
        return set()

    @classmethod
    def may_parse(cls, filename: str) -> bool:
        return any(filename.endswith("." + ending) for ending in cls.get_file_extensions())

    @classmethod
    def get_parsers_from_filename(cls, filename: str) -> list[type[Parser]]:
        cls.load_parser_implementations()
        return [p for p in (cls.frontend_parsers or {}).values() if p.may_parse(filename)]

    @classmethod
    def is_filename_valid(cls, filename: str) -> bool:
        return bool(cls.get_parsers_from_filename(filename))

    @classmethod
    def get_file_extensions_from_parsers(cls) -> set[str]:
        cls.load_parser_implementations()
        return set(itertools.chain.from_iterable(
            p.get_file_extensions() for p in (cls.frontend_parsers or {}).values()))

    # --- reading ----------------------------------------------------------------------------
    def parse_action(self, entity: Entity) -> Action:
        self.load_launch_extensions()
        return instantiate_action(entity, self)

    def parse_substitution(self, value: str) -> list[Substitution]:
        return substitutions_in(value, self.registry, self.where)

    def parse_if_substitutions(self, value: Any) -> Any:
        return parse_if_with(value, self.parse_substitution)

    def escape_characters(self, value: str) -> str:
        return replace_escaped_characters(value)

    def parse_description(self, entity: Entity) -> LaunchDescription:
        """The description a `launch` root entity holds."""
        if entity.type_name != "launch":
            raise RuntimeError("Expected 'launch' as root tag")
        deprecated = entity.get_attr("deprecated", optional=True)
        if isinstance(entity, LauncherEntity):
            file = Path(entity.location.file)
            description = build_description(entity.raw, file, self.registry)
            description.deprecated_reason = deprecated
            return description
        actions = [self.parse_action(child) for child in entity.children]
        return LaunchDescription(actions, deprecated_reason=deprecated)

    @classmethod
    def load(cls, file: Any) -> tuple[Entity, Parser]:
        """The root entity of a launch file (a path or an open file) and a parser for it: each
        frontend tried in turn, those the file name suits first."""
        cls.load_parser_implementations()
        opened = isinstance(file, str | bytes | os.PathLike)
        stream: TextIO = open(file) if opened else file  # noqa: SIM115 (closed below)
        try:
            name = str(getattr(stream, "name", ""))
            suited = cls.get_parsers_from_filename(name)
            rest = [p for p in (cls.frontend_parsers or {}).values() if p not in suited]
            errors: list[Exception] = []
            for implementation in suited + rest:
                try:
                    return implementation.load(stream)
                except Exception as exc:  # noqa: BLE001 (each frontend's failure is reported)
                    errors.append(exc)
                    stream.seek(0)
            extension = os.path.splitext(name)[1][1:] if cls.is_filename_valid(name) else ""
            raise InvalidFrontendLaunchFileError(extension, likely_errors=errors)
        finally:
            if opened:
                stream.close()
