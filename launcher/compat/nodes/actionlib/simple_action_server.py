"""actionlib.simple_action_server: SimpleActionServer, one goal at a time over an ActionServer.
A newer goal waits as the next one and asks the current one to stop (is_preempt_requested,
the preempt callback); the execute callback runs each goal on a thread of its own, or the
goal callback tells the user to take it (accept_new_goal)."""

from __future__ import annotations

import threading
import traceback
from typing import Any

import rospy

from actionlib import status as S
from actionlib.action_server import ActionServer, nop_cb  # noqa: F401 (it has nop_cb)
from actionlib.server_goal_handle import ServerGoalHandle

REPLACED = "This goal was canceled because another goal was received by the simple action server"


class SimpleActionServer:
    def __init__(self, name: str, ActionSpec: Any, execute_cb: Any = None,  # noqa: N803
                 auto_start: bool = True) -> None:
        """`execute_cb(goal)` runs each goal to its end on a thread of its own; without it,
        register_goal_callback and accept_new_goal take the goals."""
        self.new_goal = self.preempt_request = self.new_goal_preempt_request = False
        self.execute_callback = execute_cb
        self.goal_callback = self.preempt_callback = None
        self.need_to_terminate = False
        self.terminate_mutex = threading.RLock()
        # taken after action_server.lock wherever both are (the ActionServer calls in
        # holding its own)
        self.lock = threading.RLock()
        self.execute_condition = threading.Condition(self.lock)
        self.current_goal, self.next_goal = ServerGoalHandle(), ServerGoalHandle()
        self.execute_thread = None
        if execute_cb is not None:
            self.execute_thread = threading.Thread(target=self.executeLoop, daemon=True,
                                                   name="actionlib-execute")
            self.execute_thread.start()
        self.action_server = ActionServer(name, ActionSpec, self.internal_goal_callback,
                                          self.internal_preempt_callback, auto_start)

    def start(self) -> None:
        """Start taking goals (at construction unless auto_start is false)."""
        self.action_server.start()

    def get_default_result(self) -> Any:
        """An empty *Result, sent when a goal ends with none given."""
        return self.action_server.ActionResultType()

    def accept_new_goal(self) -> Any:
        """Take the waiting goal (the current one, if still running, is canceled); the goal.
        A preempt asked for the new goal before this shows in is_preempt_requested()."""
        with self.action_server.lock, self.lock:
            if not self.new_goal or self.next_goal.get_goal() is None:
                rospy.logerr("Attempting to accept the next goal when a new goal is not "
                             "available")
                return None
            if self.is_active() and self.current_goal != self.next_goal:
                self.current_goal.set_canceled(None, REPLACED)
            self.current_goal, self.new_goal = self.next_goal, False
            self.preempt_request = self.new_goal_preempt_request
            self.new_goal_preempt_request = False
            self.current_goal.set_accepted("This goal has been accepted by the simple action "
                                           "server")
            return self.current_goal.get_goal()

    def is_new_goal_available(self) -> bool:
        """Whether a goal waits to be accepted."""
        return self.new_goal

    def is_preempt_requested(self) -> bool:
        """Whether the current goal is asked to stop (a cancel, or a newer goal)."""
        return self.preempt_request

    def is_active(self) -> bool:
        """Whether the current goal is being worked on (ACTIVE or PREEMPTING)."""
        if self.current_goal.get_goal() is None:
            return False
        return self.current_goal.get_goal_status().status in (S.ACTIVE, S.PREEMPTING)

    # --- ending the current goal ----------------------------------------------------------------
    def set_succeeded(self, result: Any = None, text: str = "") -> None:
        """End the current goal as succeeded, with its result."""
        with self.action_server.lock, self.lock:
            self.current_goal.set_succeeded(result, text)

    def set_aborted(self, result: Any = None, text: str = "") -> None:
        """End the current goal as aborted."""
        with self.action_server.lock, self.lock:
            self.current_goal.set_aborted(result, text)

    def set_preempted(self, result: Any = None, text: str = "") -> None:
        """End the current goal as preempted (as asked by a cancel or a newer goal)."""
        with self.action_server.lock, self.lock:
            self.current_goal.set_canceled(result, text)

    def publish_feedback(self, feedback: Any) -> None:
        """Send feedback for the current goal."""
        self.current_goal.publish_feedback(feedback)

    def register_goal_callback(self, cb: Any) -> None:
        """Call `cb()` when a new goal comes (not with an execute callback)."""
        if self.execute_callback:
            rospy.logwarn("Cannot call SimpleActionServer.register_goal_callback() because an "
                          "executeCallback exists. Not going to register it.")
        else:
            self.goal_callback = cb

    def register_preempt_callback(self, cb: Any) -> None:
        """Call `cb()` when the current goal is asked to stop."""
        self.preempt_callback = cb

    # --- what the ActionServer hands on ---------------------------------------------------------
    def internal_goal_callback(self, goal: ServerGoalHandle) -> None:
        """A new goal: it becomes the next one (the waiting one, if any, canceled) unless a
        newer one is already current or next, when it is canceled itself."""
        with self.execute_condition:
            stamp = goal.get_goal_id().stamp.to_nsec()  # (a received stamp has no order)
            if not (self._not_newer(self.current_goal, stamp)
                    and self._not_newer(self.next_goal, stamp)):
                goal.set_canceled(None, REPLACED)
                return
            if self.next_goal.get_goal() is not None and \
                    (self.current_goal.get_goal() is None or self.next_goal != self.current_goal):
                self.next_goal.set_canceled(None, REPLACED)
            self.next_goal, self.new_goal, self.new_goal_preempt_request = goal, True, False
            if self.is_active():
                self._preempt_current()
            if self.goal_callback:
                self.goal_callback()
            self.execute_condition.notify()

    def internal_preempt_callback(self, preempt: ServerGoalHandle) -> None:
        """A cancel request for the current goal asks it to stop; for the next one, it is
        kept until that goal is accepted."""
        with self.lock:
            if preempt == self.current_goal:
                self._preempt_current()
            elif preempt == self.next_goal:
                self.new_goal_preempt_request = True

    def _preempt_current(self) -> None:
        self.preempt_request = True
        if self.preempt_callback:
            self.preempt_callback()

    @staticmethod
    def _not_newer(handle: ServerGoalHandle, stamp: int) -> bool:
        return handle.get_goal() is None or stamp >= handle.get_goal_id().stamp.to_nsec()

    def executeLoop(self) -> None:  # noqa: N802 (actionlib's name)
        """The execute thread: each new goal accepted and run to its end."""
        while not rospy.is_shutdown():
            with self.terminate_mutex:
                if self.need_to_terminate:
                    return
            if self.is_active():
                rospy.logerr("Should never reach this code with an active goal")
                return
            if self.is_new_goal_available():
                self._execute(self.accept_new_goal())
            with self.execute_condition:
                self.execute_condition.wait(0.1)

    def _execute(self, goal: Any) -> None:
        try:
            self.execute_callback(goal)
        except Exception as exc:  # noqa: BLE001 (the user's callback: the goal aborts)
            rospy.logerr(f"Exception in your execute callback: {exc}\n{traceback.format_exc()}")
            self.set_aborted(None, f"Exception in execute callback: {exc}")
            return
        if self.is_active():
            rospy.logwarn("Your executeCallback did not set the goal to a terminal status.  "
                          "This is a bug in your ActionServer implementation. Fix your code!  "
                          "For now, the ActionServer will set this goal to aborted")
            self.set_aborted(None, "No terminal state was set.")
