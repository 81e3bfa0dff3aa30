"""Services: a server answers on a queryable; a client calls with a Zenoh get.

Requests and responses are CDR of `<pkg>/srv/<Name>_Request` / `_Response`; keys use the
service type's ROS 2 hash (see interfaces.py). A server's callback runs on its node's
executor, like every other callback; a failing callback answers the caller with an error.
"""

from __future__ import annotations

import itertools
import os
import threading
import time
from collections.abc import Callable
from typing import Any

import zenoh

from launcher.bus import graph, keys
from launcher.bus.host import Host, direct
from launcher.bus.qos import QoS
from launcher.bus.types import registry
from launcher.errors import LaunchError


class Service:
    """Answers requests: `callback(request, response) -> response`, run by the executor.
    `make` and `new_response` give requests and responses of other classes (rclpy's, see
    TypeRegistry.deserialize). Given its `type_hash` (a fixed type's, like the parameter
    services every node offers), the type's definitions are read at the first request, not at
    the node's start."""

    def __init__(self, host: Host, type_name: str, name: str,
                 callback: Any, space: keys.Space | None = None,
                 make: Callable[[str, list[Any]], Any] | None = None,
                 new_response: Callable[[], Any] | None = None,
                 type_hash: str | None = None) -> None:
        types = registry()
        self.type_name = type_name
        self._halves: tuple[str, str] | None = None
        if type_hash is None:  # an unknown type is an error now
            self._halves = types.service(type_name)
            type_hash = types.service_hash(type_name)
        self.name, self._host, self._callback = name, host, callback
        self._make = make
        self._new_response = new_response or (lambda: types.message_class(
            self.response_type)(**_zero_fields(self.response_type)))
        space = space or host.space
        key = keys.service_key(keys.domain(), name, type_name, type_hash, space)
        self._queryable = host.session.declare_queryable(key, direct(self._on_query))
        self._token = host.announce(keys.SERVICE, name, type_name, type_hash, QoS().key(),
                                    space)

    def _types(self) -> tuple[str, str]:
        """(request type, response type), looked up at the first need."""
        if self._halves is None:
            self._halves = registry().service(self.type_name)
        return self._halves

    @property
    def request_type(self) -> str:
        return self._types()[0]

    @property
    def response_type(self) -> str:
        return self._types()[1]

    def new_response(self) -> Any:
        """An empty response of the service's type, to fill."""
        return self._new_response()

    def _on_query(self, query: zenoh.Query) -> None:
        if self.inline:
            self._answer(query)
        else:
            self._host.enqueue(self._answer, query)

    inline = False  # answered on Zenoh's thread, not the executor (no user code in it)

    def _answer(self, query: zenoh.Query) -> None:
        types = registry()
        try:
            request = types.deserialize(query.payload.to_bytes(), self.request_type,
                                        self._make)
            if self.deferred:  # the callback keeps the reply to send it when it can
                self._callback(request, Reply(self, query))
                return
            response = self._callback(request, self._new_response())
            query.reply(query.key_expr, types.serialize(response, self.response_type),
                        attachment=query.attachment)
        except Exception as exc:  # the caller gets an error, the node goes on
            self._host.logger.error(f"service {self.name}: {type(exc).__name__}: {exc}")
            query.reply_err(f"{type(exc).__name__}: {exc}".encode())

    deferred = False  # callback(request, Reply): the response is sent later (an action's result)

    def destroy(self) -> None:
        self._host.drop(self, self._queryable, self._token)


class Reply:
    """A request's reply to come, for a deferred service: `send(response)` answers the caller
    (once; it may be from any thread), `new_response()` makes one to fill."""

    def __init__(self, service: Service, query: zenoh.Query) -> None:
        self._service, self._query = service, query
        self._lock = threading.Lock()

    def new_response(self) -> Any:
        return self._service.new_response()

    def send(self, response: Any) -> bool:
        """Answer the caller; False if it was answered already."""
        with self._lock:
            query, self._query = self._query, None
        if query is None:
            return False
        try:
            query.reply(query.key_expr,
                        registry().serialize(response, self._service.response_type),
                        attachment=query.attachment)
        finally:
            query.drop()  # (the caller's get ends here)
        return True


class Client:
    """Calls a service: `call(request, timeout)` waits; `call_async` returns a Future."""

    def __init__(self, host: Host, type_name: str, name: str,
                 space: keys.Space | None = None,
                 make: Callable[[str, list[Any]], Any] | None = None) -> None:
        types = registry()
        self.type_name, self.name, self._host, self._make = type_name, name, host, make
        self.request_type, self.response_type = types.service(type_name)
        self.space = space or host.space
        self._key = keys.service_key(keys.domain(), name, type_name, types.service_hash(type_name),
                                     self.space)
        self._token = host.announce(keys.CLIENT, name, type_name, types.service_hash(type_name),
                                    QoS().key(), self.space)
        self._sequence = itertools.count(1)
        self.gid = os.urandom(16)  # its calls' source (service introspection tells it)

    def call(self, request: Any, timeout: float = 5.0) -> Any:
        """The response, waiting up to `timeout`. A query that no server matched ends at once
        (a session just opened may not yet know of a server that exists): it is sent again
        until one answers or the time is up, so a call right after start waits for the
        service as `ros2 service call` does. A server that got it never gets it twice."""
        types = registry()
        answer = self.call_raw(types.serialize(request, self.request_type), timeout)
        return types.deserialize(answer, self.response_type, self._make)

    def call_raw(self, payload: bytes, timeout: float = 5.0) -> bytes:
        """`call` with the request's CDR bytes: the response's (as a bridge passes them)."""
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            attachment = keys.attachment(next(self._sequence), time.time_ns(), self.gid)
            replies = self._host.session.get(self._key, payload=payload, attachment=attachment,
                                             timeout=max(left, 0.001))
            for reply in replies:
                if reply.ok is not None:
                    return reply.ok.payload.to_bytes()
                raise LaunchError(f"service {self.name} failed: "
                                  f"{reply.err.payload.to_bytes().decode(errors='replace')}")
            if deadline - time.monotonic() < 0.05:
                raise LaunchError(f"service {self.name} did not answer within {timeout:g} s "
                                  "(is its server running?)")
            time.sleep(0.05)

    def call_then(self, request: Any, timeout: float, done: Callable[[Any, Any], None]
                  ) -> None:
        """Send the request and return at once; `done(response, None)` or `done(None, error)`
        comes on Zenoh's thread when the server answers (or the time is up): no thread is
        made per call. A query no server matched yet is not sent again (use `call` for the
        first one after start, or wait for the service first)."""
        types = registry()
        payload = types.serialize(request, self.request_type)
        attachment = keys.attachment(next(self._sequence), time.time_ns(), self.gid)
        answered: list[bool] = []

        def on_reply(reply: Any) -> None:
            if answered:
                return
            answered.append(True)
            if reply.ok is not None:
                try:
                    done(types.deserialize(reply.ok.payload.to_bytes(), self.response_type,
                                           self._make), None)
                except Exception as exc:  # a malformed answer is the caller's error
                    done(None, exc)
            else:
                done(None, LaunchError(
                    f"service {self.name} failed: "
                    f"{reply.err.payload.to_bytes().decode(errors='replace')}"))

        def on_end() -> None:
            if not answered:
                answered.append(True)
                done(None, LaunchError(f"service {self.name} did not answer within "
                                       f"{timeout:g} s (is its server running?)"))
        self._host.session.get(self._key, zenoh.handlers.Callback(on_reply, on_end,
                                                                   indirect=False),
                               payload=payload, attachment=attachment, timeout=timeout)

    def call_async(self, request: Any, timeout: float = 5.0) -> Future:
        future = Future()

        def run() -> None:
            try:
                future.set_result(self.call(request, timeout))
            except LaunchError as exc:
                future.set_exception(exc)

        threading.Thread(target=run, daemon=True).start()
        return future

    def wait_for_service(self, timeout: float = 5.0) -> bool:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            # (a server of another type by that name would not answer: not counted)
            if graph.servers(self._host.graph_session(), self.name, self.type_name, 0.5,
                             self.space):
                return True
            time.sleep(0.05)
        return False

    def destroy(self) -> None:
        self._host.drop(self, self._token)


class Future:
    def __init__(self) -> None:
        self._done = threading.Event()
        self._result: Any = None
        self._error: BaseException | None = None

    def set_result(self, value: Any) -> None:
        self._result = value
        self._done.set()

    def set_exception(self, error: BaseException) -> None:
        self._error = error
        self._done.set()

    def done(self) -> bool:
        return self._done.is_set()

    def result(self, timeout: float | None = None) -> Any:
        if not self._done.wait(timeout):
            raise TimeoutError("the call has not finished")
        if self._error is not None:
            raise self._error
        return self._result


def _zero_fields(type_name: str) -> dict[str, Any]:
    from launcher.bus.messages import build

    message = build(type_name, {})
    return {name: getattr(message, name) for name in message.__dataclass_fields__
            if name != "__msgtype__"}
