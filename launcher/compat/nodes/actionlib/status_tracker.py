"""actionlib.status_tracker: what an ActionServer keeps of one goal (its GoalStatus, the goal
itself, and when the goal may leave the status list)."""

from __future__ import annotations

from typing import Any

import rospy
from actionlib_msgs.msg import GoalStatus

from actionlib import status as S
from actionlib.goal_id_generator import GoalIDGenerator


class StatusTracker:
    """One goal of a server: made from its ActionGoal (`goal`), or, for a cancel request that
    came before its goal, from the id and a status (`goal_id`, `status`)."""

    def __init__(self, goal_id: Any = None, status: int | None = None,
                 goal: Any = None) -> None:
        self.goal: Any = None
        self.handle_tracker: Any = None
        # zero while the goal is live; set when it ends, the list drops it a timeout later
        self.handle_destruction_time = rospy.Time()
        self.id_generator = GoalIDGenerator()
        self.status = GoalStatus()
        if goal_id is not None:
            self.status.goal_id, self.status.status = goal_id, status
            return
        self.goal = goal
        self.status.goal_id, self.status.status = goal.goal_id, S.PENDING
        if self.status.goal_id.id == "":  # a client that sent no id gets one made here
            self.status.goal_id = self.id_generator.generate_ID()
        if self.status.goal_id.stamp.to_nsec() == 0:
            self.status.goal_id.stamp = rospy.Time.now()
