"""actionlib.action_server: what launcher's actionlib gives of it so far (goal ids, the
do-nothing callback). launcher's actionlib gives SimpleActionServer
(simple_action_server.py), not yet the goal-handle API (ActionServer, ServerGoalHandle)."""

from __future__ import annotations

from typing import Any

from actionlib.exceptions import ActionException  # noqa: F401 (action_server has them)
from actionlib.goal_id_generator import GoalIDGenerator  # noqa: F401


def nop_cb(goal_handle: Any) -> None:
    """A goal or cancel callback that does nothing (ActionServer's default)."""
