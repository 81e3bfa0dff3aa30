"""launch_ros's managed nodes: `lifecycle_node` (a node the launch watches through its state
transitions, configured and activated at start with `autostart`), the ChangeState event a
launch emits (`EmitEvent(event=ChangeState(lifecycle_node_matcher=…, transition_id=…))`), and
OnStateTransition handlers (actions when a node reaches a state).

The bus side is the runtime's (runtime/lifecycle.py): the node's `~/transition_event` is
watched from its start, and `~/change_state` is called for the transitions asked for.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.description.action import Action
from launcher.description.actions.event_handlers import OnActionEventBase
from launcher.description.actions.node import Node
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.errors import ExecutionError
from launcher.lifecycle import ACTIVATE, CONFIGURE
from launcher.records import dataclass
from launcher.runtime import lifecycle
from launcher.runtime.context import LaunchContext
from launcher.runtime.events import Event


@action("lifecycle_node")
@dataclass(kw_only=True, eq=False)
class LifecycleNode(Node):
    autostart: Any = attr(Kind.BOOL, False, doc="Configure and activate the node once it "
                                                "runs (launch_ros's, Jazzy).")

    def execute(self, context: LaunchContext) -> Any:
        if self.given_name is None:
            raise ExecutionError("lifecycle_node needs a name (launch_ros requires one)",
                                 self.where)
        done = super().execute(context)
        self.node_fqn = f"{self._namespace(context).rstrip('/')}/{self._node_name(context)}"
        context.lifecycle_nodes.append(self)
        if context.service is not None:
            context.service.watch_lifecycle(self.node_fqn, self)
            if resolve(context, self.autostart, Kind.BOOL, "autostart"):
                context.service.change_states(self.node_fqn, [CONFIGURE, ACTIVATE],
                                              self.where)
        return done


class ChangeState(Event):
    """launch_ros.events.lifecycle.ChangeState: ask the matching lifecycle nodes for a
    transition (lifecycle_msgs/msg/Transition's id)."""

    name = "launch_ros.events.lifecycle.ChangeState"

    def __init__(self, *, lifecycle_node_matcher: Callable[[Any], bool] | None = None,
                 transition_id: int) -> None:
        self.matcher = lifecycle_node_matcher
        self.transition_id = int(transition_id)


def matches_action(target_action: Any) -> Callable[[Any], bool]:
    """launch.events.matches_action: this action, and no other."""
    return lambda candidate: candidate is target_action


class EmitEvent(Action):
    """launch.actions.EmitEvent: hand an event to the launch (Shutdown ends it, ChangeState
    drives lifecycle nodes, ShutdownProcess and SignalProcess reach their processes; every
    event reaches the handlers registered for it)."""

    def __init__(self, *, event: Any, **kwargs: Any) -> None:
        self.event, self.condition, self.where = event, kwargs.get("condition"), None

    def execute(self, context: LaunchContext) -> Any:
        if isinstance(self.event, ChangeState):
            targets = [n for n in context.lifecycle_nodes
                       if self.event.matcher is None or self.event.matcher(n)]
            if not targets:
                context.log("WARN", "EmitEvent(ChangeState): no lifecycle node matches "
                                    "(started ones: "
                            f"{', '.join(n.node_fqn for n in context.lifecycle_nodes) or 'none'})")
            for target in targets:
                context.service.change_states(  # type: ignore[union-attr]
                    target.node_fqn, [self.event.transition_id], self.where)
            return None
        if not isinstance(self.event, Event):
            raise ExecutionError(f"EmitEvent(event=...): expected an event (launch.events…), "
                                 f"got {type(self.event).__name__}", self.where)
        context.emit_event(self.event)
        return None


class OnStateTransition(OnActionEventBase):
    """launch_ros.event_handlers.OnStateTransition: `entities` when the node (all lifecycle
    nodes without `target_lifecycle_node`) goes from `start_state` to `goal_state` (either
    may be left out), or makes the `transition` ('configure' …) named."""

    def __init__(self, *, target_lifecycle_node: Any = None, transition: str | None = None,
                 start_state: str | None = None, goal_state: str | None = None,
                 entities: Any = None, matcher: Callable[[Any], bool] | None = None,
                 **kwargs: Any) -> None:
        super().__init__(action_matcher=target_lifecycle_node, on_event=entities,
                         target_event_cls=lifecycle.StateTransition,
                         target_action_cls=LifecycleNode, **kwargs)
        self.target_lifecycle_node = target_lifecycle_node
        self.start_state, self.goal_state, self.transition = start_state, goal_state, transition
        self.extra_matcher = matcher

    def matches(self, event: Any) -> bool:
        return super().matches(event) and \
            self.start_state in (None, event.start_state) and \
            self.goal_state in (None, event.goal_state) and \
            self.transition in (None, event.transition) and \
            (self.extra_matcher is None or bool(self.extra_matcher(event)))
