"""An action server on a bus node, in rcl_action's layout (the three services and two topics
under `<name>/_action/`), for controllers that take goals (follow_joint_trajectory,
gripper_cmd). The controller drives each goal from its update: `accept` decides at the request,
`feedback`, `succeed`, `abort` and `canceled` end it, and a cancel request asks `on_cancel`.
Results are answered when the goal ends, and kept RESULT_KEEP seconds."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

from launcher.bus.qos import QoS

ACCEPTED, EXECUTING, CANCELING, SUCCEEDED, CANCELED, ABORTED = 1, 2, 3, 4, 5, 6
TERMINAL = (SUCCEEDED, CANCELED, ABORTED)
RESULT_KEEP = 900.0


class Goal:
    def __init__(self, server: ActionServer, goal_id: Any, request: Any, stamp: Any) -> None:
        self.server, self.goal_id, self.request, self.stamp = server, goal_id, request, stamp
        self.status = EXECUTING
        self.result: Any = None
        self.ended_at: float | None = None
        self.waiting: list[Any] = []

    @property
    def active(self) -> bool:
        return self.status not in TERMINAL

    def feedback(self, feedback: Any) -> None:
        self.server.publish_feedback(self, feedback)

    def succeed(self, result: Any) -> None:
        self.server.end(self, SUCCEEDED, result)

    def abort(self, result: Any) -> None:
        self.server.end(self, ABORTED, result)

    def canceled(self, result: Any) -> None:
        self.server.end(self, CANCELED, result)


class ActionServer:
    def __init__(self, node: Any, type_name: str, name: str,
                 accept: Callable[[Any], bool], on_accepted: Callable[[Goal], None],
                 on_cancel: Callable[[Goal], bool], stamp: Callable[[], Any]) -> None:
        self.node, self.type_name = node, type_name
        self.accept, self.on_accepted, self.on_cancel, self.now = \
            accept, on_accepted, on_cancel, stamp
        self.goals: dict[bytes, Goal] = {}
        base = f"{name}/_action/"
        self.services = [
            node.create_service(f"{type_name}_SendGoal", base + "send_goal", self._on_goal),
            node.create_service("action_msgs/srv/CancelGoal", base + "cancel_goal",
                                self._on_cancel),
        ]
        result = node.create_service(f"{type_name}_GetResult", base + "get_result",
                                     self._on_result)
        result.deferred = True
        self.services.append(result)
        self.feedback_pub = node.create_publisher(f"{type_name}_FeedbackMessage",
                                                  base + "feedback", QoS(depth=10))
        self.status_pub = node.create_publisher("action_msgs/msg/GoalStatusArray",
                                                base + "status",
                                                QoS(depth=1, transient_local=True))

    def _on_goal(self, request: Any, response: Any) -> Any:
        self._expire()
        key = bytes(request.goal_id.uuid)
        if key in self.goals or not self.accept(request.goal):
            response.accepted = False
            return response
        goal = Goal(self, request.goal_id, request.goal, self.now())
        self.goals[key] = goal
        response.accepted, response.stamp = True, goal.stamp
        self.publish_status()
        self.on_accepted(goal)
        return response

    def _on_cancel(self, request: Any, response: Any) -> Any:
        key = bytes(request.goal_info.goal_id.uuid)
        everything = not any(key)
        canceling = []
        for goal in list(self.goals.values()):
            if goal.active and (everything or bytes(goal.goal_id.uuid) == key) and \
                    self.on_cancel(goal):
                if goal.active:
                    goal.status = CANCELING
                canceling.append(goal)
        response.return_code = 0 if canceling else (2 if not everything and key not in
                                                   self.goals else 1)
        response.goals_canceling = [self.node.message(
            "action_msgs/msg/GoalInfo", goal_id=g.goal_id, stamp=g.stamp) for g in canceling]
        self.publish_status()
        return response

    def _on_result(self, request: Any, reply: Any) -> None:
        goal = self.goals.get(bytes(request.goal_id.uuid))
        if goal is None:
            response = reply.new_response()
            response.status = 0
            reply.send(response)
        elif goal.active:
            goal.waiting.append(reply)
        else:
            self._send_result(goal, reply)

    def _send_result(self, goal: Goal, reply: Any) -> None:
        response = reply.new_response()
        response.status, response.result = goal.status, goal.result
        reply.send(response)

    def end(self, goal: Goal, status: int, result: Any) -> None:
        if not goal.active and goal.status != CANCELING:
            return
        goal.status, goal.result, goal.ended_at = status, result, time.monotonic()
        for reply in goal.waiting:
            self._send_result(goal, reply)
        goal.waiting.clear()
        self.publish_status()

    def publish_feedback(self, goal: Goal, feedback: Any) -> None:
        if self.feedback_pub.get_subscription_count():
            self.feedback_pub.publish(self.node.message(
                f"{self.type_name}_FeedbackMessage", goal_id=goal.goal_id, feedback=feedback))

    def publish_status(self) -> None:
        make = self.node.message
        self.status_pub.publish(make("action_msgs/msg/GoalStatusArray", status_list=[make(
            "action_msgs/msg/GoalStatus", goal_info=make(
                "action_msgs/msg/GoalInfo", goal_id=g.goal_id, stamp=g.stamp), status=g.status)
            for g in self.goals.values()]))

    def _expire(self) -> None:
        now = time.monotonic()
        for key, goal in list(self.goals.items()):
            if goal.ended_at is not None and now - goal.ended_at > RESULT_KEEP:
                del self.goals[key]

    def destroy(self) -> None:
        for entity in (*self.services, self.feedback_pub, self.status_pub):
            entity.destroy()
