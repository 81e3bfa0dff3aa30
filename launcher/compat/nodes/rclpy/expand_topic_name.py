"""rclpy.expand_topic_name: rcl's expansion of `~`, `{node}`, `{ns}` and relative names."""

from __future__ import annotations

from rclpy import name_rules


def expand_topic_name(topic_name: str, node_name: str, node_namespace: str) -> str:
    """The fully qualified name of `topic_name` for the node `node_name` in `node_namespace`
    (the result may still be invalid: validate_full_topic_name tells); ValueError when the
    topic name, node name or namespace is invalid."""
    for fault in (name_rules.topic_name(topic_name), name_rules.node_name(node_name),
                  name_rules.full_topic_name(node_namespace, "namespace")):
        if fault is not None:
            raise ValueError(f"{fault[0]}, at index {fault[1]}")
    namespace = node_namespace.rstrip("/")
    name = topic_name
    if name.startswith("~"):
        name = f"{namespace}/{node_name}{name[1:]}"
    for key, value in (("{node}", node_name), ("{ns}", namespace or "/"),
                       ("{namespace}", namespace or "/")):
        name = name.replace(key, value)
    if "{" in name:
        raise ValueError(f"unknown substitution in topic name '{topic_name}'")
    if not name.startswith("/"):
        name = f"{namespace}/{name}"
    return name.replace("//", "/")
