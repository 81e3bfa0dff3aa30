"""rclpy.waitable: the base of user-defined waitables and the count of what they wait on.
launcher's executors wake on their nodes' bus work, not on an rcl wait set, so they do not run
custom waitables (Node.add_waitable says so); the class is here for code that subclasses it."""

from __future__ import annotations

from typing import Any


class NumberOfEntities:
    """How many of each kind of entity a waitable uses."""

    __slots__ = ("num_subscriptions", "num_guard_conditions", "num_timers", "num_clients",
                 "num_services", "num_events")

    def __init__(self, num_subs: int = 0, num_gcs: int = 0, num_timers: int = 0,
                 num_clients: int = 0, num_services: int = 0, num_events: int = 0) -> None:
        self.num_subscriptions, self.num_guard_conditions = num_subs, num_gcs
        self.num_timers, self.num_clients = num_timers, num_clients
        self.num_services, self.num_events = num_services, num_events

    def __add__(self, other: NumberOfEntities) -> NumberOfEntities:
        return NumberOfEntities(*(getattr(self, s) + getattr(other, s) for s in self.__slots__))

    def __iadd__(self, other: NumberOfEntities) -> NumberOfEntities:
        for slot in self.__slots__:
            setattr(self, slot, getattr(self, slot) + getattr(other, slot))
        return self

    def __repr__(self) -> str:
        counts = ", ".join(str(getattr(self, s)) for s in self.__slots__)
        return f"<{type(self).__name__}({counts})>"


class Waitable:
    """Something an executor adds to a wait set and executes when it is ready (subclasses
    implement the methods that raise NotImplementedError)."""

    def __init__(self, callback_group: Any) -> None:
        self.callback_group = callback_group
        self.callback_group.add_entity(self)
        self._executor_event = False
        self._futures: list[Any] = []

    def __enter__(self) -> Any:
        raise NotImplementedError("Must be implemented by subclass")

    def __exit__(self, *exc: Any) -> None:
        raise NotImplementedError("Must be implemented by subclass")

    def add_future(self, future: Any) -> None:
        """Keep a future whose callbacks need executing."""
        self._futures.append(future)

    def remove_future(self, future: Any) -> None:
        """Forget a future add_future kept."""
        self._futures.remove(future)

    def is_ready(self, wait_set: Any) -> bool:
        """Whether the entities are ready in the wait set."""
        raise NotImplementedError("Must be implemented by subclass")

    def take_data(self) -> Any:
        """Take what is ready, so the wait set does not wake again at once."""
        raise NotImplementedError("Must be implemented by subclass")

    async def execute(self, taken_data: Any) -> None:
        """Do the work for what take_data took."""
        raise NotImplementedError("Must be implemented by subclass")

    def get_num_entities(self) -> NumberOfEntities:
        """How many of each kind of entity this waitable uses."""
        raise NotImplementedError("Must be implemented by subclass")

    def add_to_wait_set(self, wait_set: Any) -> None:
        """Add the entities to a wait set."""
        raise NotImplementedError("Must be implemented by subclass")
