"""actionlib.server_goal_handle: the server's user's hold on one goal. Its moves
(accept, reject, succeed, abort, cancel) are status.MACHINE's; each end publishes the result
and the status, as actionlib's handles do."""

from __future__ import annotations

import contextlib
from typing import Any

import rospy
from actionlib_msgs.msg import GoalID, GoalStatus

from actionlib import status as S


class ServerGoalHandle:
    """Made by the ActionServer for its goal and cancel callbacks (with no arguments: a handle
    to no goal, whose moves are refused with an error)."""

    def __init__(self, status_tracker: Any = None, action_server: Any = None,
                 handle_tracker: Any = None) -> None:
        self.status_tracker = status_tracker
        self.action_server = action_server
        self.handle_tracker = handle_tracker
        self.goal = status_tracker.goal if status_tracker else None  # the ActionGoal

    def get_default_result(self) -> Any:
        """An empty *Result, sent when a goal ends with none given."""
        return self.action_server.ActionResultType()

    # --- moves ----------------------------------------------------------------------------------
    def set_accepted(self, text: str = "") -> None:
        """Start working on the goal: ACTIVE, or PREEMPTING if a cancel came first."""
        if self._move(S.Event.ACCEPT, text):
            self.action_server.publish_status()

    def set_rejected(self, result: Any = None, text: str = "") -> None:
        """Refuse the goal (it must not be accepted yet)."""
        self._end(S.Event.REJECT, result, text)

    def set_succeeded(self, result: Any = None, text: str = "") -> None:
        """End the accepted goal as succeeded, with its result."""
        self._end(S.Event.SUCCEED, result, text)

    def set_aborted(self, result: Any = None, text: str = "") -> None:
        """End the accepted goal as aborted."""
        self._end(S.Event.ABORT, result, text)

    def set_canceled(self, result: Any = None, text: str = "") -> None:
        """End the goal as canceled: RECALLED if it was not accepted, else PREEMPTED."""
        self._end(S.Event.CANCEL, result, text)

    def set_cancel_requested(self) -> bool:
        """(the server's) A cancel came: RECALLING or PREEMPTING; whether the user's cancel
        callback is to hear of it."""
        if self.goal is None:
            return False
        with self.action_server.lock:
            if not S.MACHINE.allows(self.status_tracker.status.status, S.Event.CANCEL_REQUEST):
                return False
            self._move(S.Event.CANCEL_REQUEST)
            self.action_server.publish_status()
            return True

    def _end(self, event: S.Event, result: Any, text: str) -> None:
        with self.action_server.lock if self.action_server else contextlib.nullcontext():
            if self._move(event, text):
                self.status_tracker.handle_destruction_time = rospy.Time.now()
                self.action_server.publish_result(
                    self.status_tracker.status,
                    self.get_default_result() if result is None else result)

    def _move(self, event: S.Event, text: str | None = None) -> bool:
        """Move the goal's status by `event`, with `text` if given (an error, and False, where
        it cannot move so)."""
        if self.goal is None:
            rospy.logerr("Attempt to set status on an uninitialized ServerGoalHandle")
            return False
        with self.action_server.lock:
            status = self.status_tracker.status
            if not S.MACHINE.allows(status.status, event):
                rospy.logerr(f"To {event.name.lower()} a goal it must be "
                             f"{_states_for(event)}; it is {S.NAMES[status.status]} "
                             f"(goal {status.goal_id.id})")
                return False
            status.status = S.MACHINE.move(status.status, event)
            if text is not None:
                status.text = text
            return True

    # --- what the goal is -----------------------------------------------------------------------
    def publish_feedback(self, feedback: Any) -> None:
        """Send `feedback` to the goal's clients."""
        if self.goal is None:
            rospy.logerr("Attempt to publish feedback on an uninitialized ServerGoalHandle")
            return
        with self.action_server.lock:
            self.action_server.publish_feedback(self.status_tracker.status, feedback)

    def get_goal(self) -> Any:
        """The goal message (the *Goal, not the *ActionGoal); None for a handle to no goal."""
        return None if self.goal is None else self.goal.goal

    def get_goal_id(self) -> Any:
        """The goal's GoalID (an empty one, with an error, for a handle to no goal)."""
        if self.goal is None:
            rospy.logerr("Attempt to get a goal id on an uninitialized ServerGoalHandle")
            return GoalID()
        with self.action_server.lock:
            return self.status_tracker.status.goal_id

    def get_goal_status(self) -> Any:
        """The goal's actionlib_msgs/GoalStatus (the message, not its number)."""
        if self.goal is None:
            rospy.logerr("Attempt to get goal status on an uninitialized ServerGoalHandle")
            return GoalStatus()
        with self.action_server.lock:
            return self.status_tracker.status

    def __eq__(self, other: object) -> bool:
        """Whether both handles hold the same goal (handles to no goal equal none)."""
        if not isinstance(other, ServerGoalHandle) or self.goal is None or other.goal is None:
            return False
        return self.get_goal_id().id == other.get_goal_id().id

    def __ne__(self, other: object) -> bool:
        return not self == other

    def __hash__(self) -> int:
        return hash(self.get_goal_id().id)


def _states_for(event: S.Event) -> str:
    """The states `event` moves a goal from, as words: "PENDING or RECALLING"."""
    names = [S.NAMES[state] for state, moved_by in S.MACHINE.transitions if moved_by is event]
    return " or ".join(names)
