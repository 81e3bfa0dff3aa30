"""actionlib.action_client: ActionClient, the goal-handle client on ROS 1's action topics.
Each goal sent gets a CommStateMachine (comm_state_machine.py) that the GoalManager keeps
while the user holds its ClientGoalHandle, and that the server's status, result and feedback
move."""

from __future__ import annotations

import threading
import time
import weakref
from typing import Any

import rospy
from actionlib_msgs.msg import GoalID, GoalStatus, GoalStatusArray

from actionlib import status as S
from actionlib.comm_state import (  # noqa: F401 (action_client has them)
    INVALID_TRANSITION,
    NO_TRANSITION,
    CommState,
    TerminalState,
    get_name_of_constant,
)
from actionlib.comm_state_machine import ClientGoalHandle, CommStateMachine
from actionlib.exceptions import ActionException  # noqa: F401 (action_client has it)

g_goal_id = 1  # the number of the next goal this process sends
NO_TIMEOUT = rospy.Duration(0.0)  # a zero timeout: wait as long as it takes

# as actionlib does: GoalStatus.to_string(n) names a status once actionlib is imported
GoalStatus.to_string = classmethod(get_name_of_constant)


class GoalManager:
    """The goals an ActionClient follows (weakly: a goal whose handles are all gone is
    dropped), and what the server says handed to each."""

    def __init__(self, ActionSpec: Any) -> None:  # noqa: N803 (actionlib's name)
        types = S.message_types(ActionSpec)
        self.ActionSpec, self.ActionGoal = ActionSpec, types["ActionGoal"]
        self.ActionResult, self.ActionFeedback = types["ActionResult"], types["ActionFeedback"]
        self.list_mutex = threading.RLock()
        self.statuses: list[weakref.ref[CommStateMachine]] = []
        self.send_goal_fn: Any = None
        self.cancel_fn: Any = None

    def register_send_goal_fn(self, fn: Any) -> None:
        """Send each new goal (an *ActionGoal) with `fn`."""
        self.send_goal_fn = fn

    def register_cancel_fn(self, fn: Any) -> None:
        """Send each goal's cancel request (a GoalID) with `fn`."""
        self.cancel_fn = fn

    def init_goal(self, goal: Any, transition_cb: Any = None,
                  feedback_cb: Any = None) -> ClientGoalHandle:
        """Send `goal` and follow it; its handle."""
        now = rospy.get_rostime()
        action_goal = self.ActionGoal(goal_id=_new_goal_id(now), goal=goal)
        action_goal.header.stamp = now
        machine = CommStateMachine(action_goal, transition_cb, feedback_cb,
                                   self.send_goal_fn, self.cancel_fn)
        with self.list_mutex:
            self.statuses.append(weakref.ref(machine))
        self.send_goal_fn(action_goal)
        return ClientGoalHandle(machine)

    def update_statuses(self, status_array: Any) -> None:
        """Hand the server's status list to every goal followed."""
        with self.list_mutex:
            self.statuses = [ref for ref in self.statuses if ref() is not None]
        for machine in self._live():
            machine.update_status(status_array)

    def update_results(self, action_result: Any) -> None:
        """Hand a result to every goal followed (its own goal takes it)."""
        for machine in self._live():
            machine.update_result(action_result)

    def update_feedbacks(self, action_feedback: Any) -> None:
        """Hand feedback to every goal followed (its own goal takes it)."""
        for machine in self._live():
            machine.update_feedback(action_feedback)

    def _live(self) -> list[CommStateMachine]:
        with self.list_mutex:
            return [machine for machine in (ref() for ref in self.statuses)
                    if machine is not None]


def _new_goal_id(now: Any) -> Any:
    """`<node>-<n>-<seconds>`, as actionlib's clients number their goals."""
    global g_goal_id
    number, g_goal_id = g_goal_id, g_goal_id + 1
    return GoalID(id=f"{rospy.get_caller_id()}-{number}-{now.to_sec():.3f}", stamp=now)


class ActionClient:
    def __init__(self, ns: str, ActionSpec: Any) -> None:  # noqa: N803 (actionlib's name)
        """A client of the action server at `ns` (its topics `<ns>/goal`, …) of type
        `ActionSpec` (a *Action class)."""
        self.ns = ns
        self.last_status_msg: Any = None
        self.manager = GoalManager(ActionSpec)
        self.ActionSpec, self.ActionGoal = ActionSpec, self.manager.ActionGoal
        self.ActionResult = self.manager.ActionResult
        self.ActionFeedback = self.manager.ActionFeedback
        resolved = rospy.remap_name(ns)
        self.pub_queue_size = S.queue_size(
            rospy.get_param("actionlib_client_pub_queue_size", 10), 10)
        self.pub_goal = rospy.Publisher(f"{resolved}/goal", self.ActionGoal,
                                        queue_size=self.pub_queue_size)
        self.pub_cancel = rospy.Publisher(f"{resolved}/cancel", GoalID,
                                          queue_size=self.pub_queue_size)
        self.manager.register_send_goal_fn(self.pub_goal.publish)
        self.manager.register_cancel_fn(self.pub_cancel.publish)
        self.sub_queue_size = S.queue_size(rospy.get_param("actionlib_client_sub_queue_size", -1),
                                    None)
        self.status_sub = rospy.Subscriber(f"{resolved}/status", GoalStatusArray,
                                           callback=self._status_cb,
                                           queue_size=self.sub_queue_size)
        self.result_sub = rospy.Subscriber(f"{resolved}/result", self.ActionResult,
                                           callback=self._result_cb,
                                           queue_size=self.sub_queue_size)
        self.feedback_sub = rospy.Subscriber(f"{resolved}/feedback", self.ActionFeedback,
                                             callback=self._feedback_cb,
                                             queue_size=self.sub_queue_size)

    def stop(self) -> None:
        """Leave the action's topics."""
        for endpoint in (self.pub_goal, self.pub_cancel, self.status_sub, self.result_sub,
                         self.feedback_sub):
            endpoint.unregister()

    def send_goal(self, goal: Any, transition_cb: Any = None,
                  feedback_cb: Any = None) -> ClientGoalHandle:
        """Send `goal` (a *Goal); its handle. `transition_cb(handle)` hears each move of its
        CommState, `feedback_cb(handle, feedback)` its feedback, while the handle is kept."""
        return self.manager.init_goal(goal, transition_cb, feedback_cb)

    def cancel_all_goals(self) -> None:
        """Ask the server to cancel every goal it has."""
        self.pub_cancel.publish(GoalID(stamp=rospy.Time.from_sec(0.0), id=""))

    def cancel_goals_at_and_before_time(self, time: Any) -> None:
        """Ask the server to cancel every goal stamped at or before `time`."""
        self.pub_cancel.publish(GoalID(stamp=time, id=""))

    def wait_for_action_server_to_start(self, timeout: Any = NO_TIMEOUT) -> bool:
        """(deprecated: wait_for_server)"""
        return self.wait_for_server(timeout)

    def wait_for_server(self, timeout: Any = NO_TIMEOUT) -> bool:
        """Wait until a server's status has come and it takes this client's goals and
        cancels, at most `timeout` (zero: as long as it takes); whether it did."""
        seconds = S.seconds(timeout)
        deadline = time.monotonic() + seconds if seconds > 0 else None
        while not rospy.is_shutdown():
            if self.last_status_msg is not None and self.pub_goal.get_num_connections() > 0 \
                    and self.pub_cancel.get_num_connections() > 0:
                return True
            if deadline is not None and time.monotonic() >= deadline:
                return False
            time.sleep(0.01)
        return False

    def _status_cb(self, msg: Any) -> None:
        self.last_status_msg = msg
        self.manager.update_statuses(msg)

    def _result_cb(self, msg: Any) -> None:
        self.manager.update_results(msg)

    def _feedback_cb(self, msg: Any) -> None:
        self.manager.update_feedbacks(msg)

