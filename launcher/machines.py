"""State machines as tables: a state and an event give the next state, and a move the table
does not have is refused. rcl_action's goals (bus/actions.py), ROS 1 actionlib's
(compat/nodes/actionlib/status.py) and ROS 2 managed nodes' lifecycle (lifecycle.py) are each
one table of this kind."""

from __future__ import annotations

from typing import Any

# (rcl_action's words: goals, of either ROS, are what most tables here move)
GOAL_REFUSAL = ("Failed to update goal state: goal_handle attempted invalid transition from "
                "state {state} with event {event}")


class InvalidTransition(RuntimeError):
    """A move the state machine does not have (rclpy raises it as its RCLError)."""


class StateMachine:
    """`transitions`: (state, event) → the next state; `names`: each state's name, for the
    refusal (a format of `state` and `event`: the event's name where it has one, an enum
    member's, else the event itself)."""

    def __init__(self, transitions: dict[tuple[int, Any], int], names: dict[int, str],
                 refusal: str = GOAL_REFUSAL) -> None:
        self.transitions, self.names, self.refusal = transitions, names, refusal

    def move(self, state: int, event: Any) -> int:
        """The state after `event`; InvalidTransition (with the table's refusal) if the
        machine has no such move."""
        new = self.transitions.get((state, event))
        if new is None:
            raise InvalidTransition(self.refusal.format(
                state=self.names[state], event=getattr(event, "name", event)))
        return new

    def allows(self, state: int, event: Any) -> bool:
        return (state, event) in self.transitions
