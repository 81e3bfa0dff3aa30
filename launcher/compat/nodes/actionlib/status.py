"""actionlib_msgs/GoalStatus's states, the moves between them as actionlib's server goal
handles make them (a table of launcher's one kind of state machine, bus/actions.py), and the
action's message classes."""

import enum

from launcher.bus.actions import StateMachine

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


def message_types(action_spec: object) -> dict[str, type]:
    """{part: class} of an action's ROS 1 messages, from its `<X>Action` class."""
    import importlib

    module_name = action_spec.__module__
    base = action_spec.__name__.removesuffix("Action")
    module = importlib.import_module(module_name)
    return {part: getattr(module, f"{base}{part}")
            for part in ("ActionGoal", "ActionResult", "ActionFeedback", "Goal", "Result",
                         "Feedback")}
