"""actionlib.goal_id_generator: unique goal ids, `<node name>-<count>-<secs>.<nsecs>`."""

from __future__ import annotations

import threading

import rospy
from actionlib_msgs.msg import GoalID

s_goalcount = 0  # goals numbered so far in this process
_lock = threading.Lock()


class GoalIDGenerator:
    def __init__(self, name: str | None = None) -> None:
        """`name` (default: the node's name) begins each id."""
        self.set_name(rospy.get_name() if name is None else name)

    def set_name(self, name: str) -> None:
        self.name = name

    def generate_ID(self) -> GoalID:  # noqa: N802 (actionlib's name)
        """A new GoalID, stamped now."""
        global s_goalcount
        now = rospy.Time.now()
        with _lock:
            s_goalcount += 1
            count = s_goalcount
        return GoalID(stamp=now, id=f"{self.name}-{count}-{now.secs}.{now.nsecs}")
