"""Entities → actions, driven by each action's declared fields (see description.fields).

One generic builder for every tag: it finds the class in the registry, maps attributes and
nested entities onto fields, parses substitutions, checks literal values early, and rejects
whatever is left over with "did you mean".
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launcher.description.action import Action, LaunchDescription
from launcher.description.condition import TextCondition
from launcher.description.fields import Kind, coerce, declared_fields, frontend_name
from launcher.description.parameters import Written
from launcher.description.registry import EXTENSION, Registry, default_registry
from launcher.description.substitution import Substitution, Text, Text_, is_literal
from launcher.errors import LaunchError, Location, ParseError, did_you_mean
from launcher.frontend.entity import Attribute, Entity
from launcher.frontend.roslaunch_substitutions import parse_roslaunch
from launcher.frontend.substitution_parser import Call, SubstitutionSyntaxError, parse_text

_CONDITIONS = ("if", "unless")


def build_description(root: Entity, path: Path, registry: Registry | None = None) -> \
        LaunchDescription:
    registry = registry or default_registry()
    if not _opted_in(root):
        _refuse_extensions(root, registry)
    actions = [build_action(child, registry) for child in root.children]
    return LaunchDescription(actions, file=path, where=root.location)


# --- launcher's extensions: a ROS 2 file that uses them says so once ----------------------
EXTENSIONS = ("launcher",)  # what `<launch extensions="…">` (YAML `extensions: […]`) takes


def _opted_in(root: Entity) -> bool:
    given = root.attributes.get("extensions")
    if given is None:
        return False
    words = str(given.value).replace(",", " ").split()
    for word in words:
        if word not in EXTENSIONS:
            raise ParseError(f"extensions: expected {', '.join(EXTENSIONS)} (launcher's own), "
                             f"got '{word}'{did_you_mean(word, EXTENSIONS)}", given.location)
    return "launcher" in words


def _refuse_extensions(root: Entity, registry: Registry) -> None:
    """A tag or attribute of launcher's own, in a file that does not say it uses them (real
    ros2 launch refuses such a file): an error at it, naming the opt-in. roslaunch's own
    (a ROS 1 file's machine=) are no extension."""
    actions = registry.known("action")
    for entity in _entities(root):
        cls = registry.find_action(entity.tag) if entity.tag in actions else None
        if cls is None:
            continue
        if getattr(cls, "extension", False):
            raise ParseError(_no_opt_in(f"<{entity.tag}>", root), entity.location)
        for name in _extension_names(cls):
            given = entity.attributes.get(name)
            if given is not None and not given.roslaunch:
                raise ParseError(_no_opt_in(f"{entity.tag}'s {name}=", root),
                                 given.name_location)


def _entities(entity: Entity):
    """The entity and every one nested in it, as children or in attributes (YAML's)."""
    yield entity
    for child in entity.children:
        yield from _entities(child)
    for attribute in entity.attributes.values():
        if isinstance(attribute.value, list):
            for nested in attribute.value:
                yield from _entities(nested)


def _extension_names(cls: type) -> list[str]:
    if not hasattr(cls, "__dataclass_fields__"):  # (a ROS 2 extension's own class)
        return []
    return [n for f, s in declared_fields(cls) if f.metadata.get(EXTENSION)
            for n in (frontend_name(f, s), *s.aliases)]


def _no_opt_in(what: str, root: Entity) -> str:
    how = '<launch extensions="launcher">' if root.nested_in_children else \
        "'extensions: [launcher]' beside 'launch:'"
    return (f"{what} is launcher's extension, which ROS 2's launch lacks: say so once with "
            f"{how} (ros2 launch refuses this file either way)")


def build_action(entity: Entity, registry: Registry) -> Action:
    cls = registry.find_action(entity.tag)
    if cls is None:
        hint = did_you_mean(entity.tag, registry.known("action"))
        raise ParseError(f"unknown tag '{entity.tag}'{hint}", entity.location)
    if hasattr(cls, "from_entity"):  # it parses its own entity (launch.frontend.expose_action)
        return cls.from_entity(entity, registry, _condition(entity, registry))
    kwargs = _fields(entity, cls, registry)
    kwargs["condition"] = _condition(entity, registry)
    return _construct(cls, kwargs, entity)


def _construct(cls: type, kwargs: dict[str, Any], entity: Entity) -> Any:
    try:
        return cls(**kwargs, where=entity.location)
    except LaunchError as exc:
        raise exc.at(entity.location) from None
    except (TypeError, ValueError) as exc:
        raise ParseError(f"{entity.tag}: {exc}", entity.location) from None


def _fields(entity: Entity, cls: type, registry: Registry) -> dict[str, Any]:
    kwargs: dict[str, Any] = {}
    used_attrs: set[str] = set(_CONDITIONS)
    used_children: set[int] = set()
    takes_children = False
    for field, spec in declared_fields(cls):
        name = frontend_name(field, spec)
        names = (name, *spec.aliases)
        what = f"{entity.tag}.{name}"
        if spec.kind is Kind.CHILDREN:
            takes_children = True
            continue
        present = [n for n in names if n in entity.attributes]
        if len(present) > 1:
            raise ParseError(f"{what}: give either '{present[0]}' or '{present[1]}', not both",
                             entity.attributes[present[1]].location)
        if spec.kind in (Kind.ENTRIES, Kind.ACTIONS) and entity.nested_in_children:
            nested = [(i, c) for i, c in enumerate(entity.children) if c.tag in names]
            if nested:
                used_children.update(i for i, _ in nested)
                kwargs[field.name] = _nested_xml(spec, nested, registry, what)
                continue
        if not present:
            if spec.required:
                raise ParseError(f"'{entity.tag}' needs the attribute '{name}'"
                                 + (f" ({spec.doc})" if spec.doc else ""), entity.location)
            continue
        used_attrs.add(present[0])
        kwargs[field.name] = _value(entity.attributes[present[0]], spec, registry, what)
    _reject_leftovers(entity, cls, used_attrs)
    children = [c for i, c in enumerate(entity.children) if i not in used_children]
    if takes_children:
        field_name = next(f.name for f, s in declared_fields(cls) if s.kind is Kind.CHILDREN)
        kwargs[field_name] = [build_action(c, registry) for c in children]
    elif children:
        raise ParseError(f"'{entity.tag}' takes no child tag '{children[0].tag}'",
                         children[0].location)
    return kwargs


def _value(attribute: Attribute, spec: Any, registry: Registry, what: str) -> Any:
    value = attribute.value
    if spec.kind is Kind.ENTRIES:
        if not isinstance(value, list):
            raise ParseError(f"{what}: expected a list of maps", attribute.location)
        return [_record(spec.entry, e, registry, what) for e in value]
    if spec.kind is Kind.ACTIONS:
        if isinstance(value, list):
            return [build_action(e, registry) for e in value]
        return value  # a word such as on_exit: shutdown; the action checks it
    if spec.kind is Kind.VALUE:
        return _parameter_value(attribute, registry, what)
    if isinstance(value, list):
        raise ParseError(f"{what}: expected a value, not a list", attribute.location)
    if spec.kind is Kind.NAME:
        return value
    text = parse_substitutions(attribute, registry)
    if (spec.kind in (Kind.BOOL, Kind.FLOAT, Kind.INT) or spec.choices) and is_literal(text):
        try:
            return coerce(spec.kind, value, what, spec)
        except ParseError as exc:
            raise exc.at(attribute.location) from None
    return text


def _parameter_value(attribute: Attribute, registry: Registry, what: str) -> Any:
    """A parameter value: one text, or a YAML list of them."""
    if not isinstance(attribute.value, list):
        return Written(parse_substitutions(attribute, registry), attribute.string)
    items = []
    for entity in attribute.value:
        item = entity.attributes.get("value")
        if len(entity.attributes) != 1 or item is None or isinstance(item.value, list):
            raise ParseError(f"{what}: a parameter list holds values, not maps or lists",
                             entity.location)
        items.append(Written(parse_substitutions(item, registry), item.string))
    return items


def _nested_xml(spec: Any, nested: list[tuple[int, Entity]], registry: Registry,
                what: str) -> list[Any]:
    if spec.kind is Kind.ENTRIES:
        return [_record(spec.entry, e, registry, what) for _, e in nested]
    return [build_action(c, registry) for _, e in nested for c in e.children]


def _record(cls: type, entity: Entity, registry: Registry, what: str) -> Any:
    kwargs: dict[str, Any] = {}
    used: set[str] = set()
    valid = [frontend_name(f, s) for f, s in declared_fields(cls)]
    for key, attribute in entity.attributes.items():
        if key not in valid:
            raise ParseError(f"{what}: unknown key '{key}'{did_you_mean(key, valid)}; "
                             f"entries take {', '.join(valid)}", attribute.name_location)
    children = list(entity.children)
    for field, spec in declared_fields(cls):
        name = frontend_name(field, spec)
        if spec.kind is Kind.ENTRIES and any(c.tag == name for c in children):
            kwargs[field.name] = [_record(spec.entry, c, registry, what)
                                  for c in children if c.tag == name]
            children = [c for c in children if c.tag != name]
        elif name in entity.attributes:
            used.add(name)
            kwargs[field.name] = _value(entity.attributes[name], spec, registry, what)
        elif spec.required:
            raise ParseError(f"{what}: each entry needs '{name}'", entity.location)
    if children:
        raise ParseError(f"{what}: entries take no child tag '{children[0].tag}'",
                         children[0].location)
    if "where" in getattr(cls, "__dataclass_fields__", {}):  # an entry that reports later
        kwargs["where"] = entity.location
    return cls(**kwargs)


def _reject_leftovers(entity: Entity, cls: type, used: set[str]) -> None:
    valid = [n for f, s in declared_fields(cls) if s.kind is not Kind.CHILDREN
             for n in (frontend_name(f, s), *s.aliases)] + list(_CONDITIONS)
    for key, attribute in entity.attributes.items():
        if key not in used:
            raise ParseError(
                f"'{entity.tag}' has no attribute '{key}'{did_you_mean(key, valid)}; "
                f"valid: {', '.join(sorted(set(valid)))}", attribute.name_location)


def _condition(entity: Entity, registry: Registry) -> TextCondition | None:
    given = [k for k in _CONDITIONS if k in entity.attributes]
    if len(given) == 2:
        raise ParseError(f"'{entity.tag}' has both 'if' and 'unless'; use one",
                         entity.attributes["unless"].name_location)
    if not given:
        return None
    attribute = entity.attributes[given[0]]
    text = parse_substitutions(attribute, registry)
    if is_literal(text) and attribute.value.strip().lower() not in ("true", "false", "1", "0"):
        raise ParseError(f"{given[0]}: expected true, false, 1 or 0, got '{attribute.value}'",
                         attribute.location)
    return TextCondition(text, negate=given[0] == "unless", where=attribute.location)


# --- substitutions ------------------------------------------------------------------------
def parse_file_text(text: str, file: str, registry: Registry | None = None,
                    roslaunch: bool = False) -> Text_:
    """The substitutions in a whole file's text (a params file read with allow_substs, or
    roslaunch's rosparam with subst_value: `roslaunch`); an error names the line and column
    in that file."""
    registry = registry or default_registry()

    def at(offset: int) -> Location:
        line = text.count("\n", 0, offset) + 1
        return Location(file, line, offset - (text.rfind("\n", 0, offset) + 1) + 1)

    try:
        parts = parse_roslaunch(text) if roslaunch else parse_text(text)
    except SubstitutionSyntaxError as exc:
        raise ParseError(exc.message, at(exc.offset)) from None
    whole = Attribute(text, Location(file, 1, 1))
    out = []
    for part in parts:
        try:
            out.append(_part(part, whole, registry))
        except ParseError as exc:
            raise ParseError(exc.message, at(part.offset)) from None
    return tuple(out)


# roslaunch's substitutions that ROS 2 spells otherwise (ROS 2 refuses the ROS 1 names)
ROS2_SPELLINGS = {"arg": "var", "find": "find-pkg-share", "optenv": "env"}


def parse_substitutions(attribute: Attribute, registry: Registry) -> Text_:
    assert isinstance(attribute.value, str)
    if attribute.literal:
        return (Text(attribute.value),)
    try:
        parts = parse_roslaunch(attribute.value) if attribute.roslaunch else \
            parse_text(attribute.value)
    except SubstitutionSyntaxError as exc:
        raise ParseError(exc.message, attribute.text_location(exc.offset)) from None
    return tuple(_part(p, attribute, registry) for p in parts)


def _part(part: str | Call, attribute: Attribute, registry: Registry) -> Substitution:
    if isinstance(part, str):
        return Text(part)
    where = attribute.text_location(part.offset)
    cls = registry.find_substitution(part.name)
    if cls is None:
        if part.name in ROS2_SPELLINGS:
            raise ParseError(f"unknown substitution '$({part.name})': that is roslaunch's (ROS 1)"
                             f"; a ROS 2 file writes $({ROS2_SPELLINGS[part.name]} …)", where)
        hint = did_you_mean(part.name, registry.known('substitution'))
        raise ParseError(f"unknown substitution '$({part.name})'{hint}", where)
    args = [tuple(_part(p, attribute, registry) for p in arg) for arg in part.args]
    try:
        return cls.from_args(args, where)
    except LaunchError as exc:
        raise exc.at(where) from None


