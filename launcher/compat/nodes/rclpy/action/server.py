"""rclpy.action.server: ActionServer and ServerGoalHandle, as rclpy behaves.

A goal request asks `goal_callback` (accept by default); an accepted goal's handle goes to
`handle_accepted_callback` (by default it executes at once: `execute_callback` runs as a task
of the node's executor, so a MultiThreadedExecutor runs several goals at once). The execute
callback ends the goal with `succeed()`, `abort()` or `canceled()` and returns the result; one
that returns with the goal still active aborts it, with rclpy's warning. A cancel request asks
`cancel_callback` (reject by default) for each goal it names. A result request is answered
when the goal ends (at once for an ended or unknown one); results are kept `result_timeout`
seconds after their goal ends. The goals' states go out on the status topic at each change.
The protocol itself (names, states, the goal table) is launcher's bus/actions.py.
"""

from __future__ import annotations

import enum
import inspect
from typing import Any

from launcher.bus import actions
from launcher.bus.actions import GoalEvent
from launcher.bus.qos import QoS
from launcher.compat import rosidl
from rclpy.action import names
from rclpy.clock import Clock  # noqa: F401 - the names rclpy's module offers
from rclpy.executors import await_or_execute  # noqa: F401
from rclpy.node import adopt, check_alive, forget, grouped
from rclpy.qos import QoSProfile  # noqa: F401
from rclpy.service_introspection import ServiceIntrospectionState  # noqa: F401
from rclpy.task import Future, Task  # noqa: F401
from rclpy.type_support import (  # noqa: F401
    Action,
    FeedbackMessage,
    GetResultServiceRequest,
    GetResultServiceResponse,
    SendGoalServiceRequest,
    check_for_type_support,
)
from rclpy.waitable import NumberOfEntities, Waitable  # noqa: F401


class GoalResponse(enum.Enum):
    REJECT = 1
    ACCEPT = 2


class CancelResponse(enum.Enum):
    REJECT = 1
    ACCEPT = 2


RCLError = actions.InvalidTransition  # rclpy's error for what rcl refuses (a goal's bad move)


def default_goal_callback(goal_request: Any) -> GoalResponse:
    """Accept every goal (rclpy's default)."""
    return GoalResponse.ACCEPT


def default_handle_accepted_callback(goal_handle: ServerGoalHandle) -> None:
    """Execute an accepted goal at once (rclpy's default)."""
    goal_handle.execute()


def default_cancel_callback(cancel_request: Any) -> CancelResponse:
    """Refuse every cancel request (rclpy's default)."""
    return CancelResponse.REJECT


class ServerGoalHandle:
    def __init__(self, action_server: ActionServer, goal_info: Any, goal_request: Any) -> None:
        """`goal_info`: an action_msgs/GoalInfo (its goal_id and stamp), accepted on
        `action_server` now, as rcl_action's goal handle is; or the server's own record."""
        self._action_server = action_server
        if isinstance(goal_info, actions.Goal):
            self._goal = goal_info  # the server's record of it: its state
        else:
            self._goal = actions.Goal(goal_info.goal_id, goal_info.stamp, handle=self)
            action_server.accept(self._goal)
        self._goal_request = goal_request
        self._result_future: Future = Future()

    def __eq__(self, other: object) -> bool:
        return isinstance(other, ServerGoalHandle) and self._goal.key == other._goal.key

    def __hash__(self) -> int:
        return hash(self._goal.key)

    @property
    def request(self) -> Any:
        """The goal as the client sent it."""
        return self._goal_request

    @property
    def goal_id(self) -> Any:
        """The goal's id (unique_identifier_msgs/UUID)."""
        return self._goal.goal_id

    @property
    def is_active(self) -> bool:
        """Whether the goal has not ended (accepted, executing or canceling)."""
        return self._goal.active

    @property
    def is_cancel_requested(self) -> bool:
        """Whether a cancel was accepted: the goal is canceling."""
        return self._goal.state == actions.CANCELING

    @property
    def status(self) -> int:
        """The goal's state (action_msgs/msg/GoalStatus's numbers)."""
        return self._goal.state

    def execute(self, execute_callback: Any = None) -> None:
        # An accepted goal starts executing; one canceled before it started only runs its
        # callback (which then sees is_cancel_requested), as rclpy has it
        """Run the execute callback for this goal (`execute_callback`, else the
        server's) as a task of the node's executor; an accepted goal starts executing.
        """
        if self._goal.state == actions.ACCEPTED:
            self._action_server.move(self, GoalEvent.EXECUTE)
        self._action_server.run(self, execute_callback)

    def publish_feedback(self, feedback: Any) -> None:
        """Send feedback (the action's Feedback) to the goal's client."""
        self._action_server.publish_feedback(self, feedback)

    def succeed(self) -> None:
        """End the goal as succeeded (the execute callback returns its result)."""
        self._action_server.move(self, GoalEvent.SUCCEED)

    def abort(self) -> None:
        """End the goal as aborted."""
        self._action_server.move(self, GoalEvent.ABORT)

    def canceled(self) -> None:
        """End a canceling goal as canceled."""
        self._action_server.move(self, GoalEvent.CANCELED)

    def destroy(self) -> None:
        """Nothing to release: the server keeps the goal until its result expires."""
        pass


class ActionServer:
    def __init__(self, node: Any, action_type: Any, action_name: str, execute_callback: Any,
                 *, callback_group: Any = None, goal_callback: Any = default_goal_callback,
                 handle_accepted_callback: Any = default_handle_accepted_callback,
                 cancel_callback: Any = default_cancel_callback,
                 goal_service_qos_profile: Any = None, result_service_qos_profile: Any = None,
                 cancel_service_qos_profile: Any = None, feedback_pub_qos_profile: Any = None,
                 status_pub_qos_profile: Any = None, result_timeout: float = 900) -> None:
        check_alive(node)
        self._node, self._action_name = node, action_name
        self._type_name = names.action_type_name(action_type)
        self._action_type = rosidl.action_class(self._type_name)
        self.register_goal_callback(goal_callback)
        self.register_handle_accepted_callback(handle_accepted_callback)
        self.register_cancel_callback(cancel_callback)
        self.register_execute_callback(execute_callback)
        self.callback_group = callback_group or node.default_callback_group
        bus, impl, name = node.handle, self._action_type.Impl, action_name
        self._send_goal = bus.create_service(
            actions.send_goal_type(self._type_name), actions.endpoint(name, actions.SEND_GOAL),
            grouped(node, self.callback_group, self._on_goal), make=rosidl.make,
            new_response=impl.SendGoalService.Response)
        self._send_goal.deferred = True
        self._cancel = bus.create_service(
            actions.CANCEL_TYPE, actions.endpoint(name, actions.CANCEL_GOAL),
            grouped(node, self.callback_group, self._on_cancel), make=rosidl.make,
            new_response=impl.CancelGoalService.Response)
        self._get_result = bus.create_service(
            actions.get_result_type(self._type_name), actions.endpoint(name, actions.GET_RESULT),
            self._on_result_request, make=rosidl.make,
            new_response=impl.GetResultService.Response)
        # a result request runs none of the user's code: answered (or kept for the goal's
        # end) on Zenoh's thread, a hand-over to the executor less on every goal's way
        self._get_result.deferred = self._get_result.inline = True
        self._feedback = bus.create_publisher(actions.feedback_type(self._type_name),
                                              actions.endpoint(name, actions.FEEDBACK),
                                              QoS(depth=10))
        self._status = bus.create_publisher(actions.STATUS_TYPE,
                                            actions.endpoint(name, actions.STATUS),
                                            QoS(depth=1, transient_local=True))
        self._goals = actions.GoalTable(self._status.publish_raw, result_timeout)
        adopt(node, self)
        from action_msgs.msg import GoalInfo

        self._goal_info = GoalInfo

    # --- callbacks the user gives -------------------------------------------------------------
    def register_goal_callback(self, goal_callback: Any) -> None:
        """Set the callback that accepts or rejects each goal
        (returns a GoalResponse; None: accept all).
        """
        self._goal_callback = goal_callback or default_goal_callback

    def register_handle_accepted_callback(self, handle_accepted_callback: Any) -> None:
        """Set the callback handed each accepted goal's
        handle (None: execute it at once).
        """
        self._handle_accepted_callback = handle_accepted_callback or \
            default_handle_accepted_callback

    def register_cancel_callback(self, cancel_callback: Any) -> None:
        """Set the callback that accepts or refuses each cancel
        request (returns a CancelResponse; None: refuse all).
        """
        self._cancel_callback = cancel_callback or default_cancel_callback

    def register_execute_callback(self, execute_callback: Any) -> None:
        """Set the callback that executes a goal: it ends the goal
        and returns its result.
        """
        if not callable(execute_callback):
            raise TypeError("Failed to register execute callback: not callable")
        self._execute_callback = execute_callback

    # --- goal requests ------------------------------------------------------------------------
    def _on_goal(self, request: Any, reply: Any) -> None:
        self._goals.expire()
        response = reply.new_response()
        if actions.uuid_key(request.goal_id) in self._goals:
            self._node.get_logger().warning(f"Received goal request with duplicate ID: "
                                            f"{names.uuid_text(request.goal_id)}")  # (rejected)
            response.accepted = False
            reply.send(response)
            return
        verdict = _resolve(self._goal_callback(request.goal))
        if verdict != GoalResponse.ACCEPT:
            response.accepted = False
            reply.send(response)
            return
        stamp = self._node.get_clock().now().to_msg()
        goal = actions.Goal(request.goal_id, stamp)
        goal.handle = ServerGoalHandle(self, goal, request.goal)
        response.accepted, response.stamp = True, stamp
        self._goals.add(goal)
        reply.send(response)  # answered first, then said and handed on (as rclpy does)
        self._goals.announce()
        self._handle_accepted_callback(goal.handle)

    def accept(self, goal: actions.Goal) -> None:
        """Keep a goal made outside the send_goal service (a ServerGoalHandle made by hand)
        and say so on the status topic."""
        self._goals.add(goal)
        self._goals.announce()

    def move(self, handle: ServerGoalHandle, event: GoalEvent) -> None:
        """A goal's move (its handle's execute, succeed, abort, canceled)."""
        self._goals.move(handle._goal, event)

    def publish_feedback(self, handle: ServerGoalHandle, feedback: Any) -> None:
        """Send feedback for a goal (ServerGoalHandle.publish_feedback)."""
        if not isinstance(feedback, self._action_type.Feedback):
            raise TypeError(f"Expected type {self._action_type.Feedback}, got "
                            f"{type(feedback)}")
        self._feedback.publish(self._action_type.Impl.FeedbackMessage(
            goal_id=handle.goal_id, feedback=feedback))

    def run(self, handle: ServerGoalHandle, execute_callback: Any) -> None:
        """Run a goal's execute callback as a task of the node's executor."""
        executor = self._node.executor
        if executor is None:
            raise RuntimeError("the action server's node is not spinning: add it to an "
                               "executor before executing goals")
        executor.create_task(self._execute_goal, execute_callback or self._execute_callback,
                             handle)

    async def _execute_goal(self, execute_callback: Any, handle: ServerGoalHandle) -> None:
        logger = self._node.get_logger()
        try:
            result = execute_callback(handle)
            if inspect.isawaitable(result):
                result = await result
        except Exception as exc:
            logger.error(f"Error raised in execute callback: {exc}")
            result = None
            if handle.is_active:
                self.move(handle, GoalEvent.ABORT)
        if handle.is_active:
            logger.warning(f"Goal state not set, assuming aborted. Goal ID: "
                           f"{names.uuid_text(handle.goal_id)}")
            self.move(handle, GoalEvent.ABORT)
        if result is None:
            result = self._action_type.Result()
        response = self._action_type.Impl.GetResultService.Response(status=handle.status,
                                                                     result=result)
        handle._result_future.set_result(response)
        self._goals.finish(handle._goal, response)

    # --- result requests (answered when the goal ends) ------------------------------------
    def _on_result_request(self, request: Any, reply: Any) -> None:
        def unknown() -> Any:
            self._node.get_logger().debug(f"Sending result response for unknown or expired "
                                          f"goal ID: {names.uuid_text(request.goal_id)}")
            return self._action_type.Impl.GetResultService.Response(status=actions.UNKNOWN)

        self._goals.result_request(actions.uuid_key(request.goal_id), reply, unknown)

    # --- cancel requests --------------------------------------------------------------------
    def _on_cancel(self, request: Any, response: Any) -> Any:
        info = request.goal_info
        code, candidates = self._goals.cancel_candidates(
            actions.uuid_key(info.goal_id), info.stamp.sec * 1_000_000_000 + info.stamp.nanosec)
        canceling = []
        for goal in candidates:
            if goal.state not in (actions.ACCEPTED, actions.EXECUTING):
                continue
            if _resolve(self._cancel_callback(goal.handle)) == CancelResponse.ACCEPT:
                try:
                    self._goals.move(goal, GoalEvent.CANCEL_GOAL)
                except actions.InvalidTransition:
                    continue
                canceling.append(self._goal_info(goal_id=goal.goal_id, stamp=goal.stamp))
        response.goals_canceling = canceling
        response.return_code = code if code != actions.ERROR_NONE else \
            actions.ERROR_NONE if canceling else actions.ERROR_REJECTED
        return response

    def destroy(self) -> None:
        """Take the action's services and topics off the graph."""
        for entity in (self._send_goal, self._cancel, self._get_result, self._feedback,
                       self._status):
            entity.destroy()
        forget(self._node, self)


def _resolve(value: Any) -> Any:
    """A callback's verdict, whether it returned it or a coroutine of it (run to its end:
    rclpy awaits it the same way)."""
    if inspect.iscoroutine(value):
        try:
            value.send(None)
        except StopIteration as end:
            return end.value
        value.close()
        raise RuntimeError("an async goal or cancel callback may not await: return its "
                           "verdict")
    return value
