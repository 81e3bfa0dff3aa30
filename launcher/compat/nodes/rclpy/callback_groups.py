"""rclpy.callback_groups: which callbacks may run at the same time (MultiThreadedExecutor)."""

from __future__ import annotations

import threading
from typing import Any


class CallbackGroup:
    def __init__(self) -> None:
        self.entities: list[Any] = []

    def add_entity(self, entity: Any) -> None:
        """Make `entity` (a subscription, timer, …) one of the group's."""
        self.entities.append(entity)

    def has_entity(self, entity: Any) -> bool:
        """Whether `entity` is one of the group's."""
        return entity in self.entities

    def can_execute(self, entity: Any) -> bool:
        """Whether `entity`'s callback may start now."""
        raise NotImplementedError

    def beginning_execution(self, entity: Any) -> bool:
        """Take the group for `entity`'s callback; False if it may
        not run now.
        """
        raise NotImplementedError

    def ending_execution(self, entity: Any) -> None:
        """Give the group back after `entity`'s callback."""
        raise NotImplementedError


class ReentrantCallbackGroup(CallbackGroup):
    """Its callbacks may run in parallel."""

    def can_execute(self, entity: Any) -> bool:
        """True: any number run at once."""
        return True

    def beginning_execution(self, entity: Any) -> bool:
        """True: any number run at once."""
        return True

    def ending_execution(self, entity: Any) -> None:
        """Nothing to give back."""
        pass


class MutuallyExclusiveCallbackGroup(CallbackGroup):
    """One of its callbacks at a time (a callback that spins the executor itself may still
    run another of its group: reentry on one thread does not deadlock, as it does in rclpy)."""

    def __init__(self) -> None:
        super().__init__()
        self._lock = threading.RLock()

    def can_execute(self, entity: Any) -> bool:
        """Whether none of the group's callbacks runs now."""
        if self._lock.acquire(blocking=False):
            self._lock.release()
            return True
        return False

    def beginning_execution(self, entity: Any) -> bool:
        """Take the group; False while another of
        its callbacks runs.
        """
        return self._lock.acquire(blocking=False)

    def ending_execution(self, entity: Any) -> None:
        """Give the group back."""
        self._lock.release()

    def run(self, callback: Any, *args: Any) -> Any:
        """Run `callback(*args)` holding the group."""
        with self._lock:
            return callback(*args)


def is_custom(group: Any) -> bool:
    """A group of the program's own: neither of rclpy's two."""
    return group is not None and \
        not isinstance(group, ReentrantCallbackGroup | MutuallyExclusiveCallbackGroup)
