"""rclpy.action.client: ActionClient and ClientGoalHandle, as rclpy behaves.

`send_goal_async` returns a Future of the goal's handle (accepted or not); the handle's
`get_result_async` a Future of the GetResult response (`status`, `result`), answered when the
goal ends; `cancel_goal_async` a Future of the CancelGoal response. Futures are completed by
the node's executor, so done callbacks and awaiting coroutines run there, as in rclpy; the
blocking `send_goal`, `get_result` and `cancel_goal` wait on the calling thread. Feedback for
a goal goes to its `feedback_callback` (the FeedbackMessage, as rclpy passes it); the status
topic keeps each handle's `status` current.
"""

from __future__ import annotations

import threading
import uuid
from collections.abc import Callable
from typing import Any, TypedDict

from launcher.bus import actions
from launcher.bus.qos import QoS
from launcher.compat import rosidl
from rclpy.action import names
from rclpy.clock import Clock  # noqa: F401 - the names rclpy's module offers
from rclpy.custody import adopt, check_alive, forget, grouped, live_host
from rclpy.executors import await_or_execute  # noqa: F401
from rclpy.properties import readonly
from rclpy.qos import QoSProfile  # noqa: F401
from rclpy.service_introspection import ServiceIntrospectionState  # noqa: F401
from rclpy.task import Future, has_executor, wake_on_done
from rclpy.type_support import (  # noqa: F401
    Action,
    FeedbackMessage,
    GetResultServiceResponse,
    SendGoalServiceResponse,
    check_for_type_support,
)
from rclpy.waitable import NumberOfEntities, Waitable  # noqa: F401

# s: a goal or cancel request's answer (rclpy waits for ever; a server busy on a loaded
# machine, a sim stepping, took more than 10 s)
CALL_TIMEOUT = 60.0
RESULT_TIMEOUT = 365 * 24 * 3600.0  # s: a result comes when the goal ends, however long



class SendGoalKWargs(TypedDict):
    """The keywords send_goal takes besides the goal."""

    feedback_callback: Callable[[Any], None] | None
    goal_uuid: Any

class ClientGoalHandle:
    def __init__(self, action_client: ActionClient, goal_id: Any, goal_response: Any) -> None:
        self._action_client = action_client
        self._goal_id = goal_id
        self._goal_response = goal_response
        self._status = actions.UNKNOWN if not goal_response.accepted else actions.ACCEPTED

    def __eq__(self, other: object) -> bool:
        return isinstance(other, ClientGoalHandle) and \
            actions.uuid_key(self._goal_id) == actions.uuid_key(other._goal_id)

    def __hash__(self) -> int:
        return hash(actions.uuid_key(self._goal_id))

    def __repr__(self) -> str:
        return f"ClientGoalHandle <id={self.goal_id.uuid}, accepted={self.accepted}, " \
               f"status={self.status}>"

    goal_id = readonly("_goal_id", "The goal's id (unique_identifier_msgs/UUID).")
    stamp = readonly("_goal_response.stamp", "When the server accepted the goal.")
    status = readonly("_status", "The goal's state as the server's status topic last said it.")

    @property
    def accepted(self) -> bool:
        """Whether the server accepted the goal."""
        return bool(self._goal_response.accepted)

    def cancel_goal(self) -> Any:
        """Ask the server to cancel the goal, waiting for its answer
        (a CancelGoal response).
        """
        return self._action_client._cancel_goal(self)

    def cancel_goal_async(self) -> Future:
        """Ask the server to cancel the goal: a Future of its answer."""
        return self._action_client._cancel_goal_async(self)

    def get_result(self) -> Any:
        """Wait for the goal's result (a GetResult response: status, result)."""
        return self._action_client._get_result(self)

    def get_result_async(self) -> Future:
        """A Future of the goal's result, completed when the goal ends."""
        return self._action_client._get_result_async(self)


class ActionClient:
    def __init__(self, node: Any, action_type: Any, action_name: str, *,
                 callback_group: Any = None, goal_service_qos_profile: Any = None,
                 result_service_qos_profile: Any = None,
                 cancel_service_qos_profile: Any = None, feedback_sub_qos_profile: Any = None,
                 status_sub_qos_profile: Any = None) -> None:
        check_alive(node)
        self._node, self._action_name = node, action_name
        self._type_name = names.action_type_name(action_type)
        self._action_type = rosidl.action_class(self._type_name)
        self.callback_group = callback_group or node.default_callback_group
        bus, name, kind = node.handle, action_name, self._type_name
        self._goal_client = bus.create_client(actions.send_goal_type(kind),
                                              actions.endpoint(name, actions.SEND_GOAL),
                                              make=rosidl.make)
        self._cancel_client = bus.create_client(actions.CANCEL_TYPE,
                                                actions.endpoint(name, actions.CANCEL_GOAL),
                                                make=rosidl.make)
        self._result_client = bus.create_client(actions.get_result_type(kind),
                                                actions.endpoint(name, actions.GET_RESULT),
                                                make=rosidl.make)
        self._feedback_callbacks: dict[bytes, Any] = {}
        self._handles: dict[bytes, ClientGoalHandle] = {}
        self._lock = threading.Lock()
        self._feedback = bus.create_subscription(
            actions.feedback_type(kind), actions.endpoint(name, actions.FEEDBACK),
            grouped(node, self.callback_group, self._on_feedback), QoS(depth=10),
            make=rosidl.make)
        # the status array names every goal the server keeps (hundreds, on a busy one): read
        # as bytes, for the few goals of this client, not made into messages each time
        self._status = bus.create_subscription(
            actions.STATUS_TYPE, actions.endpoint(name, actions.STATUS), self._on_status,
            QoS(depth=1, transient_local=True), raw=True, inline=True)
        adopt(node, self)

    # --- the server -----------------------------------------------------------------------------
    def server_is_ready(self) -> bool:
        """Whether the server's three services are on the graph now."""
        return all(client.wait_for_service(0.05)
                   for client in (self._goal_client, self._cancel_client, self._result_client))

    def wait_for_server(self, timeout_sec: float | None = None) -> bool:
        """Whether the server's three services are there, waiting up to `timeout_sec` (None:
        as long as it takes, while the context is up)."""
        import time

        deadline = None if timeout_sec is None else time.monotonic() + timeout_sec
        for client in (self._goal_client, self._cancel_client, self._result_client):
            while True:
                left = 1.0 if deadline is None else deadline - time.monotonic()
                if left <= 0:
                    return False
                if client.wait_for_service(min(left, 1.0)):
                    break
                if not self._node.context.ok():
                    return False
        return True

    # --- goals --------------------------------------------------------------------------------
    def send_goal_async(self, goal: Any, feedback_callback: Any = None,
                        goal_uuid: Any = None) -> Future:
        """Send a goal: a Future of its ClientGoalHandle (accepted or not).

        :param goal: the action's Goal.
        :param feedback_callback: called with each FeedbackMessage for this goal.
        :param goal_uuid: the goal's id (default: a new random one).
        """
        if not isinstance(goal, self._action_type.Goal):
            raise TypeError(f"Expected type {self._action_type.Goal}, got {type(goal)}")
        from unique_identifier_msgs.msg import UUID

        goal_id = goal_uuid if goal_uuid is not None else UUID(uuid=list(uuid.uuid4().bytes))
        key = actions.uuid_key(goal_id)
        if feedback_callback is not None:
            with self._lock:
                self._feedback_callbacks[key] = feedback_callback
        request = self._action_type.Impl.SendGoalService.Request(goal_id=goal_id, goal=goal)

        def handle(response: Any) -> ClientGoalHandle:
            found = ClientGoalHandle(self, goal_id, response)
            with self._lock:
                if found.accepted:
                    self._handles[key] = found
                else:
                    self._feedback_callbacks.pop(key, None)
            return found
        return self._call_async(self._goal_client, request, CALL_TIMEOUT, handle)

    def send_goal(self, goal: Any, **kwargs: Any) -> Any:
        """Send a goal and wait for its result (the GetResult response); None if rejected."""
        handle = self._wait(self.send_goal_async(goal, **kwargs))
        if not handle.accepted:
            return None
        return self._get_result(handle)

    def _get_result_async(self, goal_handle: ClientGoalHandle) -> Future:
        if not goal_handle.accepted:
            raise TypeError("Goal was not accepted")
        request = self._action_type.Impl.GetResultService.Request(goal_id=goal_handle.goal_id)

        def done(response: Any) -> Any:
            goal_handle._status = response.status
            with self._lock:
                key = actions.uuid_key(goal_handle.goal_id)
                self._feedback_callbacks.pop(key, None)
                self._handles.pop(key, None)
            return response
        return self._call_async(self._result_client, request, RESULT_TIMEOUT, done)

    def _get_result(self, goal_handle: ClientGoalHandle) -> Any:
        return self._wait(self._get_result_async(goal_handle))

    def _cancel_goal_async(self, goal_handle: ClientGoalHandle) -> Future:
        if not goal_handle.accepted:
            raise TypeError("Goal was not accepted")
        from action_msgs.msg import GoalInfo
        from action_msgs.srv import CancelGoal

        request = CancelGoal.Request(goal_info=GoalInfo(goal_id=goal_handle.goal_id))
        return self._call_async(self._cancel_client, request, CALL_TIMEOUT, lambda r: r)

    def _cancel_goal(self, goal_handle: ClientGoalHandle) -> Any:
        return self._wait(self._cancel_goal_async(goal_handle))

    # --- topics ---------------------------------------------------------------------------------
    def _on_feedback(self, message: Any) -> None:
        with self._lock:
            callback = self._feedback_callbacks.get(actions.uuid_key(message.goal_id))
        if callback is not None:
            callback(message)

    def _on_status(self, payload: bytes) -> None:
        with self._lock:
            if not self._handles:
                return
            for uuid, status in actions.statuses(payload):
                handle = self._handles.get(uuid)
                if handle is not None:
                    handle._status = status

    # --- calls ----------------------------------------------------------------------------------
    def _call_async(self, client: Any, request: Any, timeout: float, shape: Any) -> Future:
        """A Future completed on the node's executor with `shape(response)` (the answer
        comes on Zenoh's thread and is handed to the executor: no thread per call)."""
        future = Future(executor=self._node.executor)
        host = live_host(self._node)

        def finish(response: Any, error: Any) -> None:
            if error is None:
                try:
                    future.set_result(shape(response))
                except Exception as exc:
                    future.set_exception(exc)
            else:
                future.set_exception(error)

        def done(response: Any, error: Any) -> None:
            # A future with an executor runs its done callbacks there whoever completes it:
            # completed here, on Zenoh's thread, it wakes a blocking wait a hand-over sooner
            if has_executor(future) or host is None:
                finish(response, error)
            else:
                host.enqueue(finish, response, error)
        client.call_then(request, timeout, done)
        return future

    def _wait(self, future: Future) -> Any:
        """The future's result, waited for on this thread (the executor completes it: it
        must be spinning elsewhere, as rclpy requires for its blocking calls)."""
        event = threading.Event()
        wake_on_done(future, event)
        if self._node.executor is None:  # nobody spins: complete it here
            while not event.wait(0.01):
                live_host(self._node) and self._drain()
        else:
            event.wait()
        return future.result()

    def _drain(self) -> None:
        host = live_host(self._node)
        while host is not None:
            work = host.next_work(0)
            if work is None:
                return
            callback, args = work
            callback(*args)

    def destroy(self) -> None:
        """Take the client's services and subscriptions off the graph."""
        for entity in (self._goal_client, self._cancel_client, self._result_client,
                       self._feedback, self._status):
            entity.destroy()
        forget(self._node, self)

