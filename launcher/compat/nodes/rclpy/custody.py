"""What a node holds of its own, apart from rclpy's Node: whether it lives, the bus node under it
(whose host queues its work), the entities it destroys with itself and the callback groups
their callbacks run in.

The rest of this rclpy asks a node for these here (executors, clients, action servers and
clients), so that the modules rclpy.node stands on reach a node without importing it; the
Node makes its Custody at its start and keeps it in one private attribute, as rclpy's keeps
its own in private ones.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

from rclpy.callback_groups import CallbackGroup, MutuallyExclusiveCallbackGroup, is_custom
from rclpy.exceptions import InvalidHandle


class Custody:
    def __init__(self, node: Any, bus: Any, default_group: CallbackGroup) -> None:
        self.bus, self.alive = bus, True
        self.entities: list[Any] = []
        self.groups: list[CallbackGroup] = [default_group]
        node._custody = self

    def check_alive(self) -> None:
        """rclpy's InvalidHandle once the node is destroyed."""
        if not self.alive:
            raise InvalidHandle("cannot use Destroyable because destruction was requested")

    def live_host(self) -> Any:
        """The bus host that queues the node's work; None once the node is destroyed."""
        return self.bus.host if self.alive else None

    def grouped(self, group: CallbackGroup, callback: Callable[..., Any],
                entity: Callable[[], Any]) -> Callable[..., Any]:
        """The callback as its group runs it: under the group's lock if mutually exclusive;
        a group of the program's own (rclpy's CallbackGroup subclassed) is asked, as rclpy's
        executor asks it, beginning_execution(entity) before (False: it does not run) and
        told ending_execution(entity) after; its can_execute holds a timer back
        (Executor._next_work)."""
        if group not in self.groups:
            self.groups.append(group)
        if isinstance(group, MutuallyExclusiveCallbackGroup):
            return functools.partial(group.run, callback)
        if is_custom(group):
            def asked(*args: Any) -> Any:
                who = entity()
                if not group.beginning_execution(who):
                    return None
                try:
                    return callback(*args)
                finally:
                    group.ending_execution(who)
            return asked
        return callback


def check_alive(node: Any) -> None:
    """rclpy's InvalidHandle once the node is destroyed."""
    node._custody.check_alive()


def live_host(node: Any) -> Any:
    """The bus host that queues the node's work; None once the node is destroyed."""
    return node._custody.live_host()


def caught_up(node: Any) -> None:
    """The executor has nothing left to do for the node (a sim in lockstep is told so)."""
    custody = node._custody
    if custody.alive:
        custody.bus.get_clock().caught_up()


def grouped(node: Any, group: CallbackGroup | None, callback: Callable[..., Any],
            entity: Callable[[], Any] = lambda: None) -> Callable[..., Any]:
    """`callback` as `group` (None: the node's default) runs it; see Custody.grouped."""
    return node._custody.grouped(group or node.default_callback_group, callback, entity)


def adopt(node: Any, entity: Any) -> None:
    """An entity made outside the node (an action server or client) that it destroys with
    itself."""
    node._custody.entities.append(entity)


def forget(node: Any, entity: Any) -> None:
    """The entity, destroyed by itself, is no longer the node's."""
    entities = node._custody.entities
    if entity in entities:
        entities.remove(entity)
