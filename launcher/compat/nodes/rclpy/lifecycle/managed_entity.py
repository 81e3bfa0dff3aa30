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
    """A callback per transition of a lifecycle node, which a subclass overrides: an entity
    the node manages is told of each; the node itself (LifecycleNodeMixin is one) does the
    transition's work there. Each returns TransitionCallbackReturn SUCCESS, FAILURE or ERROR;
    by default an entity's SUCCESS, and a node's its managed entities' (the first that is not
    SUCCESS)."""

    def on_configure(self, state: Any) -> Any:
        """The `configure` transition's work; SUCCESS by default."""
        return self._by_default("on_configure", state)

    def on_cleanup(self, state: Any) -> Any:
        """The `cleanup` transition's work; SUCCESS by default."""
        return self._by_default("on_cleanup", state)

    def on_shutdown(self, state: Any) -> Any:
        """The `shutdown` transition's work; SUCCESS by default."""
        return self._by_default("on_shutdown", state)

    def on_activate(self, state: Any) -> Any:
        """The `activate` transition's work; SUCCESS by default."""
        return self._by_default("on_activate", state)

    def on_deactivate(self, state: Any) -> Any:
        """The `deactivate` transition's work; SUCCESS by default."""
        return self._by_default("on_deactivate", state)

    def on_error(self, state: Any) -> Any:
        """The `error` transition's work; SUCCESS by default."""
        return self._by_default("on_error", state)

    def _by_default(self, callback: str, state: Any) -> Any:
        """What `callback` does unless overridden (a lifecycle node asks its entities)."""
        return TransitionCallbackReturn.SUCCESS


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
