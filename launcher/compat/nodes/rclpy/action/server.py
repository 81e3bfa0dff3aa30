"""rclpy.action.server: ActionServer and ServerGoalHandle, as rclpy behaves.

A goal request asks `goal_callback` (accept by default); an accepted goal's handle goes to
`handle_accepted_callback` (by default it executes at once: `execute_callback` runs as a task
of the node's executor, so a MultiThreadedExecutor runs several goals at once). The execute
callback ends the goal with `succeed()`, `abort()` or `canceled()` and returns the result; one
that returns with the goal still active aborts it, with rclpy's warning. A cancel request asks
`cancel_callback` (reject by default) for each goal it names. A result request is answered
when the goal ends (at once for an ended or unknown one); results are kept `result_timeout`
seconds after their goal ends. The goals' states go out on the status topic at each change.
"""

from __future__ import annotations

import enum
import inspect
import struct
import threading
import time
from typing import Any

from launcher.bus.qos import QoS
from launcher.compat import rosidl
from rclpy.action import names as N
from rclpy.node import adopt, check_alive, forget, grouped
from rclpy.task import Future


class GoalResponse(enum.Enum):
    REJECT = 1
    ACCEPT = 2


class CancelResponse(enum.Enum):
    REJECT = 1
    ACCEPT = 2


GoalEvent = enum.Enum("GoalEvent", "EXECUTE CANCEL_GOAL SUCCEED ABORT CANCELED")

# rcl_action's goal state machine: (state, event) → state
_TRANSITIONS = {
    (N.ACCEPTED, GoalEvent.EXECUTE): N.EXECUTING,
    (N.ACCEPTED, GoalEvent.CANCEL_GOAL): N.CANCELING,
    (N.EXECUTING, GoalEvent.CANCEL_GOAL): N.CANCELING,
    (N.EXECUTING, GoalEvent.SUCCEED): N.SUCCEEDED,
    (N.EXECUTING, GoalEvent.ABORT): N.ABORTED,
    (N.CANCELING, GoalEvent.SUCCEED): N.SUCCEEDED,
    (N.CANCELING, GoalEvent.ABORT): N.ABORTED,
    (N.CANCELING, GoalEvent.CANCELED): N.CANCELED,
}


class RCLError(RuntimeError):
    """rclpy's error for what rcl refuses (an invalid goal transition)."""


def default_goal_callback(goal_request: Any) -> GoalResponse:
    return GoalResponse.ACCEPT


def default_handle_accepted_callback(goal_handle: ServerGoalHandle) -> None:
    goal_handle.execute()


def default_cancel_callback(cancel_request: Any) -> CancelResponse:
    return CancelResponse.REJECT


class ServerGoalHandle:
    def __init__(self, action_server: ActionServer, goal_info: Any, goal_request: Any) -> None:
        self._action_server = action_server
        self._goal_info = goal_info
        self._goal_request = goal_request
        self._state = N.ACCEPTED
        self._cancel_requested = False
        self._lock = threading.Lock()
        self._result_future: Future = Future()
        self.ended_at: float | None = None
        self._status_made: tuple[int, bytes] | None = None

    def __eq__(self, other: object) -> bool:
        return isinstance(other, ServerGoalHandle) and \
            N.uuid_key(self.goal_id) == N.uuid_key(other.goal_id)

    def __hash__(self) -> int:
        return hash(N.uuid_key(self.goal_id))

    def _status_cdr(self) -> bytes:
        """Its status array entry (status_entry_cdr), made again only when its state moves."""
        made = self._status_made
        if made is None or made[0] != self._state:
            stamp = self._goal_info.stamp
            made = self._status_made = (self._state, status_entry_cdr(
                bytes(self.goal_id.uuid), stamp.sec, stamp.nanosec, self._state))
        return made[1]

    @property
    def request(self) -> Any:
        return self._goal_request

    @property
    def goal_id(self) -> Any:
        return self._goal_info.goal_id

    @property
    def is_active(self) -> bool:
        return self._state not in N.TERMINAL

    @property
    def is_cancel_requested(self) -> bool:
        return self._state == N.CANCELING

    @property
    def status(self) -> int:
        return self._state

    def _update_state(self, event: GoalEvent) -> None:
        with self._lock:
            new = _TRANSITIONS.get((self._state, event))
            if new is None:
                raise RCLError(f"Failed to update goal state: goal_handle attempted invalid "
                               f"transition from state {N.STATE_NAMES[self._state]} with "
                               f"event {event.name}")
            self._state = new
            if new in N.TERMINAL:
                self.ended_at = time.monotonic()
        self._action_server._publish_status()

    def execute(self, execute_callback: Any = None) -> None:
        # An accepted goal starts executing; one canceled before it started only runs its
        # callback (which then sees is_cancel_requested), as rclpy has it
        if self._state == N.ACCEPTED:
            self._update_state(GoalEvent.EXECUTE)
        self._action_server._run(self, execute_callback)

    def publish_feedback(self, feedback: Any) -> None:
        server = self._action_server
        if not isinstance(feedback, server._action_type.Feedback):
            raise TypeError(f"Expected type {server._action_type.Feedback}, got "
                            f"{type(feedback)}")
        message = server._action_type.Impl.FeedbackMessage(goal_id=self.goal_id,
                                                           feedback=feedback)
        server._feedback.publish(message)

    def succeed(self) -> None:
        self._update_state(GoalEvent.SUCCEED)

    def abort(self) -> None:
        self._update_state(GoalEvent.ABORT)

    def canceled(self) -> None:
        self._update_state(GoalEvent.CANCELED)

    def destroy(self) -> None:
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
        self._type_name = N.action_type_name(action_type)
        self._action_type = rosidl.action_class(self._type_name)
        self.register_goal_callback(goal_callback)
        self.register_handle_accepted_callback(handle_accepted_callback)
        self.register_cancel_callback(cancel_callback)
        self.register_execute_callback(execute_callback)
        self._result_timeout = result_timeout
        self._goals: dict[bytes, ServerGoalHandle] = {}
        self._waiting: dict[bytes, list[Any]] = {}  # result requests of goals not ended
        self._lock = threading.RLock()
        self.callback_group = callback_group or node.default_callback_group
        bus, impl = node.handle, self._action_type.Impl
        self._send_goal = bus.create_service(
            f"{self._type_name}_SendGoal", N.endpoint(action_name, N.SEND_GOAL),
            grouped(node, self.callback_group, self._on_goal), make=rosidl.make,
            new_response=impl.SendGoalService.Response)
        self._send_goal.deferred = True
        self._cancel = bus.create_service(
            N.CANCEL_TYPE, N.endpoint(action_name, N.CANCEL_GOAL),
            grouped(node, self.callback_group, self._on_cancel), make=rosidl.make,
            new_response=impl.CancelGoalService.Response)
        self._get_result = bus.create_service(
            f"{self._type_name}_GetResult", N.endpoint(action_name, N.GET_RESULT),
            self._on_result_request, make=rosidl.make,
            new_response=impl.GetResultService.Response)
        # a result request runs none of the user's code: answered (or kept for the goal's
        # end) on Zenoh's thread, a hand-over to the executor less on every goal's way
        self._get_result.deferred = self._get_result.inline = True
        self._feedback = bus.create_publisher(f"{self._type_name}_FeedbackMessage",
                                              N.endpoint(action_name, N.FEEDBACK), QoS(depth=10))
        self._status = bus.create_publisher(N.STATUS_TYPE, N.endpoint(action_name, N.STATUS),
                                            QoS(depth=1, transient_local=True))
        adopt(node, self)
        from action_msgs.msg import GoalInfo

        self._goal_info = GoalInfo

    # --- callbacks the user gives -------------------------------------------------------------
    def register_goal_callback(self, goal_callback: Any) -> None:
        self._goal_callback = goal_callback or default_goal_callback

    def register_handle_accepted_callback(self, handle_accepted_callback: Any) -> None:
        self._handle_accepted_callback = handle_accepted_callback or \
            default_handle_accepted_callback

    def register_cancel_callback(self, cancel_callback: Any) -> None:
        self._cancel_callback = cancel_callback or default_cancel_callback

    def register_execute_callback(self, execute_callback: Any) -> None:
        if not callable(execute_callback):
            raise TypeError("Failed to register execute callback: not callable")
        self._execute_callback = execute_callback

    # --- goal requests ------------------------------------------------------------------------
    def _on_goal(self, request: Any, reply: Any) -> None:
        self._expire()
        key = N.uuid_key(request.goal_id)
        response = reply.new_response()
        with self._lock:
            duplicate = key in self._goals
        if duplicate:
            self._node.get_logger().warning(f"Received goal request with duplicate ID: "
                                            f"{N.uuid_text(request.goal_id)}")  # (rejected)
            response.accepted = False
            reply.send(response)
            return
        verdict = _resolve(self._goal_callback(request.goal))
        if verdict != GoalResponse.ACCEPT:
            response.accepted = False
            reply.send(response)
            return
        stamp = self._node.get_clock().now().to_msg()
        handle = ServerGoalHandle(self, self._goal_info(goal_id=request.goal_id, stamp=stamp),
                                  request.goal)
        with self._lock:
            self._goals[key] = handle
        response.accepted, response.stamp = True, stamp
        reply.send(response)  # answered first, then handed on (as rclpy does)
        self._publish_status()
        self._handle_accepted_callback(handle)

    def _run(self, handle: ServerGoalHandle, execute_callback: Any) -> None:
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
                handle._update_state(GoalEvent.ABORT)
        if handle.is_active:
            logger.warning(f"Goal state not set, assuming aborted. Goal ID: "
                           f"{N.uuid_text(handle.goal_id)}")
            handle._update_state(GoalEvent.ABORT)
        if result is None:
            result = self._action_type.Result()
        self._finish(handle, result)

    def _finish(self, handle: ServerGoalHandle, result: Any) -> None:
        key = N.uuid_key(handle.goal_id)
        response = self._action_type.Impl.GetResultService.Response(status=handle.status,
                                                                     result=result)
        handle._result_future.set_result(response)
        with self._lock:
            waiting = self._waiting.pop(key, [])
        for reply in waiting:
            reply.send(response)

    # --- result requests (answered when the goal ends) ------------------------------------
    def _on_result_request(self, request: Any, reply: Any) -> None:
        self._expire()
        key = N.uuid_key(request.goal_id)
        with self._lock:
            handle = self._goals.get(key)
            if handle is not None and not handle._result_future.done():
                self._waiting.setdefault(key, []).append(reply)
                return
        if handle is None:
            self._node.get_logger().debug(f"Sending result response for unknown or expired "
                                          f"goal ID: {N.uuid_text(request.goal_id)}")
            reply.send(self._action_type.Impl.GetResultService.Response(status=N.UNKNOWN))
            return
        reply.send(handle._result_future.result())

    # --- cancel requests --------------------------------------------------------------------
    def _on_cancel(self, request: Any, response: Any) -> Any:
        from action_msgs.srv import CancelGoal

        self._expire()
        info = request.goal_info
        key = N.uuid_key(info.goal_id)
        everything = not any(key)
        stamp = info.stamp.sec * 1_000_000_000 + info.stamp.nanosec
        with self._lock:
            goals = list(self._goals.values())
        if not everything:
            named = [g for g in goals if N.uuid_key(g.goal_id) == key]
            if not named:
                response.return_code = CancelGoal.Response.ERROR_UNKNOWN_GOAL_ID
                return response
            if not named[0].is_active:
                response.return_code = CancelGoal.Response.ERROR_GOAL_TERMINATED
                return response
            candidates = named + ([g for g in goals if _stamp(g) <= stamp and g not in named]
                                  if stamp else [])
        elif stamp:
            candidates = [g for g in goals if _stamp(g) <= stamp]
        else:
            candidates = goals
        canceling = []
        for handle in candidates:
            if handle._state not in (N.ACCEPTED, N.EXECUTING):
                continue
            if _resolve(self._cancel_callback(handle)) == CancelResponse.ACCEPT:
                try:
                    handle._update_state(GoalEvent.CANCEL_GOAL)
                except RCLError:
                    continue
                canceling.append(handle._goal_info)
        response.goals_canceling = canceling
        response.return_code = CancelGoal.Response.ERROR_NONE if canceling else \
            CancelGoal.Response.ERROR_REJECTED
        return response

    # --- status -------------------------------------------------------------------------------
    def _publish_status(self) -> None:
        """Every goal kept (terminal ones until their results expire), as rclpy publishes
        them; each goal's entry is made once per state, so a server that has seen many goals
        does not rebuild them all at each change."""
        with self._lock:
            entries = [g._status_cdr() for g in self._goals.values()]
        self._status.publish_raw(status_array_join(entries))

    def _expire(self) -> None:
        """Forget goals whose results have been kept `result_timeout` seconds."""
        now = time.monotonic()
        with self._lock:
            gone = [k for k, g in self._goals.items() if g.ended_at is not None and
                    now - g.ended_at > self._result_timeout]
            for key in gone:
                del self._goals[key]
        if gone:
            self._publish_status()

    def destroy(self) -> None:
        for entity in (self._send_goal, self._cancel, self._get_result, self._feedback,
                       self._status):
            entity.destroy()
        forget(self._node, self)


_COUNT = struct.Struct("<I")
_ENTRY_TAIL = struct.Struct("<iIb")


def status_entry_cdr(uuid: bytes, sec: int, nanosec: int, status: int) -> bytes:
    """One GoalStatus as it sits in a GoalStatusArray after the first entry (every entry
    but the first starts 1 past a multiple of 4, so its stamp is padded by 3)."""
    return uuid + b"\x00\x00\x00" + _ENTRY_TAIL.pack(sec, nanosec, status)


def status_array_join(entries: list[bytes]) -> bytes:
    """action_msgs/GoalStatusArray's CDR (little endian) from status_entry_cdr's entries,
    written directly: a server keeps every goal until its result expires and says them all
    at each change, so this is made often and grows (rcl does it in C)."""
    if not entries:
        return b"\x00\x01\x00\x00" + _COUNT.pack(0)
    first = entries[0]
    return b"".join((b"\x00\x01\x00\x00", _COUNT.pack(len(entries)), first[:16], first[19:],
                     *entries[1:]))


def status_array_cdr(entries: list[tuple[bytes, int, int, int]]) -> bytes:
    """The same from (uuid, sec, nanosec, status) entries."""
    return status_array_join([status_entry_cdr(*e) for e in entries])


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


def _stamp(handle: ServerGoalHandle) -> int:
    stamp = handle._goal_info.stamp
    return stamp.sec * 1_000_000_000 + stamp.nanosec
