"""actionlib.SimpleActionClient: one goal at a time on `<ns>/goal`, its feedback, result and
status followed by goal id; done, active and feedback callbacks as actionlib calls them."""

from __future__ import annotations

import itertools
import threading
import time
from typing import Any

import rospy
from actionlib_msgs.msg import GoalID, GoalStatusArray

from actionlib import status as S
from actionlib.action_client import CommState, get_name_of_constant  # noqa: F401


class SimpleGoalState:
    PENDING, ACTIVE, DONE = 0, 1, 2
    to_str = {0: "PENDING", 1: "ACTIVE", 2: "DONE"}


class SimpleActionClient:
    _ids = itertools.count(1)

    def __init__(self, ns: str, ActionSpec: Any) -> None:  # noqa: N803
        self.ns = ns.rstrip("/")
        self.types = S.message_types(ActionSpec)
        self.goal_pub = rospy.Publisher(f"{self.ns}/goal", self.types["ActionGoal"],
                                        queue_size=10)
        self.cancel_pub = rospy.Publisher(f"{self.ns}/cancel", GoalID, queue_size=10)
        self.lock = threading.Lock()
        self.done = threading.Event()
        self.goal_id = ""
        self.state = S.LOST
        self.simple_state = SimpleGoalState.DONE
        self.result: Any = None
        self.callbacks: tuple[Any, Any, Any] = (None, None, None)
        self.server_seen = threading.Event()
        rospy.Subscriber(f"{self.ns}/status", GoalStatusArray, self._on_status)
        rospy.Subscriber(f"{self.ns}/feedback", self.types["ActionFeedback"], self._on_feedback)
        rospy.Subscriber(f"{self.ns}/result", self.types["ActionResult"], self._on_result)

    def wait_for_server(self, timeout: Any = None) -> bool:
        """Wait for the server's status up to `timeout` (None: as long
        as it takes); whether it came.
        """
        seconds = _seconds(timeout)
        deadline = None if not seconds else time.monotonic() + seconds
        while not rospy.is_shutdown():
            if self.server_seen.is_set() and self.goal_pub.get_num_connections() > 0:
                return True
            if deadline is not None and time.monotonic() > deadline:
                return False
            time.sleep(0.05)
        return False

    def send_goal(self, goal: Any, done_cb: Any = None, active_cb: Any = None,
                  feedback_cb: Any = None) -> None:
        """Send a goal (the previous one is no longer tracked), with
        callbacks for its end, its start and its feedback.
        """
        now = rospy.Time.now()
        goal_id = f"{rospy.get_name()}-{next(self._ids)}-{now.to_sec():.3f}"
        with self.lock:
            self.goal_id, self.state, self.result = goal_id, S.PENDING, None
            self.simple_state = SimpleGoalState.PENDING
            self.callbacks = (done_cb, active_cb, feedback_cb)
            self.done.clear()
        message = self.types["ActionGoal"](goal_id=GoalID(stamp=now, id=goal_id), goal=goal)
        message.header.stamp = now
        self.goal_pub.publish(message)

    def send_goal_and_wait(self, goal: Any, execute_timeout: Any = None,
                           preempt_timeout: Any = None) -> int:
        """Send a goal and wait for its end (canceled after
        `execute_timeout`); its final state.
        """
        self.send_goal(goal)
        if not self.wait_for_result(execute_timeout):
            self.cancel_goal()
            self.wait_for_result(preempt_timeout)
        return self.get_state()

    def wait_for_result(self, timeout: Any = None) -> bool:
        """Wait for the goal's end up to `timeout`; whether it ended."""
        seconds = _seconds(timeout)
        while not rospy.is_shutdown():
            if self.done.wait(min(seconds, 0.1) if seconds else 0.1):
                return True
            if seconds:
                seconds -= 0.1
                if seconds <= 0:
                    return False
        return self.done.is_set()

    def get_result(self) -> Any:
        """The goal's result, once it ended."""
        return self.result

    def get_state(self) -> int:
        """The goal's state (actionlib_msgs/GoalStatus's numbers)."""
        return self.state

    def get_goal_status_text(self) -> str:
        """The text the server gave with the goal's state."""
        return getattr(self, "status_text", "")

    def cancel_goal(self) -> None:
        """Ask the server to cancel the goal."""
        self.cancel_pub.publish(GoalID(id=self.goal_id))

    def cancel_all_goals(self) -> None:
        """Ask the server to cancel every goal."""
        self.cancel_pub.publish(GoalID())

    def stop_tracking_goal(self) -> None:
        """Forget the goal (its later states are not followed)."""
        self.goal_id = ""

    # --- what the server says -----------------------------------------------------------------
    def _on_status(self, array: Any) -> None:
        self.server_seen.set()
        for status in array.status_list:
            if status.goal_id.id == self.goal_id and status.status not in S.TERMINAL:
                self._became(status.status)

    def _became(self, state: int) -> None:
        with self.lock:
            was = self.simple_state
            self.state = state
            if state in (S.ACTIVE, S.PREEMPTING) and was == SimpleGoalState.PENDING:
                self.simple_state = SimpleGoalState.ACTIVE
                active_cb = self.callbacks[1]
            else:
                active_cb = None
        if active_cb:
            active_cb()

    def _on_feedback(self, message: Any) -> None:
        if message.status.goal_id.id == self.goal_id:
            self._became(message.status.status)
            if self.callbacks[2]:
                self.callbacks[2](message.feedback)

    def _on_result(self, message: Any) -> None:
        if message.status.goal_id.id != self.goal_id or self.done.is_set():
            return
        with self.lock:
            self.state, self.result = message.status.status, message.result
            self.status_text = message.status.text
            self.simple_state = SimpleGoalState.DONE
            done_cb = self.callbacks[0]
        self.done.set()
        if done_cb:
            done_cb(self.state, self.result)


def _seconds(timeout: Any) -> float:
    if timeout is None:
        return 0.0
    if hasattr(timeout, "to_sec"):
        return float(timeout.to_sec())
    return float(timeout)
