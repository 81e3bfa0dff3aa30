"""ROS 2 names: validation, expansion (relative, absolute, `~`) and remapping."""

from __future__ import annotations

import re

from launcher.bus.tokens import hidden  # noqa: F401 - with the other rules for names
from launcher.errors import LaunchError

_TOKEN = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_NODE = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")


class InvalidName(LaunchError):
    pass


def check_node_name(name: str) -> str:
    if not _NODE.match(name):
        raise InvalidName(f"invalid node name '{name}': a node name holds letters, digits and "
                          "underscores, and does not start with a digit")
    return name


def check_namespace(namespace: str) -> str:
    if namespace in ("", "/"):
        return ""
    if not namespace.startswith("/"):
        namespace = "/" + namespace
    _check_tokens(namespace.rstrip("/"), "namespace")
    return namespace.rstrip("/")


def _check_tokens(name: str, what: str) -> None:
    if "//" in name:
        raise InvalidName(f"invalid {what} '{name}': it has an empty part ('//')")
    for token in name.strip("/").split("/"):
        if not _TOKEN.match(token):
            reason = "starts with a digit" if token[:1].isdigit() else \
                "holds a character other than letters, digits and '_'"
            raise InvalidName(f"invalid {what} '{name}': the part '{token}' {reason}")


def expand(name: str, node: str = "", namespace: str = "", what: str = "topic name") -> str:
    """The fully qualified name: `x` -> NS/x, `/x` stays, `~` -> NS/NODE, `~/x` -> NS/NODE/x."""
    if not name:
        raise InvalidName(f"invalid {what}: it is empty")
    if name.endswith("/") and name != "/":
        raise InvalidName(f"invalid {what} '{name}': it ends with '/'")
    if name.startswith("~"):
        if name not in ("~",) and not name.startswith("~/"):
            raise InvalidName(f"invalid {what} '{name}': '~' must be alone or followed by '/'")
        if not node:
            raise InvalidName(f"invalid {what} '{name}': '~' needs a node name")
        base = f"{namespace.rstrip('/')}/{node}"
        full = base + name[1:]
    elif name.startswith("/"):
        full = name
    else:
        full = f"{namespace.rstrip('/')}/{name}"
    _check_tokens(full, what)
    return full


def below(namespace: str | None) -> str:
    """What the names in `namespace` begin with (every name begins with "/")."""
    return expand(namespace).rstrip("/") + "/" if namespace else "/"


def remap(full: str, rules: list[tuple[str, str]], node: str = "", namespace: str = "") -> str:
    """The first rule whose `from` expands to `full` gives the new name (expanded)."""
    for source, target in rules:
        if source.startswith("__"):
            continue
        try:
            if expand(source, node, namespace) == full:
                return expand(target, node, namespace)
        except InvalidName:
            continue
    return full
