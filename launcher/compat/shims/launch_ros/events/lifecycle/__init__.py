"""launch_ros.events.lifecycle: ChangeState (ask a lifecycle node for a transition) and
StateTransition (a node made one)."""

from launcher.api import ChangeState
from launcher.runtime.lifecycle import StateTransition

__all__ = ["ChangeState", "StateTransition"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
