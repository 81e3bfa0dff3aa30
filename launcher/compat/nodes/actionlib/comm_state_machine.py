"""One goal as an ActionClient follows it: CommStateMachine moves its CommState by the
server's status, result and feedback (comm_state.TRANSITIONS), calling the user's transition
and feedback callbacks; ClientGoalHandle is the user's hold on it. actionlib.action_client
gives these names."""

from __future__ import annotations

import threading
from typing import Any

import rospy
from actionlib_msgs.msg import GoalID, GoalStatus, GoalStatusArray

from actionlib import status as S
from actionlib.comm_state import TRANSITIONS, CommState


class CommStateMachine:
    def __init__(self, action_goal: Any, transition_cb: Any, feedback_cb: Any,
                 send_goal_fn: Any, send_cancel_fn: Any) -> None:
        self.action_goal = action_goal
        self.transition_cb, self.feedback_cb = transition_cb, feedback_cb
        self.send_goal_fn, self.send_cancel_fn = send_goal_fn, send_cancel_fn
        self.state = CommState.WAITING_FOR_GOAL_ACK
        self.mutex = threading.RLock()
        self.latest_goal_status = GoalStatus(status=S.PENDING)
        self.latest_result: Any = None  # the ActionResult, once it came

    @property
    def goal_id(self) -> str:
        """The goal's id (its GoalID's string)."""
        return self.action_goal.goal_id.id

    def __eq__(self, other: object) -> bool:
        return isinstance(other, CommStateMachine) and self.goal_id == other.goal_id

    def __hash__(self) -> int:
        return hash(self.goal_id)

    def set_state(self, state: int) -> None:
        """Set the state, telling no one."""
        self.state = state

    def transition_to(self, state: int) -> None:
        """Move to `state` and tell the transition callback."""
        rospy.logdebug(f"Transitioning to {CommState.to_string(state)} (from "
                       f"{CommState.to_string(self.state)}, goal: {self.goal_id})")
        self.state = state
        if self.transition_cb:
            self.transition_cb(ClientGoalHandle(self))

    def update_status(self, status_array: Any) -> None:
        """The server's status list came: move as this goal's entry says. A goal the server
        no longer lists, once it had acknowledged it, is LOST."""
        with self.mutex:
            if self.state == CommState.DONE:
                return
            status = next((entry for entry in status_array.status_list
                           if entry.goal_id.id == self.goal_id), None)
            if status is None:
                if self.state not in (CommState.WAITING_FOR_GOAL_ACK,
                                      CommState.WAITING_FOR_RESULT):
                    self.latest_goal_status.status = S.LOST
                    self.transition_to(CommState.DONE)
                return
            self.latest_goal_status = status
            if status.status not in S.NAMES or status.status == S.LOST:
                rospy.logerr(f"Got an unknown status from the ActionServer: {status.status}")
                return
            path = TRANSITIONS[self.state].get(status.status)
            if path is None:
                rospy.logerr(f"Invalid goal status transition from "
                             f"{CommState.to_string(self.state)} to {S.NAMES[status.status]}")
                return
            for state in path:
                self.transition_to(state)

    def update_result(self, action_result: Any) -> None:
        """A result came: if it is this goal's, its status moves the goal, then DONE."""
        if action_result.status.goal_id.id != self.goal_id:
            return
        with self.mutex:
            self.latest_goal_status, self.latest_result = action_result.status, action_result
            if self.state == CommState.DONE:
                rospy.logerr("Got a result when we were already in the DONE state")
                return
            self.update_status(GoalStatusArray(status_list=[action_result.status]))
            self.transition_to(CommState.DONE)

    def update_feedback(self, action_feedback: Any) -> None:
        """Feedback came: if it is this goal's, the feedback callback hears it."""
        if action_feedback.status.goal_id.id != self.goal_id:
            return
        if self.feedback_cb and self.state != CommState.DONE:
            self.feedback_cb(ClientGoalHandle(self), action_feedback.feedback)


class ClientGoalHandle:
    """The user's hold on a goal an ActionClient sent. The client follows the goal while a
    handle to it is kept (it keeps only a weak reference)."""

    def __init__(self, comm_state_machine: CommStateMachine | None) -> None:
        self.comm_state_machine = comm_state_machine

    def __eq__(self, other: object) -> bool:
        """Whether both handles follow the same goal."""
        return isinstance(other, ClientGoalHandle) and \
            self.comm_state_machine == other.comm_state_machine

    def __ne__(self, other: object) -> bool:
        return not self == other

    def __hash__(self) -> int:
        return hash(self.comm_state_machine)

    def cancel(self) -> None:
        """Ask the server to cancel this goal (WAITING_FOR_CANCEL_ACK until it answers)."""
        machine = self._machine("cancel")
        if machine is None:
            return
        with machine.mutex:
            machine.send_cancel_fn(GoalID(stamp=rospy.Time(0), id=machine.goal_id))
            machine.transition_to(CommState.WAITING_FOR_CANCEL_ACK)

    def get_comm_state(self) -> int:
        """Where the goal's exchange with the server stands (a CommState)."""
        machine = self._machine("get_comm_state")
        return CommState.LOST if machine is None else machine.state

    def get_goal_status(self) -> int:
        """The goal's status as the server last gave it (actionlib_msgs/GoalStatus's numbers)."""
        machine = self._machine("get_goal_status")
        return S.PENDING if machine is None else machine.latest_goal_status.status

    def get_goal_status_text(self) -> str:
        """The text the server last gave with the goal's status."""
        machine = self._machine("get_goal_status_text")
        if machine is None:
            return "ERROR: Trying to get_goal_status_text on an inactive ClientGoalHandle."
        return machine.latest_goal_status.text

    def get_result(self) -> Any:
        """The goal's *Result, None until it came."""
        machine = self._machine("get_result")
        if machine is None or machine.latest_result is None:
            return None
        return machine.latest_result.result

    def get_terminal_state(self) -> int:
        """How the goal ended (a GoalStatus number; LOST with an error if it has not)."""
        machine = self._machine("get_terminal_state")
        if machine is None:
            return S.LOST
        with machine.mutex:
            if machine.state != CommState.DONE:
                rospy.logwarn(f"Asking for the terminal state when we're in "
                              f"[{CommState.to_string(machine.state)}]")
            status = machine.latest_goal_status.status
            if status in S.TERMINAL:
                return status
            rospy.logerr(f"Asking for a terminal state, but the goal status is {status}")
            return S.LOST

    def _machine(self, verb: str) -> CommStateMachine | None:
        if self.comm_state_machine is None:
            rospy.logerr(f"Trying to {verb} on an inactive ClientGoalHandle.")
        return self.comm_state_machine
