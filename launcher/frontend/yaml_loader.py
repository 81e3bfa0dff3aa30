"""YAML launch files: `{launch: [{tag: {attr: value, children: [...]}}, ...]}`.

The document is *composed*, not loaded, so that every value keeps its line and column.
"""

from __future__ import annotations

import yaml

from launcher.errors import LaunchError, Location, ParseError
from launcher.frontend.entity import Attribute, Entity
from launcher.user_files import check_yaml_depth

try:  # libyaml is much faster and keeps the same marks
    from yaml import CSafeLoader as _Loader
except ImportError:  # pragma: no cover - depends on the PyYAML build
    from yaml import SafeLoader as _Loader  # type: ignore[assignment]


def _where(file: str, node: yaml.Node) -> Location:
    return Location(file, node.start_mark.line + 1, node.start_mark.column + 1)


def load_yaml(text: str, file: str) -> Entity:
    """Parse a YAML launch file into its root `launch` entity."""
    try:
        try:
            check_yaml_depth(text, file)
        except LaunchError as exc:
            raise ParseError(exc.message, exc.location) from None
        root = yaml.compose(text, Loader=_Loader)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        where = Location(file, mark.line + 1, mark.column + 1) if mark else Location(file)
        raise ParseError(f"malformed YAML: {exc.problem or exc}", where) from None
    except yaml.reader.ReaderError as exc:  # a character YAML does not allow (a NUL byte…)
        line = text.count("\n", 0, exc.position) + 1
        column = exc.position - (text.rfind("\n", 0, exc.position) + 1) + 1
        raise ParseError(f"malformed YAML: {exc.reason} (character {exc.character!r})",
                         Location(file, line, column)) from None
    except yaml.YAMLError as exc:
        raise ParseError(f"malformed YAML: {exc}", Location(file)) from None
    if root is None:
        raise ParseError("the file is empty; expected a 'launch:' root", Location(file, 1, 1))
    if not isinstance(root, yaml.MappingNode) or not root.value:
        raise ParseError("expected a single 'launch:' root key", _where(file, root))
    keys = {str(key.value): (key, body) for key, body in root.value}
    for key, _ in root.value:
        if key.value not in ROOT_KEYS:
            raise ParseError(f"the root key is '{key.value}'; expected 'launch' (and, for "
                             "launcher's extensions, 'extensions' beside it)",
                             _where(file, key))
    if "launch" not in keys or len(keys) != len(root.value):
        raise ParseError("expected a single 'launch:' root key", _where(file, root))
    key, body = keys["launch"]
    entity = Entity("launch", _where(file, key))
    entity.children = _children(file, body, "launch")
    if "extensions" in keys:
        entity.attributes["extensions"] = _extensions(file, *keys["extensions"])
    return entity


ROOT_KEYS = ("launch", "extensions")


def _extensions(file: str, key: yaml.Node, node: yaml.Node) -> Attribute:
    """`extensions: [launcher]` (or one word): the words, as XML's `extensions=` has them."""
    items = node.value if isinstance(node, yaml.SequenceNode) else [node]
    if not all(isinstance(item, yaml.ScalarNode) for item in items):
        raise ParseError("'extensions' expects a list of names: extensions: [launcher]",
                         _where(file, node))
    made = Attribute(" ".join(str(item.value) for item in items), _where(file, node))
    made.key_location = _where(file, key)
    return made


def _children(file: str, node: yaml.Node, parent: str) -> list[Entity]:
    if isinstance(node, yaml.ScalarNode) and node.value in ("", "~", "null"):
        return []
    if not isinstance(node, yaml.SequenceNode):
        raise ParseError(f"'{parent}' expects a list of tags", _where(file, node))
    return [_entity(file, item) for item in node.value]


def _entity(file: str, node: yaml.Node) -> Entity:
    if not isinstance(node, yaml.MappingNode) or len(node.value) != 1:
        keys = [k.value for k, _ in node.value] if isinstance(node, yaml.MappingNode) else []
        detail = f"got {len(keys)} keys ({', '.join(keys)})" if keys else "got something else"
        raise ParseError(
            f"each list item must be a map with exactly one key (the tag); {detail}",
            _where(file, node),
        )
    key, body = node.value[0]
    entity = Entity(str(key.value), _where(file, key))
    if isinstance(body, yaml.SequenceNode):  # `group: [...]`: the list form is the children
        entity.children = _children(file, body, entity.tag)
    elif isinstance(body, yaml.MappingNode):
        for attr_key, value in body.value:
            name = str(attr_key.value)
            if name in entity.attributes or (name == "children" and entity.children):
                raise ParseError(f"'{name}' is given twice", _where(file, attr_key))
            if name == "children":
                entity.children = _children(file, value, entity.tag)
            else:
                entity.attributes[name] = _attribute(file, name, value)
                entity.attributes[name].key_location = _where(file, attr_key)
    elif not (isinstance(body, yaml.ScalarNode) and body.value in ("", "~", "null")):
        raise ParseError(
            f"'{entity.tag}' expects a map of attributes or a list of children",
            _where(file, body),
        )
    return entity


def _attribute(file: str, name: str, node: yaml.Node) -> Attribute:
    where = _where(file, node)
    if isinstance(node, yaml.ScalarNode):
        if node.tag == "tag:yaml.org,2002:null":  # (launch_yaml refuses one too)
            raise ParseError(f"'{name}' has no value (YAML's null: nothing after the colon, "
                             "'~' or 'null'); give one, or write '' for empty text", where)
        text = str(node.value)
        offset = None
        if "\n" not in text and node.style in (None, "'", '"'):
            offset = 0 if node.style is None else 1
            if node.style == '"' and "\\" in text:
                offset = None
        return Attribute(text, where, offset, string=node.tag == "tag:yaml.org,2002:str")
    if isinstance(node, yaml.SequenceNode):
        items = []
        for item in node.value:
            if _is_action(item):  # `on_exit: [{log: {message: …}}]`
                items.append(_entity(file, item))
            elif isinstance(item, yaml.MappingNode):
                nested = Entity(name, _where(file, item))
                for k, v in item.value:
                    nested.attributes[str(k.value)] = _attribute(file, str(k.value), v)
                    nested.attributes[str(k.value)].key_location = _where(file, k)
                items.append(nested)
            elif isinstance(item, yaml.ScalarNode):  # `args: [a, b]` style plain lists
                nested = Entity(name, _where(file, item))
                nested.attributes["value"] = _attribute(file, "value", item)
                items.append(nested)
            else:
                raise ParseError(f"'{name}' items must be maps", _where(file, item))
        return Attribute(items, where)
    raise ParseError(f"'{name}' must be a value or a list of maps, not a map", where)


def _is_action(node: yaml.Node) -> bool:
    """A one-key map whose value is a map, a list or empty is a tag, not a record."""
    if not isinstance(node, yaml.MappingNode) or len(node.value) != 1:
        return False
    value = node.value[0][1]
    if isinstance(value, yaml.ScalarNode):
        return value.tag == "tag:yaml.org,2002:null"
    return True
