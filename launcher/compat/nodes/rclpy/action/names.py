"""The names and types of an action's services and topics (rcl_action's), and goal status."""

from __future__ import annotations

from typing import Any

SEND_GOAL, CANCEL_GOAL, GET_RESULT = "send_goal", "cancel_goal", "get_result"
FEEDBACK, STATUS = "feedback", "status"
CANCEL_TYPE = "action_msgs/srv/CancelGoal"
STATUS_TYPE = "action_msgs/msg/GoalStatusArray"

# action_msgs/msg/GoalStatus
UNKNOWN, ACCEPTED, EXECUTING, CANCELING, SUCCEEDED, CANCELED, ABORTED = range(7)
STATE_NAMES = {UNKNOWN: "UNKNOWN", ACCEPTED: "ACCEPTED", EXECUTING: "EXECUTING",
               CANCELING: "CANCELING", SUCCEEDED: "SUCCEEDED", CANCELED: "CANCELED",
               ABORTED: "ABORTED"}
TERMINAL = (SUCCEEDED, CANCELED, ABORTED)


def endpoint(action_name: str, part: str) -> str:
    return f"{action_name}/_action/{part}"


def action_type_name(action_type: Any) -> str:
    """`pkg/action/Name` of an action class (or of its name given as text)."""
    from launcher.compat import rosidl

    name = rosidl.type_name_of(action_type)
    if name.split("/")[1:2] != ["action"]:
        raise TypeError(f"expected an action type, got {name}")
    rosidl.action_class(name)
    return name


def uuid_key(goal_id: Any) -> bytes:
    """A goal id (unique_identifier_msgs/UUID) as a dict key."""
    return bytes(goal_id.uuid)


def uuid_text(goal_id: Any) -> str:
    """As rclpy prints a goal id in its logs."""
    return str(list(bytes(goal_id.uuid)))
