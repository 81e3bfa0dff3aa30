"""ROS 2 managed nodes' lifecycle as rcl_lifecycle keeps it, written once: lifecycle_msgs'
states and transitions, and the moves between them as one StateMachine (machines.py).

A primary transition (configure, cleanup, activate, deactivate, shutdown), asked for by id or
by label, takes a node from a primary state into a transition state (configuring, …); there the
return of its callback (SUCCESS, FAILURE, ERROR) moves it on. rclpy's LifecycleNode (compat),
the launch's lifecycle requests (runtime/lifecycle.py), ros2_control's controllers and hardware
components (control/) and `launcher control` all move by this table."""

from __future__ import annotations

from typing import NamedTuple

from launcher.machines import StateMachine

# lifecycle_msgs/msg/State's ids: the primary states, then the transition states
UNKNOWN, UNCONFIGURED, INACTIVE, ACTIVE, FINALIZED = range(5)
CONFIGURING, CLEANINGUP, SHUTTINGDOWN, ACTIVATING, DEACTIVATING, ERRORPROCESSING = range(10, 16)
LABELS = {UNKNOWN: "unknown", UNCONFIGURED: "unconfigured", INACTIVE: "inactive",
          ACTIVE: "active", FINALIZED: "finalized", CONFIGURING: "configuring",
          CLEANINGUP: "cleaningup", SHUTTINGDOWN: "shuttingdown", ACTIVATING: "activating",
          DEACTIVATING: "deactivating", ERRORPROCESSING: "errorprocessing"}
STATES = {label: state for state, label in LABELS.items()}  # a state's id by its label

# lifecycle_msgs/msg/Transition's ids of the primary transitions
CONFIGURE, CLEANUP, ACTIVATE, DEACTIVATE = 1, 2, 3, 4
UNCONFIGURED_SHUTDOWN, INACTIVE_SHUTDOWN, ACTIVE_SHUTDOWN = 5, 6, 7
# what a transition's callback returns (lifecycle_msgs' TRANSITION_CALLBACK_*)
SUCCESS, FAILURE, ERROR = 97, 98, 99


class Transition(NamedTuple):
    """A primary transition: from `start` into the transition state `through`, where the
    node's `callback` (on_configure, …) does its work."""

    id: int
    name: str  # lifecycle_msgs' constant, in lower case (TRANSITION_INACTIVE_SHUTDOWN's)
    label: str  # rcl_lifecycle's (the three shutdowns share theirs)
    start: int
    through: int
    callback: str


TRANSITIONS = {t.id: t for t in (
    Transition(CONFIGURE, "configure", "configure", UNCONFIGURED, CONFIGURING, "on_configure"),
    Transition(CLEANUP, "cleanup", "cleanup", INACTIVE, CLEANINGUP, "on_cleanup"),
    Transition(ACTIVATE, "activate", "activate", INACTIVE, ACTIVATING, "on_activate"),
    Transition(DEACTIVATE, "deactivate", "deactivate", ACTIVE, DEACTIVATING, "on_deactivate"),
    Transition(UNCONFIGURED_SHUTDOWN, "unconfigured_shutdown", "shutdown", UNCONFIGURED,
               SHUTTINGDOWN, "on_shutdown"),
    Transition(INACTIVE_SHUTDOWN, "inactive_shutdown", "shutdown", INACTIVE, SHUTTINGDOWN,
               "on_shutdown"),
    Transition(ACTIVE_SHUTDOWN, "active_shutdown", "shutdown", ACTIVE, SHUTTINGDOWN,
               "on_shutdown"),
)}
NAMED = {t.name: t.id for t in TRANSITIONS.values()}  # an id by lifecycle_msgs' name

# where a callback's SUCCESS, FAILURE and ERROR take a node from each transition state
_OUTCOMES = {
    CONFIGURING: (INACTIVE, UNCONFIGURED, ERRORPROCESSING),
    CLEANINGUP: (UNCONFIGURED, INACTIVE, ERRORPROCESSING),
    ACTIVATING: (ACTIVE, INACTIVE, ERRORPROCESSING),
    DEACTIVATING: (INACTIVE, ACTIVE, ERRORPROCESSING),
    SHUTTINGDOWN: (FINALIZED, FINALIZED, ERRORPROCESSING),
    ERRORPROCESSING: (UNCONFIGURED, FINALIZED, FINALIZED),  # on_error's own outcome
}

# the events: a primary transition's id from a primary state, a callback's return from a
# transition state (the two sets of numbers do not meet)
MACHINE = StateMachine(
    {**{(t.start, t.id): t.through for t in TRANSITIONS.values()},
     **{(through, outcome): goal for through, goals in _OUTCOMES.items()
        for outcome, goal in zip((SUCCESS, FAILURE, ERROR), goals, strict=True)}},
    LABELS, "No transition matching {event} found for current state {state}")


def allowed(state: int) -> list[Transition]:
    """The primary transitions a node in `state` may make, in id order."""
    return [t for t in TRANSITIONS.values() if MACHINE.allows(state, t.id)]


def labelled(state: int, label: str) -> Transition | None:
    """The transition `label` names from `state`, as rcl_lifecycle finds one by its label
    (shutdown: the one of the three that starts there), or None."""
    return next((t for t in allowed(state) if t.label == label), None)


def reached(state: int, transition: int) -> int:
    """The state a transition that succeeds leaves a node in (InvalidTransition if it is not
    allowed from `state`)."""
    return MACHINE.move(MACHINE.move(state, transition), SUCCESS)
