"""actionlib.SimpleActionServer: one goal at a time; a new goal preempts the active one (its
execute callback sees is_preempt_requested()); status at 5 Hz on `<ns>/status`."""

from __future__ import annotations

import threading
from typing import Any

import rospy
from actionlib_msgs.msg import GoalID, GoalStatus, GoalStatusArray

from actionlib import status as S
from actionlib.action_server import nop_cb  # noqa: F401 (simple_action_server has it)


class SimpleActionServer:
    def __init__(self, name: str, ActionSpec: Any, execute_cb: Any = None,  # noqa: N803
                 auto_start: bool = True) -> None:
        self.action_server_name = name
        self.types = S.message_types(ActionSpec)
        self.execute_callback = execute_cb
        self.goal_callback = self.preempt_callback = None
        self.lock = threading.RLock()
        self.new_goal = threading.Condition(self.lock)
        self.current: tuple[Any, Any] | None = None  # (ActionGoal, status)
        self.next: Any = None
        self.preempt_request = False
        self.statuses: dict[str, GoalStatus] = {}
        self.started = False
        ns = name.rstrip("/")
        self.status_pub = rospy.Publisher(f"{ns}/status", GoalStatusArray, queue_size=10)
        self.result_pub = rospy.Publisher(f"{ns}/result", self.types["ActionResult"],
                                          queue_size=10)
        self.feedback_pub = rospy.Publisher(f"{ns}/feedback", self.types["ActionFeedback"],
                                            queue_size=10)
        self._ns = ns
        if auto_start:
            self.start()

    def start(self) -> None:
        """Start taking goals (at construction unless auto_start is false)."""
        if self.started:
            return
        self.started = True
        rospy.Subscriber(f"{self._ns}/goal", self.types["ActionGoal"], self._on_goal)
        rospy.Subscriber(f"{self._ns}/cancel", GoalID, self._on_cancel)
        threading.Thread(target=self._status_loop, daemon=True).start()
        if self.execute_callback is not None:
            threading.Thread(target=self._execute_loop, daemon=True).start()

    # --- goals ----------------------------------------------------------------------------------
    def _on_goal(self, action_goal: Any) -> None:
        with self.lock:
            status = GoalStatus(goal_id=action_goal.goal_id, status=S.PENDING)
            self.statuses[action_goal.goal_id.id] = status
            if self.next is not None:  # the waiting one is replaced: recalled
                self._end(self.next, S.Event.CANCEL, self.types["Result"](), "a newer goal came")
            self.next = action_goal
            if self.current is not None:
                self.preempt_request = True
                if self.preempt_callback:
                    self.preempt_callback()
            self.new_goal.notify_all()
        if self.goal_callback:
            self.goal_callback()

    def _on_cancel(self, goal_id: Any) -> None:
        with self.lock:
            if self.current is not None and goal_id.id in ("", self.current[0].goal_id.id):
                self.preempt_request = True
                status = self.statuses[self.current[0].goal_id.id]
                if S.MACHINE.allows(status.status, S.Event.CANCEL_REQUEST):  # (once)
                    status.status = S.MACHINE.move(status.status, S.Event.CANCEL_REQUEST)
                if self.preempt_callback:
                    self.preempt_callback()
            if self.next is not None and goal_id.id in ("", self.next.goal_id.id):
                self._end(self.next, S.Event.CANCEL, self.types["Result"](), "canceled")
                self.next = None

    def accept_new_goal(self) -> Any:
        """Take the waiting goal (the active one is preempted); the
        goal.
        """
        with self.lock:
            if self.next is None:
                rospy.logerr("Attempting to accept the next goal when a new goal is not "
                             "available")
                return None
            if self.current is not None:
                self._end(self.current[0], S.Event.CANCEL, self.types["Result"](),
                          "a new goal was accepted")
            action_goal, self.next = self.next, None
            status = self.statuses[action_goal.goal_id.id]
            status.status = S.MACHINE.move(status.status, S.Event.ACCEPT)
            self.current = (action_goal, self.statuses[action_goal.goal_id.id])
            self.preempt_request = False
            self._publish_status()
            return action_goal.goal

    def is_new_goal_available(self) -> bool:
        """Whether a goal waits to be taken."""
        return self.next is not None

    def is_preempt_requested(self) -> bool:
        """Whether the active goal is asked to stop."""
        return self.preempt_request

    def is_active(self) -> bool:
        """Whether a goal is being executed."""
        return self.current is not None

    def _execute_loop(self) -> None:
        while not rospy.is_shutdown():
            with self.lock:
                while self.next is None and not rospy.is_shutdown():
                    self.new_goal.wait(0.1)
                if rospy.is_shutdown():
                    return
                goal = self.accept_new_goal()
            try:
                self.execute_callback(goal)
            except Exception as exc:
                rospy.logerr(f"Exception in your execute callback: {exc}")
                if self.is_active():
                    self.set_aborted(text=f"Exception in execute callback: {exc}")
                continue
            if self.is_active():
                rospy.logwarn("Your executeCallback did not set the goal to a terminal status."
                              "  This is a bug in your ActionServer implementation. Fix your "
                              "code!  For now, the ActionServer will set this goal to aborted")
                self.set_aborted(text="This goal was aborted by the simple action server. The "
                                      "user should have set a terminal status on this goal "
                                      "and did not")

    # --- ending -------------------------------------------------------------------------------
    def set_succeeded(self, result: Any = None, text: str = "") -> None:
        """End the active goal as succeeded, with its result."""
        self._finish(S.Event.SUCCEED, result, text)

    def set_aborted(self, result: Any = None, text: str = "") -> None:
        """End the active goal as aborted."""
        self._finish(S.Event.ABORT, result, text)

    def set_preempted(self, result: Any = None, text: str = "") -> None:
        """End the active goal as preempted."""
        self._finish(S.Event.CANCEL, result, text)

    def _finish(self, event: S.Event, result: Any, text: str) -> None:
        with self.lock:
            if self.current is None:
                return
            action_goal, _ = self.current
            self.current = None
            self._end(action_goal, event, result if result is not None
                      else self.types["Result"](), text)

    def _end(self, action_goal: Any, event: S.Event, result: Any, text: str) -> None:
        """The goal ends as `event` moves it (actionlib's state machine)."""
        status = self.statuses[action_goal.goal_id.id]
        status.status, status.text = S.MACHINE.move(status.status, event), text
        message = self.types["ActionResult"](status=status, result=result)
        message.header.stamp = rospy.Time.now()
        self.result_pub.publish(message)
        self._publish_status()

    def publish_feedback(self, feedback: Any) -> None:
        """Send feedback for the active goal."""
        with self.lock:
            if self.current is None:
                return
            message = self.types["ActionFeedback"](status=self.current[1], feedback=feedback)
        message.header.stamp = rospy.Time.now()
        self.feedback_pub.publish(message)

    def register_goal_callback(self, cb: Any) -> None:
        """Call `cb()` when a new goal comes (no execute
        callback: the user takes it with accept_new_goal).
        """
        self.goal_callback = cb

    def register_preempt_callback(self, cb: Any) -> None:
        """Call `cb()` when the active goal is asked
        to stop.
        """
        self.preempt_callback = cb

    def _status_loop(self) -> None:
        """The status, 5 times a second, as actionlib's server publishes it."""
        while not rospy.is_shutdown():
            self._publish_status()
            rospy.sleep(0.2)

    def _publish_status(self) -> None:
        with self.lock:
            listing = list(self.statuses.values())[-50:]
        array = GoalStatusArray(status_list=listing)
        array.header.stamp = rospy.Time.now()
        self.status_pub.publish(array)
