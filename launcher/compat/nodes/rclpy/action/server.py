"""rclpy.action.server: ActionServer and ServerGoalHandle, as rclpy behaves.

A goal request asks `goal_callback` (accept by default); an accepted goal's handle goes to
`handle_accepted_callback` (by default it executes at once: `execute_callback` runs as a task
of the node's executor, so a MultiThreadedExecutor runs several goals at once). The execute
callback ends the goal with `succeed()`, `abort()` or `canceled()` and returns the result; one
that returns with the goal still active aborts it, with rclpy's warning. A cancel request asks
`cancel_callback` (reject by default) for each goal it names. A result request is answered
when the goal ends (at once for an ended or unknown one); results are kept `result_timeout`
seconds after their goal ends. The goals' states go out on the status topic at each change.
The protocol itself (names, states, the goal table) is launcher's bus/actions.py, and the
server's services, topics and requests are bus/action_server.py's (the one action server, the
controllers' too), here with rclpy's classes, callback group and callbacks (_Server).
"""

from __future__ import annotations

import enum
import inspect
from typing import Any

from launcher.bus import action_server, actions
from launcher.bus.actions import GoalEvent
from launcher.compat import rosidl
from launcher.machines import InvalidTransition
from rclpy.action import names
from rclpy.clock import Clock  # noqa: F401 - the names rclpy's module offers
from rclpy.custody import adopt, check_alive, forget, grouped
from rclpy.executors import await_or_execute  # noqa: F401
from rclpy.properties import readonly
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


RCLError = InvalidTransition  # rclpy's error for what rcl refuses (a goal's bad move)


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

    request = readonly("_goal_request", "The goal as the client sent it.")
    goal_id = readonly("_goal.goal_id", "The goal's id (unique_identifier_msgs/UUID).")
    is_active = readonly("_goal.active", "Whether the goal has not ended (accepted, executing "
                                         "or canceling).")
    status = readonly("_goal.state", "The goal's state (action_msgs/msg/GoalStatus's numbers).")

    @property
    def is_cancel_requested(self) -> bool:
        """Whether a cancel was accepted: the goal is canceling."""
        return self._goal.state == actions.CANCELING

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
        self._server = _Server(self, result_timeout)
        adopt(node, self)

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

    # --- what the server (_Server) asks of the user's callbacks ----------------------------------
    def _accepts(self, goal_request: Any) -> bool:
        return _resolve(self._goal_callback(goal_request)) == GoalResponse.ACCEPT

    def _accepts_cancel(self, handle: ServerGoalHandle) -> bool:
        return _resolve(self._cancel_callback(handle)) == CancelResponse.ACCEPT

    def _accepted(self, handle: ServerGoalHandle) -> None:
        self._handle_accepted_callback(handle)

    # --- a goal's handle ------------------------------------------------------------------------
    def accept(self, goal: actions.Goal) -> None:
        """Keep a goal made outside the send_goal service (a ServerGoalHandle made by hand)
        and say so on the status topic."""
        self._server.goals.add(goal)
        self._server.goals.announce()

    def move(self, handle: ServerGoalHandle, event: GoalEvent) -> None:
        """A goal's move (its handle's execute, succeed, abort, canceled)."""
        self._server.goals.move(handle._goal, event)

    def publish_feedback(self, handle: ServerGoalHandle, feedback: Any) -> None:
        """Send feedback for a goal (ServerGoalHandle.publish_feedback)."""
        if not isinstance(feedback, self._action_type.Feedback):
            raise TypeError(f"Expected type {self._action_type.Feedback}, got "
                            f"{type(feedback)}")
        self._server.publish_feedback(handle._goal, feedback)

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
                           f"{actions.uuid_text(handle.goal_id)}")
            self.move(handle, GoalEvent.ABORT)
        if result is None:
            result = self._action_type.Result()
        handle._result_future.set_result(self._server.finish(handle._goal, result))

    def destroy(self) -> None:
        """Take the action's services and topics off the graph."""
        self._server.destroy()
        forget(self._node, self)


class _Server(action_server.ActionServer):
    """The bus's action server as rclpy's: rclpy's message classes, the goal and cancel
    requests run in the server's callback group, the user's callbacks decide, and an accepted
    goal waits for its handle's execute()."""

    executes_at_once = False

    def __init__(self, owner: ActionServer, result_timeout: float) -> None:
        node = self._node = owner._node  # (what the hooks use, before the services are made)
        self._owner, self._group, self.logger = owner, owner.callback_group, node.get_logger()
        super().__init__(node.handle, owner._type_name, owner._action_name, owner._accepts,
                         owner._accepted, lambda handle: None,
                         lambda: node.get_clock().now().to_msg(), result_timeout)

    def serve(self, type_name: str, name: str, callback: Any, owners_code: bool = True) -> Any:
        run = grouped(self._node, self._group, callback) if owners_code else callback
        return self.node.create_service(type_name, name, run, make=rosidl.make,
                                        new_response=rosidl.service_class(type_name).Response)

    def message(self, type_name: str, **fields: Any) -> Any:
        return rosidl.message_class(type_name)(**fields)

    def handle(self, record: actions.Goal, request: Any) -> ServerGoalHandle:
        return ServerGoalHandle(self._owner, record, request)

    def accept_cancel(self, handle: Any) -> bool:
        return self._owner._accepts_cancel(handle)


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
