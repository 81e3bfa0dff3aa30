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
from launcher.description.actions.event_handlers import Handler, Reaction
from launcher.description.actions.node import Node
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.errors import ExecutionError
from launcher.records import dataclass
from launcher.runtime import lifecycle
from launcher.runtime.context import LaunchContext


@action("lifecycle_node")
@dataclass(kw_only=True, eq=False)
class LifecycleNode(Node):
    autostart: Any = attr(Kind.BOOL, False, doc="Configure and activate the node once it "
                                                "runs (launch_ros's, Jazzy).")

    def execute(self, context: LaunchContext) -> Any:
        if self.node_name is None:
            raise ExecutionError("lifecycle_node needs a name (launch_ros requires one)",
                                 self.where)
        done = super().execute(context)
        self.node_fqn = f"{self._namespace(context).rstrip('/')}/{self._node_name(context)}"
        context.lifecycle_nodes.append(self)
        if context.service is not None:
            context.service.watch_lifecycle(self.node_fqn, self)
            if resolve(context, self.autostart, Kind.BOOL, "autostart"):
                context.service.change_states(self.node_fqn, [
                    lifecycle.TRANSITIONS["configure"], lifecycle.TRANSITIONS["activate"]],
                    self.where)
        return done


class ChangeState:
    """launch_ros.events.lifecycle.ChangeState: ask the matching lifecycle nodes for a
    transition (lifecycle_msgs/msg/Transition's id)."""

    def __init__(self, *, lifecycle_node_matcher: Callable[[Any], bool] | None = None,
                 transition_id: int) -> None:
        self.matcher = lifecycle_node_matcher
        self.transition_id = int(transition_id)


def matches_action(target: Any) -> Callable[[Any], bool]:
    """launch.events.matches_action: this action, and no other."""
    return lambda candidate: candidate is target


class EmitEvent(Action):
    """launch.actions.EmitEvent, for the events launcher acts on: ChangeState (and Shutdown,
    which the Shutdown action is)."""

    def __init__(self, *, event: Any, condition: Any = None) -> None:
        self.event, self.condition, self.where = event, condition, None

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
        name = type(self.event).__name__
        if name == "Shutdown":
            from launcher.description.actions.shutdown import Shutdown

            return [Shutdown(reason=getattr(self.event, "reason", None))]
        raise ExecutionError(f"EmitEvent: launcher acts on ChangeState and Shutdown events, "
                             f"not {name}", self.where)


@dataclass
class OnStateTransition(Handler):
    """launch_ros.event_handlers.OnStateTransition: `entities` when the node (all lifecycle
    nodes without `target_lifecycle_node`) goes from `start_state` to `goal_state` (either
    may be left out)."""

    target_lifecycle_node: Any = None
    start_state: str | None = None
    goal_state: str | None = None
    entities: Reaction | None = None
    transition: str | None = None

    def __post_init__(self) -> None:
        self.event_type = lifecycle.StateTransition
        if self.target_action is None:
            self.target_action = self.target_lifecycle_node

    def matches(self, event: Any) -> bool:
        return super().matches(event) and \
            self.start_state in (None, event.start_state) and \
            self.goal_state in (None, event.goal_state)

    def reaction(self, event: Any) -> Reaction | None:
        return self.entities
