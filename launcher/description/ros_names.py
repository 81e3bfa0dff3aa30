"""ROS 2's rules for node names and namespaces (rmw's validate_node_name and
validate_namespace), checked when a node is launched, with the rule in the error.

A node name: letters, digits and '_', not starting with a digit, at most 255 characters. A
namespace: '/' or '/'-separated tokens of the same characters, not starting with a digit,
no empty token (no '//' or trailing '/'). A relative namespace is made absolute before the
check, as launch_ros does.
"""

from __future__ import annotations

import re
from typing import Any

from launcher.errors import ExecutionError

_TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
MAX_NODE_NAME = 255


def check_node_name(name: str, where: Any = None) -> None:
    if _TOKEN.fullmatch(name) and len(name) <= MAX_NODE_NAME:
        return
    raise ExecutionError(f"node name '{name}' is not valid in ROS 2: {_why_not(name)}; "
                         f"expected letters, digits and '_', not starting with a digit"
                         f"{_fixed(name)}", where)


def check_namespace(space: str, where: Any = None) -> None:
    if not space or space == "/":
        return
    tokens = space.split("/")[1:] if space.startswith("/") else space.split("/")
    for token in tokens:
        if not _TOKEN.fullmatch(token):
            what = "an empty part ('//' or a trailing '/')" if not token else \
                f"the part '{token}': {_why_not(token)}"
            raise ExecutionError(f"namespace '{space}' is not valid in ROS 2: {what}; "
                                 f"expected '/'-separated names of letters, digits and '_', "
                                 f"none starting with a digit", where)


def _why_not(name: str) -> str:
    if not name:
        return "it is empty"
    if name[0].isdigit():
        return "it starts with a digit"
    if len(name) > MAX_NODE_NAME:
        return f"it is longer than {MAX_NODE_NAME} characters"
    bad = sorted({c for c in name if not (c.isascii() and (c.isalnum() or c == "_"))})
    return f"it holds {', '.join(repr(c) for c in bad)}"


def _fixed(name: str) -> str:
    fixed = re.sub(r"[^A-Za-z0-9_]", "_", name)
    if fixed and fixed[0].isdigit():
        fixed = f"_{fixed}"
    return f" (did you mean '{fixed}'?)" if fixed and fixed != name else ""
