"""Managed (lifecycle) nodes as launch_ros drives them: a `lifecycle_node` is watched for its
state transitions (each one a StateTransition event, for OnStateTransition handlers), and the
launch asks it for transitions (`autostart`, or a ChangeState event emitted by the launch).

The bus side is a `Lifecycle` the command line gives the service (it subscribes to
`<node>/transition_event` and calls `<node>/change_state` from threads of its own); here the
answers come back to the loop, a failed request is reported, and the launch does not end while
one is out.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol

from launcher.errors import ExecutionError, LaunchError
from launcher.lifecycle import TRANSITIONS
from launcher.runtime.events import Event
from launcher.runtime.loop import EventLoop


class StateTransition(Event):
    """launch_ros.events.lifecycle.StateTransition: a lifecycle node went from `start_state`
    to `goal_state` (lifecycle_msgs' labels: unconfigured, inactive, active, finalized, …).
    `action` is its lifecycle_node action, `node` its fully qualified name; `msg` (the
    TransitionEvent message) is not kept: the labels are what handlers read."""

    name = "launch_ros.events.lifecycle.StateTransition"

    def __init__(self, *, action: Any, msg: Any = None, node: str = "",
                 start_state: str = "", goal_state: str = "") -> None:
        self.action, self.msg, self.node = action, msg, node
        self.start_state, self.goal_state = start_state, goal_state

    @property
    def transition(self) -> str:
        """The transition's label (configure, on_configure_success, …), as the message has
        it."""
        return "" if self.msg is None else self.msg.transition.label


Done = Callable[[str], None]  # "" when the transition succeeded, else why not


class Lifecycle(Protocol):
    def watch(self, node: str, seen: Callable[..., None]) -> None:
        """Call `seen(start_label, goal_label, message)` (from any thread) for each transition
        `node` makes from now on (`message`: its TransitionEvent)."""

    def change_state(self, node: str, transition: int, done: Done) -> None:
        """Ask `node` for a transition, waiting for its service; `done` from any thread."""

    def close(self) -> None:
        """Leave the bus; the launch has ended."""


class LifecycleRequests:
    def __init__(self, loop: EventLoop, lifecycle: Lifecycle | None,
                 emit: Callable[[Any], None], log: Callable[[str, str, str], None],
                 report: Callable[[LaunchError], None], answered: Callable[[], None]) -> None:
        self.loop, self.lifecycle, self.emit = loop, lifecycle, emit
        self.log, self.report, self.answered = log, report, answered
        self.out = 0
        self.cancelled = False

    def _bus(self) -> Lifecycle:
        if self.lifecycle is None:
            raise ExecutionError("lifecycle nodes need the bus, which this run lacks (run it "
                                 "with `launcher launch`)")
        self.loop.open_posting()
        return self.lifecycle

    def watch(self, node: str, origin: Any) -> None:
        def seen(start: str, goal: str, message: Any = None) -> None:  # a bus thread
            self.loop.call_soon_threadsafe(self._seen, StateTransition(
                action=origin, msg=message, node=node, start_state=start, goal_state=goal))
        self._bus().watch(node, seen)

    def _seen(self, event: StateTransition) -> None:
        self.log("INFO", "launch", f"{event.node}: {event.start_state} -> {event.goal_state}")
        self.emit(event)

    def change_states(self, node: str, transitions: list[int], where: Any) -> None:
        """The transitions one after another (autostart: configure, then activate)."""
        if not transitions or self.cancelled:
            return
        bus = self._bus()
        self.out += 1

        def done(error: str) -> None:  # a bus thread
            self.loop.call_soon_threadsafe(self._done, node, transitions, error, where)

        bus.change_state(node, transitions[0], done)

    def _done(self, node: str, transitions: list[int], error: str, where: Any) -> None:
        self.out = max(0, self.out - 1)
        known = TRANSITIONS.get(transitions[0])
        name = known.name if known else str(transitions[0])
        if error and not self.cancelled:
            self.report(ExecutionError(f"lifecycle node {node}: transition '{name}' failed: "
                                       f"{error}", where))
        elif not error:
            self.change_states(node, transitions[1:], where)
        self.answered()

    def cancel(self) -> None:
        self.cancelled = True
        self.out = 0

    def close(self) -> None:
        if self.lifecycle is not None:
            self.lifecycle.close()
