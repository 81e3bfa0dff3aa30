"""rclpy.lifecycle.managed_entity: what a lifecycle node activates and deactivates."""

from __future__ import annotations

import enum
from typing import Any


class TransitionCallbackReturn(enum.IntEnum):
    """What a transition callback returns (lifecycle_msgs' transition results)."""

    SUCCESS = 97
    FAILURE = 98
    ERROR = 99


class ManagedEntity:
    def on_configure(self, state: Any) -> Any:
        """Told of the node's `configure` transition; SUCCESS by default."""
        return TransitionCallbackReturn.SUCCESS

    def on_cleanup(self, state: Any) -> Any:
        """Told of the node's `cleanup` transition; SUCCESS by default."""
        return self.on_configure(state)

    def on_shutdown(self, state: Any) -> Any:
        """Told of the node's `shutdown` transition; SUCCESS by default."""
        return self.on_configure(state)

    def on_activate(self, state: Any) -> Any:
        """Told of the node's `activate` transition; SUCCESS by default."""
        return self.on_configure(state)

    def on_deactivate(self, state: Any) -> Any:
        """Told of the node's `deactivate` transition; SUCCESS by default."""
        return self.on_configure(state)

    def on_error(self, state: Any) -> Any:
        """Told of the node's `error` transition; SUCCESS by default."""
        return self.on_configure(state)


class SimpleManagedEntity(ManagedEntity):
    """Enabled while its node is active."""

    def __init__(self) -> None:
        self._enabled = False

    def on_activate(self, state: Any) -> Any:
        """Active from now on; SUCCESS."""
        self._enabled = True
        return super().on_activate(state)

    def on_deactivate(self, state: Any) -> Any:
        """Inactive from now on; SUCCESS."""
        self._enabled = False
        return super().on_deactivate(state)

    @property
    def is_activated(self) -> bool:
        """Whether the node is active."""
        return self._enabled
