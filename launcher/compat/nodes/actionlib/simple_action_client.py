"""actionlib.simple_action_client: SimpleActionClient, one goal at a time over an ActionClient.
A new goal stops the following of the previous one (it is not canceled); the goal's CommState
moves become the done, active and feedback callbacks, as actionlib calls them."""

from __future__ import annotations

import threading
from typing import Any

import rospy

from actionlib import status as S
from actionlib.action_client import NO_TIMEOUT, ActionClient, ClientGoalHandle, CommState
from actionlib.comm_state import get_name_of_constant


class SimpleGoalState:
    PENDING = 0
    ACTIVE = 1
    DONE = 2
    to_string = classmethod(get_name_of_constant)


class SimpleActionClient:
    def __init__(self, ns: str, ActionSpec: Any) -> None:  # noqa: N803 (actionlib's name)
        self.action_client = ActionClient(ns, ActionSpec)
        self.simple_state = SimpleGoalState.DONE
        self.gh: ClientGoalHandle | None = None
        self.done_condition = threading.Condition()
        self.done_cb = self.active_cb = self.feedback_cb = None

    def wait_for_server(self, timeout: Any = NO_TIMEOUT) -> bool:
        """Wait for the server up to `timeout` (zero: as long as it takes); whether it came."""
        return self.action_client.wait_for_server(timeout)

    def send_goal(self, goal: Any, done_cb: Any = None, active_cb: Any = None,
                  feedback_cb: Any = None) -> None:
        """Send a goal, following it instead of the previous one: `done_cb(state, result)`
        at its end, `active_cb()` when it starts, `feedback_cb(feedback)` at its feedback."""
        self.stop_tracking_goal()
        self.done_cb, self.active_cb, self.feedback_cb = done_cb, active_cb, feedback_cb
        self.simple_state = SimpleGoalState.PENDING
        self.gh = self.action_client.send_goal(goal, self._handle_transition,
                                               self._handle_feedback)

    def send_goal_and_wait(self, goal: Any, execute_timeout: Any = NO_TIMEOUT,
                           preempt_timeout: Any = NO_TIMEOUT) -> int:
        """Send a goal and wait for its end, canceling it after `execute_timeout`; its
        state."""
        self.send_goal(goal)
        if not self.wait_for_result(execute_timeout):
            rospy.logdebug("Canceling goal")
            self.cancel_goal()
            self.wait_for_result(preempt_timeout)
        return self.get_state()

    def wait_for_result(self, timeout: Any = NO_TIMEOUT) -> bool:
        """Wait for the goal's end up to `timeout` (zero: as long as it takes); whether it
        ended."""
        if self.gh is None:
            rospy.logerr("Called wait_for_result when no goal exists")
            return False
        left = S.seconds(timeout) or None
        with self.done_condition:
            while not rospy.is_shutdown() and self.simple_state != SimpleGoalState.DONE:
                if left is not None and left <= 0:
                    break
                step = 0.1 if left is None else min(left, 0.1)
                self.done_condition.wait(step)
                left = None if left is None else left - step
        return self.simple_state == SimpleGoalState.DONE

    def get_result(self) -> Any:
        """The goal's *Result (None until it came)."""
        if self.gh is None:
            rospy.logerr("Called get_result when no goal is running")
            return None
        return self.gh.get_result()

    def get_state(self) -> int:
        """The goal's state as a GoalStatus number (RECALLING is PENDING, PREEMPTING is
        ACTIVE here); LOST if no goal is followed."""
        if self.gh is None:
            return S.LOST
        status = self.gh.get_goal_status()
        return {S.RECALLING: S.PENDING, S.PREEMPTING: S.ACTIVE}.get(status, status)

    def get_goal_status_text(self) -> str:
        """The text the server gave with the goal's status."""
        if self.gh is None:
            rospy.logerr("Called get_goal_status_text when no goal is running")
            return "ERROR: Called get_goal_status_text when no goal is running"
        return self.gh.get_goal_status_text()

    def cancel_all_goals(self) -> None:
        """Ask the server to cancel every goal it has."""
        self.action_client.cancel_all_goals()

    def cancel_goals_at_and_before_time(self, time: Any) -> None:
        """Ask the server to cancel every goal stamped at or before `time`."""
        self.action_client.cancel_goals_at_and_before_time(time)

    def cancel_goal(self) -> None:
        """Ask the server to cancel the goal followed."""
        if self.gh is not None:
            self.gh.cancel()

    def stop_tracking_goal(self) -> None:
        """Stop following the goal (its callbacks are not called again; it is not canceled)."""
        self.gh = None

    # --- the goal's moves, as its handle reports them -------------------------------------------
    def _handle_transition(self, gh: ClientGoalHandle) -> None:
        if gh != self.gh:
            rospy.logerr("Got a transition callback on a goal handle that we're not tracking")
            return
        comm_state = gh.get_comm_state()
        if comm_state in (CommState.ACTIVE, CommState.PREEMPTING):
            if self.simple_state == SimpleGoalState.PENDING:
                self.simple_state = SimpleGoalState.ACTIVE
                if self.active_cb:
                    self.active_cb()
            elif self.simple_state == SimpleGoalState.DONE:
                self._unexpected(comm_state)
        elif comm_state == CommState.RECALLING:
            if self.simple_state != SimpleGoalState.PENDING:
                self._unexpected(comm_state)
        elif comm_state == CommState.DONE:
            if self.simple_state == SimpleGoalState.DONE:
                rospy.logerr("SimpleActionClient received DONE twice")
                return
            if self.done_cb:
                self.done_cb(gh.get_goal_status(), gh.get_result())
            with self.done_condition:
                self.simple_state = SimpleGoalState.DONE
                self.done_condition.notify_all()

    def _handle_feedback(self, gh: ClientGoalHandle, feedback: Any) -> None:
        if self.gh is None:
            return  # (the previous goal's feedback, come after it stopped being followed)
        if gh != self.gh:
            rospy.logerr("Got a feedback callback on a goal handle that we're not tracking")
            return
        if self.feedback_cb:
            self.feedback_cb(feedback)

    def _unexpected(self, comm_state: int) -> None:
        rospy.logerr(f"Received comm state {CommState.to_string(comm_state)} when in simple "
                     f"state {SimpleGoalState.to_string(self.simple_state)} with "
                     f"SimpleActionClient in NS {rospy.resolve_name(self.action_client.ns)}")
