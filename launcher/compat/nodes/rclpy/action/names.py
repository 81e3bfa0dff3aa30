"""What rclpy's action modules add to the protocol (launcher/bus/actions.py): an action
class's type name."""

from __future__ import annotations

from typing import Any


def action_type_name(action_type: Any) -> str:
    """`pkg/action/Name` of an action class (or of its name given as text)."""
    from launcher.compat import rosidl

    name = rosidl.type_name_of(action_type)
    if name.split("/")[1:2] != ["action"]:
        raise TypeError(f"expected an action type, got {name}")
    rosidl.action_class(name)
    return name
