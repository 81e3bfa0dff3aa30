"""rmw's and rcl's rules for names, as (error message, index of the fault) or None when the
name is valid; the validate_* modules raise rclpy's exceptions from them."""

from __future__ import annotations

import re

MAX_FULL_TOPIC = 247  # rmw's longest topic name (255 less the DDS prefix)
MAX_NAMESPACE = MAX_FULL_TOPIC - 2  # room for "/x"
MAX_NODE_NAME = 255

_FULL = re.compile(r"[^A-Za-z0-9_/]")
_NODE = re.compile(r"[^A-Za-z0-9_]")
_RELATIVE = re.compile(r"[^A-Za-z0-9_/~{}]")


def full_topic_name(name: str, what: str = "topic name") -> tuple[str, int] | None:
    """rmw_validate_full_topic_name (rmw_validate_namespace when `what` is "namespace")."""
    if not name:
        return f"{what} must not be empty", 0
    if not name.startswith("/"):
        return f"{what} must be absolute, it must lead with a '/'", 0
    if len(name) > 1 and name.endswith("/"):
        return f"{what} must not end with a forward slash", len(name) - 1
    found = _FULL.search(name)
    if found:
        return (f"{what} must not contain characters other than alphanumerics, '_', or '/'",
                found.start())
    if "//" in name:
        return f"{what} must not contain repeated '/'", name.index("//") + 1
    for match in re.finditer(r"/([0-9])", name):
        return f"{what} must not have a token that starts with a number", match.start(1)
    limit = MAX_NAMESPACE if what == "namespace" else MAX_FULL_TOPIC
    if len(name) > limit:
        return f"{what} should not exceed '{limit}'", limit - 1
    return None


def node_name(name: str) -> tuple[str, int] | None:
    """rmw_validate_node_name."""
    if not name:
        return "node name must not be empty", 0
    found = _NODE.search(name)
    if found:
        return "node name must not contain characters other than alphanumerics or '_'", \
            found.start()
    if name[0].isdigit():
        return "node name must not start with a number", 0
    if len(name) > MAX_NODE_NAME:
        return f"node name should not exceed '{MAX_NODE_NAME}'", MAX_NODE_NAME - 1
    return None


def topic_name(name: str) -> tuple[str, int] | None:
    """rcl_validate_topic_name: a name before expansion (relative, `~`, `{substitutions}`)."""
    if not name:
        return "topic name must not be empty", 0
    if name[0].isdigit():
        return "topic name must not start with a number", 0
    if len(name) > 1 and name.endswith("/"):
        return "topic name must not end with a forward slash", len(name) - 1
    found = _RELATIVE.search(name)
    if found:
        return ("topic name must not contain characters other than alphanumerics, '_', '~', "
                "'{', or '}'", found.start())
    if "~" in name[1:]:
        return "'~' must only be the first character of the topic name", name.index("~", 1)
    if name.startswith("~") and len(name) > 1 and name[1] != "/":
        return "'~' must be followed by a forward slash", 1
    if "//" in name:
        return "topic name must not contain repeated '/'", name.index("//") + 1
    depth = 0
    for index, char in enumerate(name):
        depth += {"{": 1, "}": -1}.get(char, 0)
        if depth not in (0, 1):
            return "topic name must not have unmatched (unbalanced) curly braces '{}'", index
    if depth:
        return "topic name must not have unmatched (unbalanced) curly braces '{}'", len(name) - 1
    for match in re.finditer(r"/([0-9])", name):
        return "topic name must not have a token that starts with a number", match.start(1)
    return None
