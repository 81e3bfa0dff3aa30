"""rclpy.lifecycle's node: rcl_lifecycle's state machine with the user's on_configure,
on_activate, … callbacks, its services (`~/get_state`, `~/change_state`,
`~/get_available_states`, `~/get_available_transitions`, `~/get_transition_graph`) and
`~/transition_event`, over launcher's one table of the states and transitions
(launcher/lifecycle.py). A transition that is not allowed from the current state is refused
(ChangeState's `success` false) and logged with the transitions that are."""

from __future__ import annotations

import threading
import time
from typing import Any, NoReturn, TypedDict

from launcher.lifecycle import (
    ACTIVATE,
    CLEANUP,
    CONFIGURE,
    DEACTIVATE,
    ERRORPROCESSING,
    LABELS,
    MACHINE,
    TRANSITIONS,
    UNCONFIGURED,
    UNCONFIGURED_SHUTDOWN,
    Transition,
    allowed,
    labelled,
)
from rclpy.callback_groups import CallbackGroup  # noqa: F401 - the names rclpy's module offers
from rclpy.lifecycle.managed_entity import ManagedEntity, TransitionCallbackReturn
from rclpy.lifecycle.publisher import LifecyclePublisher
from rclpy.logging import RcutilsLogger  # noqa: F401
from rclpy.node import Node
from rclpy.qos import QoSProfile, qos_profile_services_default  # noqa: F401
from rclpy.service import Service  # noqa: F401
from rclpy.type_support import check_is_valid_srv_type  # noqa: F401


class LifecycleState:
    def __init__(self, label: str, state_id: int) -> None:
        self.label, self.state_id = label, state_id

    def __repr__(self) -> str:
        return f"LifecycleState(label='{self.label}', state_id={self.state_id})"


class LifecycleNodeArgs(TypedDict, total=False):
    """LifecycleNode's keywords besides Node's."""

    enable_communication_interface: bool


class CreateLifecyclePublisherArgs(TypedDict, total=False):
    """create_lifecycle_publisher's keywords."""

    callback_group: CallbackGroup | None
    event_callbacks: Any
    qos_overriding_options: Any
    publisher_class: type[LifecyclePublisher]


class LifecycleNodeMixin(ManagedEntity):
    """The lifecycle state machine, its services and transition events, mixed into a Node
    (made before the mixin's __init__ runs). Its transition callbacks (on_configure, …) are
    ManagedEntity's: by default they call its managed entities' own."""

    def __init__(self, *, enable_communication_interface: bool = True,
                 callback_group: CallbackGroup | None = None) -> None:
        self._init_lifecycle(enable_communication_interface, callback_group)

    def _init_lifecycle(self, enable_communication_interface: bool = True,
                        callback_group: CallbackGroup | None = None) -> None:
        from lifecycle_msgs.msg import TransitionEvent
        from lifecycle_msgs.srv import (
            ChangeState,
            GetAvailableStates,
            GetAvailableTransitions,
            GetState,
        )

        self._state_id = UNCONFIGURED
        self._managed_entities: set[ManagedEntity] = set()
        self._transition_lock = threading.RLock()
        self._state_publisher = None
        if enable_communication_interface:
            self._state_publisher = self.create_publisher(  # type: ignore[attr-defined]
                TransitionEvent, "~/transition_event", 10)
            for srv, name, callback in (
                    (GetState, "~/get_state", self._on_get_state),
                    (ChangeState, "~/change_state", self._on_change_state),
                    (GetAvailableStates, "~/get_available_states", self._on_states),
                    (GetAvailableTransitions, "~/get_available_transitions",
                     self._on_transitions),
                    (GetAvailableTransitions, "~/get_transition_graph", self._on_graph)):
                self.create_service(srv, name, callback,  # type: ignore[attr-defined]
                                    qos_profile=qos_profile_services_default,
                                    callback_group=callback_group)

    # --- the callbacks users override (ManagedEntity's) -------------------------------------
    def _by_default(self, callback: str, state: Any) -> TransitionCallbackReturn:
        """The managed entities' `callback`s, up to the first that does not succeed."""
        for entity in self._managed_entities:
            outcome = getattr(entity, callback)(state)
            if outcome != TransitionCallbackReturn.SUCCESS:
                return outcome
        return TransitionCallbackReturn.SUCCESS

    def add_managed_entity(self, entity: ManagedEntity) -> None:
        """An entity (a lifecycle publisher, …) told of every transition."""
        self._managed_entities.add(entity)

    def create_lifecycle_publisher(self, *args: Any, **kwargs: Any) -> LifecyclePublisher:
        """A publisher that publishes only while the node is active
        (create_publisher's arguments).
        """
        kwargs["publisher_class"] = LifecyclePublisher
        publisher = self.create_publisher(*args, **kwargs)  # type: ignore[attr-defined]
        self._managed_entities.add(publisher)
        return publisher

    # --- transitions -----------------------------------------------------------------------
    def trigger_configure(self) -> TransitionCallbackReturn:
        """Run the configure transition now; its callback's return."""
        return self._trigger(CONFIGURE)

    def trigger_cleanup(self) -> TransitionCallbackReturn:
        """Run the cleanup transition now; its callback's return."""
        return self._trigger(CLEANUP)

    def trigger_activate(self) -> TransitionCallbackReturn:
        """Run the activate transition now; its callback's return."""
        return self._trigger(ACTIVATE)

    def trigger_deactivate(self) -> TransitionCallbackReturn:
        """Run the deactivate transition now; its callback's return."""
        return self._trigger(DEACTIVATE)

    def trigger_shutdown(self) -> TransitionCallbackReturn:
        """Run the shutdown transition now; its callback's return."""
        found = labelled(self._state_id, "shutdown")
        return self._trigger(found.id if found else UNCONFIGURED_SHUTDOWN)

    def _trigger(self, transition: int) -> TransitionCallbackReturn:
        with self._transition_lock:
            start = self._state_id
            if transition not in TRANSITIONS or not MACHINE.allows(start, transition):
                self._refuse(transition)
            through = MACHINE.move(start, transition)
            self._move(start, through)
            outcome = self._call(TRANSITIONS[transition].callback, through, start)
            goal = self._finish(through, outcome)
            if goal == ERRORPROCESSING:
                error = self._call("on_error", ERRORPROCESSING, through)
                self._finish(ERRORPROCESSING, error)
            return outcome

    def _refuse(self, transition: int) -> NoReturn:
        """Log, then raise, that `transition` is not allowed from the current state."""
        label = TRANSITIONS[transition].label if transition in TRANSITIONS else str(transition)
        state = LABELS[self._state_id]
        choices = ", ".join(f"{t.label} [{t.id}]" for t in allowed(self._state_id)) or "none"
        self.get_logger().error(  # type: ignore[attr-defined]
            f"Unable to start transition {label} [{transition}] from current state "
            f"{state}: it is not allowed there (allowed: {choices})")
        raise TransitionNotAllowed(label, state, choices)

    def _call(self, method: str, through: int, previous: int) -> TransitionCallbackReturn:
        # (rclpy hands the callback the state the transition started from)
        state = LifecycleState(LABELS[previous], previous)
        try:
            outcome = getattr(self, method)(state)
        except Exception as exc:  # an exception is an error, as rclpy has it
            self.get_logger().error(  # type: ignore[attr-defined]
                f"Caught exception in callback for transition {through}: {exc}")
            return TransitionCallbackReturn.ERROR
        if outcome not in (97, 98, 99):
            self.get_logger().error(  # type: ignore[attr-defined]
                f"{method} returned {outcome!r}: return a TransitionCallbackReturn; taken as "
                "ERROR")
            return TransitionCallbackReturn.ERROR
        return TransitionCallbackReturn(int(outcome))

    def _finish(self, through: int, outcome: int) -> int:
        goal = MACHINE.move(through, int(outcome))
        self._move(through, goal)
        return goal

    def _move(self, start: int, goal: int) -> None:
        """Enter `goal`, and say so on transition_event as rcl_lifecycle says it: the start and
        goal states (its `transition` field is left empty, id 0 and no label)."""
        self._state_id = goal
        if self._state_publisher is None:
            return
        from lifecycle_msgs.msg import State, TransitionEvent

        self._state_publisher.publish(TransitionEvent(
            timestamp=time.time_ns(),
            start_state=State(id=start, label=LABELS[start]),
            goal_state=State(id=goal, label=LABELS[goal])))

    # --- services ----------------------------------------------------------------------------
    def _on_get_state(self, request: Any, response: Any) -> Any:
        from lifecycle_msgs.msg import State

        response.current_state = State(id=self._state_id, label=LABELS[self._state_id])
        return response

    def _on_change_state(self, request: Any, response: Any) -> Any:
        transition = request.transition.id
        if transition == 0 and request.transition.label:  # by label, as ros2 lifecycle asks
            found = labelled(self._state_id, request.transition.label)
            transition = found.id if found else -1
        try:
            outcome = self._trigger(transition)
        except TransitionNotAllowed:
            response.success = False
            return response
        response.success = outcome == TransitionCallbackReturn.SUCCESS
        return response

    def _on_states(self, request: Any, response: Any) -> Any:
        from lifecycle_msgs.msg import State

        response.available_states = [State(id=i, label=label) for i, label in LABELS.items()]
        return response

    def _describe(self, transitions: list[Transition]) -> list[Any]:
        """TransitionDescriptions, each going into its transition state, as rcl lists them."""
        from lifecycle_msgs import msg

        return [msg.TransitionDescription(
            transition=msg.Transition(id=t.id, label=t.label),
            start_state=msg.State(id=t.start, label=LABELS[t.start]),
            goal_state=msg.State(id=t.through, label=LABELS[t.through]))
            for t in transitions]

    def _on_transitions(self, request: Any, response: Any) -> Any:
        response.available_transitions = self._describe(allowed(self._state_id))
        return response

    def _on_graph(self, request: Any, response: Any) -> Any:
        response.available_transitions = self._describe(list(TRANSITIONS.values()))
        return response

    @property
    def _current_state(self) -> LifecycleState:
        return LifecycleState(LABELS[self._state_id], self._state_id)


class TransitionNotAllowed(RuntimeError):
    def __init__(self, label: str, state: str, allowed: str) -> None:
        super().__init__(f"transition {label} is not allowed from state {state} (allowed: "
                         f"{allowed})")


class LifecycleNode(LifecycleNodeMixin, Node):
    def __init__(self, node_name: str, *args: Any, enable_communication_interface: bool = True,
                 **kwargs: Any) -> None:
        Node.__init__(self, node_name, *args, **kwargs)
        LifecycleNodeMixin.__init__(
            self, enable_communication_interface=enable_communication_interface)
