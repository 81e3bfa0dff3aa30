"""An action server on a bus node, written once, over the protocol of bus/actions.py: the
action's three services and two topics, its goal table, and what rcl_action decides by itself
(a goal id already kept is refused; a cancel request names its goals, of which only those
accepted or executing can be canceled; a result request is answered when its goal ends, at once
for an ended or unknown one).

What is the owner's: `accept` decides at a goal's request, `on_accepted` is handed the goal
once its request is answered, `on_cancel` hears of a goal that is now canceling, and the owner
ends each goal. As it is, the server is the one of what drives goals from its own loop, the
controllers (follow_joint_trajectory, gripper_cmd) and the sim's SimulateSteps: an accepted
goal executes at once, every cancel is accepted, and the owner's `Goal` handle reports
(`feedback`) and ends it (`succeed`, `abort`, `canceled`), as ros2_controllers' servers do.
rclpy's ActionServer (compat) is this server with its own message classes, callback group and
callbacks: a subclass that changes the hooks below (`serve`, `message`, `handle`,
`accept_cancel`, `executes_at_once`, `logger`)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.bus import actions
from launcher.bus.actions import GoalEvent
from launcher.bus.qos import QoS
from launcher.bus.wire import stamp_nanoseconds
from launcher.machines import InvalidTransition


class Goal:
    """A goal as its owner (a controller, the sim) drives it."""

    def __init__(self, server: ActionServer, record: actions.Goal, request: Any) -> None:
        self.server, self.record, self.request = server, record, request

    @property
    def active(self) -> bool:
        return self.record.active

    def feedback(self, feedback: Any) -> None:
        """Said only while someone listens (it is made at every step of the owner's loop)."""
        if self.server.feedback_heard():
            self.server.publish_feedback(self.record, feedback)

    def succeed(self, result: Any) -> None:
        self.server.end(self.record, GoalEvent.SUCCEED, result)

    def abort(self, result: Any) -> None:
        self.server.end(self.record, GoalEvent.ABORT, result)

    def canceled(self, result: Any) -> None:
        self.server.end(self.record, GoalEvent.CANCELED, result)


class ActionServer:
    executes_at_once = True  # an accepted goal is executing (rclpy's waits for execute())
    logger: Any = None  # what rclpy's server says of duplicate ids and unknown results

    def __init__(self, node: Any, type_name: str, name: str,
                 accept: Callable[[Any], bool], on_accepted: Callable[[Any], None],
                 on_cancel: Callable[[Any], None], stamp: Callable[[], Any],
                 keep: float = actions.RESULT_KEEP) -> None:
        """`node`: the bus node; `stamp()`: the time a goal is accepted at (a Time message);
        `keep`: seconds a result is kept after its goal ends."""
        self.node, self.type_name = node, type_name
        self.accept, self.on_accepted, self.on_cancel, self.now = \
            accept, on_accepted, on_cancel, stamp
        send_goal = self.serve(actions.send_goal_type(type_name),
                               actions.endpoint(name, actions.SEND_GOAL), self._on_goal)
        send_goal.deferred = True  # answered before the owner is handed the goal
        cancel = self.serve(actions.CANCEL_TYPE, actions.endpoint(name, actions.CANCEL_GOAL),
                            self._on_cancel)
        self.results = self.serve(actions.get_result_type(type_name),
                                  actions.endpoint(name, actions.GET_RESULT), self._on_result,
                                  owners_code=False)
        # a result request runs none of the owner's code: answered (or kept for the goal's
        # end) on Zenoh's thread, a hand-over to the executor less on every goal's way
        self.results.deferred = self.results.inline = True
        self.services = [send_goal, cancel, self.results]
        self.feedback_pub = node.create_publisher(actions.feedback_type(type_name),
                                                  actions.endpoint(name, actions.FEEDBACK),
                                                  QoS(depth=10))
        self.status_pub = node.create_publisher(actions.STATUS_TYPE,
                                                actions.endpoint(name, actions.STATUS),
                                                QoS(depth=1, transient_local=True))
        self.goals = actions.GoalTable(self.status_pub.publish_raw, keep)

    # --- the hooks a subclass changes -----------------------------------------------------------
    def serve(self, type_name: str, name: str, callback: Callable[[Any, Any], Any],
              owners_code: bool = True) -> Any:
        """One of the action's services on the node (`owners_code`: its callback runs the
        owner's)."""
        return self.node.create_service(type_name, name, callback)

    def message(self, type_name: str, **fields: Any) -> Any:
        """A message of the owner's classes."""
        return self.node.message(type_name, **fields)

    def handle(self, record: actions.Goal, request: Any) -> Any:
        """The owner's object for an accepted goal (its record's `handle`)."""
        return Goal(self, record, request)

    def accept_cancel(self, handle: Any) -> bool:
        """Whether the owner lets a goal be canceled (before it is canceling)."""
        return True

    # --- requests -------------------------------------------------------------------------------
    def _on_goal(self, request: Any, reply: Any) -> None:
        self.goals.expire()
        response = reply.new_response()
        if actions.uuid_key(request.goal_id) in self.goals:
            if self.logger is not None:
                self.logger.warning(f"Received goal request with duplicate ID: "
                                    f"{actions.uuid_text(request.goal_id)}")
            response.accepted = False
        else:
            response.accepted = bool(self.accept(request.goal))
        if not response.accepted:
            reply.send(response)
            return
        response.stamp = stamp = self.now()
        goal = actions.Goal(request.goal_id, stamp,
                            actions.EXECUTING if self.executes_at_once else actions.ACCEPTED)
        goal.handle = self.handle(goal, request.goal)
        self.goals.add(goal)
        reply.send(response)  # answered first, then said and handed on (as rclcpp does)
        self.goals.announce()
        self.on_accepted(goal.handle)

    def _on_cancel(self, request: Any, response: Any) -> Any:
        info = request.goal_info
        code, candidates = self.goals.cancel_candidates(
            actions.uuid_key(info.goal_id), stamp_nanoseconds(info.stamp))
        canceling = [goal for goal in candidates if self._cancel(goal)]
        response.goals_canceling = [self.message(actions.GOAL_INFO_TYPE, goal_id=goal.goal_id,
                                                 stamp=goal.stamp) for goal in canceling]
        response.return_code = code if code != actions.ERROR_NONE or canceling else \
            actions.ERROR_REJECTED
        return response

    def _cancel(self, goal: actions.Goal) -> bool:
        """Whether the goal is canceling now: one accepted or executing, that the owner lets
        go (and that did not end meanwhile)."""
        if goal.state not in (actions.ACCEPTED, actions.EXECUTING) or \
                not self.accept_cancel(goal.handle):
            return False
        try:
            self.goals.move(goal, GoalEvent.CANCEL_GOAL)
        except InvalidTransition:
            return False
        self.on_cancel(goal.handle)
        return True

    def _on_result(self, request: Any, reply: Any) -> None:
        def unknown() -> Any:
            if self.logger is not None:
                self.logger.debug(f"Sending result response for unknown or expired goal ID: "
                                  f"{actions.uuid_text(request.goal_id)}")
            response = reply.new_response()
            response.status = actions.UNKNOWN
            return response

        self.goals.result_request(actions.uuid_key(request.goal_id), reply, unknown)

    # --- the owner's goals ----------------------------------------------------------------------
    def end(self, goal: actions.Goal, event: GoalEvent, result: Any) -> None:
        """The goal ends (an ended one stays as it ended): its result goes to every request
        waiting for it."""
        if goal.active:
            self.goals.move(goal, event)
            self.finish(goal, result)

    def finish(self, goal: actions.Goal, result: Any) -> Any:
        """The ended goal's result response, sent to every request waiting for it."""
        response = self.results.new_response()
        response.status, response.result = goal.state, result
        self.goals.finish(goal, response)
        return response

    def feedback_heard(self) -> bool:
        """Whether any client listens to the action's feedback now."""
        return bool(self.feedback_pub.get_subscription_count())

    def publish_feedback(self, goal: actions.Goal, feedback: Any) -> None:
        self.feedback_pub.publish(self.message(actions.feedback_type(self.type_name),
                                               goal_id=goal.goal_id, feedback=feedback))

    def destroy(self) -> None:
        for entity in (*self.services, self.feedback_pub, self.status_pub):
            entity.destroy()
