"""rclpy.client.Client over launcher's bus client.

`call_async` returns a Future completed by the node's executor (so its done callbacks and
awaiting coroutines run there, as in rclpy); `call` waits for the answer on the calling thread
without needing an executor spinning elsewhere (rclpy's `call` deadlocks in a callback: this
one does not)."""

from __future__ import annotations

import threading
from typing import Any

from rclpy.callback_groups import CallbackGroup  # noqa: F401 - as rclpy's module offers it
from rclpy.clock import Clock  # noqa: F401
from rclpy.context import Context
from rclpy.custody import live_host
from rclpy.qos import QoSProfile  # noqa: F401
from rclpy.service import ServiceNames
from rclpy.service_introspection import ServiceIntrospectionState  # noqa: F401
from rclpy.task import Future
from rclpy.type_support import Srv  # noqa: F401

CALL_TIMEOUT = 3600.0  # s, the longest a call waits for its answer unless told


class Client(ServiceNames):
    def __init__(self, context: Context, client_impl: Any, srv_type: Any, srv_name: str,
                 qos_profile: Any, callback_group: Any, *, node: Any = None) -> None:
        """`client_impl`: launcher's bus client; `node`: the Node whose executor completes
        its futures (Node.create_client gives both)."""
        self.context, self._node, self._bus, self.srv_type = context, node, client_impl, \
            srv_type
        self.callback_group, self.qos_profile = callback_group, qos_profile
        self._pending: set[Future] = set()

    def _check(self, request: Any) -> Any:
        if type(request) is not self.srv_type.Request:
            raise TypeError(f"Request must be instance of {self.srv_type.Request}, "
                            f"got {type(request)}")
        return request

    @property
    def _introspection(self) -> Any:
        found = self.__dict__.get("_introspection_made")
        if found is None:
            from rclpy.service_introspection import Introspection

            found = self.__dict__["_introspection_made"] = Introspection(
                self._node, self._bus.name, self.srv_type, self._bus.gid)
        return found

    def configure_introspection(self, clock: Any, service_event_qos_profile: Any,
                                introspection_state: Any) -> None:
        """Publish this client's events on `<name>/_service_event`, as rclpy's."""
        self._introspection.configure(clock, service_event_qos_profile, introspection_state)

    def call(self, request: Any, timeout_sec: float | None = None) -> Any:
        """Call the service and wait for its response (the executor need not spin);
        LaunchError after `timeout_sec` seconds.
        """
        from rclpy.service_introspection import REQUEST_SENT, RESPONSE_RECEIVED

        sequence = self._introspection.next_sequence()
        self._introspection.say(REQUEST_SENT, sequence, request=request)
        response = self._bus.call(self._check(request),
                                  CALL_TIMEOUT if timeout_sec is None else timeout_sec)
        self._introspection.say(RESPONSE_RECEIVED, sequence, response=response)
        return response

    def call_async(self, request: Any) -> Future:
        """Call the service: a Future of its response, completed on the node's
        executor.
        """
        payload = self._check(request)
        future = Future(executor=self._node.executor)
        self._pending.add(future)
        host = live_host(self._node)

        def finish(method: Any, value: Any) -> None:
            self._pending.discard(future)
            method(value)

        from rclpy.service_introspection import REQUEST_SENT, RESPONSE_RECEIVED

        sequence = self._introspection.next_sequence()
        self._introspection.say(REQUEST_SENT, sequence, request=payload)

        def run() -> None:
            try:
                answer = self._bus.call(payload, CALL_TIMEOUT)
                self._introspection.say(RESPONSE_RECEIVED, sequence, response=answer)
                outcome: tuple[Any, Any] = (future.set_result, answer)
            except Exception as exc:  # the caller sees it from future.result()
                outcome = (future.set_exception, exc)
            if host is not None:
                host.enqueue(finish, *outcome)  # completed by the executor
            else:
                finish(*outcome)
        threading.Thread(target=run, daemon=True).start()
        return future

    def remove_pending_request(self, future: Future) -> None:
        """Forget a call's Future (its response, if it comes, is dropped)."""
        self._pending.discard(future)

    def service_is_ready(self) -> bool:
        """Whether a server of the service is on the graph now."""
        return self._bus.wait_for_service(0.05)

    def wait_for_service(self, timeout_sec: float | None = None) -> bool:
        """Wait until a server is on the graph: True, or False after
        `timeout_sec` seconds (None: as long as it takes).
        """
        if timeout_sec is None:
            while not self._bus.wait_for_service(1.0):
                if not self.context.ok():
                    return False
            return True
        return self._bus.wait_for_service(max(timeout_sec, 0.0))

    def destroy(self) -> None:
        """Take the client off the graph."""
        self._bus.destroy()

    @property
    def handle(self) -> Any:
        """The launcher bus client under this one."""
        return self._bus
