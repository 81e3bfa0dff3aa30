"""An action server on a bus node for what drives goals from its own loop: controllers that
take goals (follow_joint_trajectory, gripper_cmd) and the sim's SimulateSteps, over the
protocol of bus/actions.py (rcl_action's services, topics, states and goal table). The owner
drives each goal from its update: `accept` decides at the request, an accepted goal executes
at once (`on_accepted`), `feedback` reports, and `succeed`, `abort` and `canceled` end it.
Every cancel request is accepted, as ros2_controllers' servers accept them: the goal is
canceling when `on_cancel` hears of it, and its owner ends it."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.bus import actions
from launcher.bus.actions import GoalEvent
from launcher.bus.qos import QoS


class Goal:
    """A goal as its controller drives it."""

    def __init__(self, server: ActionServer, record: actions.Goal, request: Any) -> None:
        self.server, self.record, self.request = server, record, request

    @property
    def active(self) -> bool:
        return self.record.active

    def feedback(self, feedback: Any) -> None:
        self.server.publish_feedback(self, feedback)

    def succeed(self, result: Any) -> None:
        self.server.end(self, GoalEvent.SUCCEED, result)

    def abort(self, result: Any) -> None:
        self.server.end(self, GoalEvent.ABORT, result)

    def canceled(self, result: Any) -> None:
        self.server.end(self, GoalEvent.CANCELED, result)


class ActionServer:
    def __init__(self, node: Any, type_name: str, name: str,
                 accept: Callable[[Any], bool], on_accepted: Callable[[Goal], None],
                 on_cancel: Callable[[Goal], None], stamp: Callable[[], Any]) -> None:
        self.node, self.type_name = node, type_name
        self.accept, self.on_accepted, self.on_cancel, self.now = \
            accept, on_accepted, on_cancel, stamp
        self.services = [
            node.create_service(actions.send_goal_type(type_name),
                                actions.endpoint(name, actions.SEND_GOAL), self._on_goal),
            node.create_service(actions.CANCEL_TYPE, actions.endpoint(name, actions.CANCEL_GOAL),
                                self._on_cancel),
        ]
        self.results = node.create_service(actions.get_result_type(type_name),
                                           actions.endpoint(name, actions.GET_RESULT),
                                           self._on_result)
        self.results.deferred = True
        self.services.append(self.results)
        self.feedback_pub = node.create_publisher(actions.feedback_type(type_name),
                                                  actions.endpoint(name, actions.FEEDBACK),
                                                  QoS(depth=10))
        self.status_pub = node.create_publisher(actions.STATUS_TYPE,
                                                actions.endpoint(name, actions.STATUS),
                                                QoS(depth=1, transient_local=True))
        self.goals = actions.GoalTable(self.status_pub.publish_raw)

    def _on_goal(self, request: Any, response: Any) -> Any:
        self.goals.expire()
        if actions.uuid_key(request.goal_id) in self.goals or not self.accept(request.goal):
            response.accepted = False
            return response
        record = actions.Goal(request.goal_id, self.now())
        goal = record.handle = Goal(self, record, request.goal)
        self.goals.add(record)
        self.goals.move(record, GoalEvent.EXECUTE)  # (the controller takes it at its update)
        response.accepted, response.stamp = True, record.stamp
        self.on_accepted(goal)
        return response

    def _on_cancel(self, request: Any, response: Any) -> Any:
        info = request.goal_info
        code, candidates = self.goals.cancel_candidates(
            actions.uuid_key(info.goal_id), info.stamp.sec * 1_000_000_000 + info.stamp.nanosec)
        canceling = [record for record in candidates if record.active]
        for record in canceling:
            self.goals.move(record, GoalEvent.CANCEL_GOAL)
            self.on_cancel(record.handle)
        response.return_code = code if code != actions.ERROR_NONE or canceling else \
            actions.ERROR_REJECTED
        response.goals_canceling = [self.node.message(
            actions.GOAL_INFO_TYPE, goal_id=r.goal_id, stamp=r.stamp) for r in canceling]
        return response

    def _on_result(self, request: Any, reply: Any) -> None:
        def unknown() -> Any:
            response = reply.new_response()
            response.status = actions.UNKNOWN
            return response

        self.goals.result_request(actions.uuid_key(request.goal_id), reply, unknown)

    def end(self, goal: Goal, event: GoalEvent, result: Any) -> None:
        """The goal ends (an ended one stays as it ended): its result goes to every request
        waiting for it."""
        if not goal.active:
            return
        self.goals.move(goal.record, event)
        response = self.results.new_response()
        response.status, response.result = goal.record.state, result
        self.goals.finish(goal.record, response)

    def publish_feedback(self, goal: Goal, feedback: Any) -> None:
        if self.feedback_pub.get_subscription_count():
            self.feedback_pub.publish(self.node.message(
                actions.feedback_type(self.type_name), goal_id=goal.record.goal_id,
                feedback=feedback))

    def destroy(self) -> None:
        for entity in (*self.services, self.feedback_pub, self.status_pub):
            entity.destroy()
