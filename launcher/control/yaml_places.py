"""Where a node's block is in ROS parameter files (file:line), for messages about it, and the
`params_file` values spawner gives the manager (a path, a list, or a list written as text).
Places keeps what a controller needs to find its own settings there."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Places:
    """Where a node's settings are in its parameter files: its block (`file:line`, found
    once), and a key or a value, found when a message asks for one."""

    files: tuple[str, ...] = ()
    node: str = ""
    namespace: str = "/"
    block: str = ""

    @classmethod
    def find(cls, files: list[str], node: str, namespace: str = "/") -> Places:
        return cls(tuple(files), node, namespace, block_place(files, node, namespace))

    def key(self, dotted: str) -> str:
        """`file:line` of parameter `dotted` (key_place), or ""."""
        return key_place(list(self.files), self.node, dotted)

    def value(self, wanted: list[str]) -> str:
        """`file:line:column` of the first of `wanted` written as a value (value_place), or
        ""."""
        return value_place(list(self.files), self.node, wanted, self.namespace)


def block_place(files: list[str], node: str, namespace: str = "/") -> str:
    """`file:line` of the first block of the files for node `node` (by the keys ROS matches:
    `node`, `/ns/node`, `/**/node`, under `/**`), or ""."""
    import yaml

    full = f"{namespace.rstrip('/')}/{node}"
    keys = {node, full, f"/**/{node}", f"/**{full}"}
    for path, root in _composed(files):
        if not isinstance(root, yaml.MappingNode):
            continue
        for key, value in root.value:
            if key.value in keys:
                return f"{path}:{key.start_mark.line + 1}"
            if key.value == "/**" and isinstance(value, yaml.MappingNode):
                for inner, _ in value.value:
                    if inner.value in keys:
                        return f"{path}:{inner.start_mark.line + 1}"
    return ""


def value_place(files: list[str], node: str, wanted: list[str], namespace: str = "/") -> str:
    """`file:line:column` of the first of `wanted` (tried in order) written as a value in
    node `node`'s block of the files: a joint in `joints:`, an interface in
    `interface_name:`; or ""."""
    import yaml

    full = f"{namespace.rstrip('/')}/{node}"
    keys = {node, full, f"/**/{node}", f"/**{full}"}
    blocks = []
    for path, root in _composed(files):
        if not isinstance(root, yaml.MappingNode):
            continue
        for key, value in root.value:
            if key.value in keys:
                blocks.append((path, value))
            elif key.value == "/**" and isinstance(value, yaml.MappingNode):
                blocks += [(path, inner_value) for inner, inner_value in value.value
                           if inner.value in keys]
    for text in wanted:
        for path, block in blocks:
            found = _scalar(block, text)
            if found is not None:
                return f"{path}:{found.start_mark.line + 1}:{found.start_mark.column + 1}"
    return ""


def _scalar(node: Any, text: str) -> Any:
    """The first scalar value (not a key) of the tree equal to `text`, or None."""
    import yaml

    if isinstance(node, yaml.ScalarNode):
        return node if node.value == text else None
    children = [value for _, value in node.value] if isinstance(node, yaml.MappingNode) else \
        node.value if isinstance(node, yaml.SequenceNode) else []
    for child in children:
        found = _scalar(child, text)
        if found is not None:
            return found
    return None


def key_place(files: list[str], node: str, dotted: str) -> str:
    """`file:line` of `node: ros__parameters: a: b:` for dotted name `a.b`, or ""."""
    parts = dotted.split(".")
    for path, root in _composed(files):
        parent = _descend(root, [node, "ros__parameters", *parts[:-1]]) or \
            _descend(root, [f"/{node}", "ros__parameters", *parts[:-1]])
        key = _key(parent, parts[-1])
        if key is not None:
            return f"{path}:{key.start_mark.line + 1}"
    return ""


def _key(node: Any, name: str) -> Any:
    """The key `name` of a mapping node (its line is the key's, not its value's)."""
    import yaml

    if not isinstance(node, yaml.MappingNode):
        return None
    return next((key for key, _ in node.value if key.value == name), None)


def _composed(files: list[str]) -> Iterator[tuple[str, Any]]:
    """Each file's YAML node tree (with its lines), skipping one that cannot be read."""
    import yaml

    for path in files:
        try:
            with open(path, encoding="utf-8") as stream:
                yield path, yaml.compose(stream)
        except (OSError, yaml.YAMLError):
            continue


def _descend(node: Any, path: list[str]) -> Any:
    import yaml

    for part in path:
        if not isinstance(node, yaml.MappingNode):
            return None
        for key, value in node.value:
            if key.value == part:
                node = value
                break
            if part.count(".") == 0 and key.value.startswith(part + "."):
                continue
        else:
            return None
    return node


def params_files(value: Any) -> list[str]:
    """A `<controller>.params_file` value as paths: spawner sets it to a list written as text
    (`['/a.yaml']`), users to a path or a list."""
    if value is None or value == "":
        return []
    if isinstance(value, list | tuple):
        return [str(v) for v in value]
    text = str(value).strip()
    if text.startswith("["):
        import yaml

        try:
            loaded = yaml.safe_load(text)
        except yaml.YAMLError:
            return [text]
        if isinstance(loaded, list):
            return [str(v) for v in loaded]
    return [text]
