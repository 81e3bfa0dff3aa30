"""actionlib_msgs/GoalStatus's states, the moves between them as actionlib's server goal
handles make them (a table of launcher's one kind of state machine, machines.py), the
action's message classes, and how actionlib reads its timeouts and queue size parameters."""

from __future__ import annotations

import enum
from typing import Any

from actionlib.exceptions import ActionException
from launcher.machines import StateMachine

PENDING, ACTIVE, PREEMPTED, SUCCEEDED, ABORTED, REJECTED, PREEMPTING, RECALLING, RECALLED, \
    LOST = range(10)
TERMINAL = (PREEMPTED, SUCCEEDED, ABORTED, REJECTED, RECALLED, LOST)
NAMES = {PENDING: "PENDING", ACTIVE: "ACTIVE", PREEMPTED: "PREEMPTED", SUCCEEDED: "SUCCEEDED",
         ABORTED: "ABORTED", REJECTED: "REJECTED", PREEMPTING: "PREEMPTING",
         RECALLING: "RECALLING", RECALLED: "RECALLED", LOST: "LOST"}

Event = enum.Enum("Event", "ACCEPT REJECT CANCEL_REQUEST CANCEL SUCCEED ABORT")
MACHINE = StateMachine({
    (PENDING, Event.ACCEPT): ACTIVE, (PENDING, Event.REJECT): REJECTED,
    (PENDING, Event.CANCEL_REQUEST): RECALLING, (PENDING, Event.CANCEL): RECALLED,
    (RECALLING, Event.ACCEPT): PREEMPTING, (RECALLING, Event.REJECT): REJECTED,
    (RECALLING, Event.CANCEL): RECALLED,
    (ACTIVE, Event.CANCEL_REQUEST): PREEMPTING, (ACTIVE, Event.CANCEL): PREEMPTED,
    (ACTIVE, Event.SUCCEED): SUCCEEDED, (ACTIVE, Event.ABORT): ABORTED,
    (PREEMPTING, Event.CANCEL): PREEMPTED, (PREEMPTING, Event.SUCCEED): SUCCEEDED,
    (PREEMPTING, Event.ABORT): ABORTED,
}, NAMES)


def message_types(action_spec: Any) -> dict[str, type]:
    """{part: class} of an action's ROS 1 messages, read off an instance of its `<X>Action`
    class as actionlib reads them (ActionException if it is not one)."""
    try:
        action = action_spec()
        parts = {"ActionGoal": action.action_goal, "ActionResult": action.action_result,
                 "ActionFeedback": action.action_feedback, "Goal": action.action_goal.goal,
                 "Result": action.action_result.result,
                 "Feedback": action.action_feedback.feedback}
    except (AttributeError, TypeError):
        raise ActionException(f"Type is not an action spec: {action_spec}") from None
    return {part: type(message) for part, message in parts.items()}


def seconds(timeout: Any) -> float:
    """A timeout given as a Duration or a number of seconds (None: 0)."""
    if timeout is None:
        return 0.0
    return float(timeout.to_sec()) if hasattr(timeout, "to_sec") else float(timeout)


def queue_size(value: int, default: int | None) -> int | None:
    """A queue size parameter's value (a negative one means the default)."""
    return default if value < 0 else value
