"""The launch's Lifecycle (runtime/lifecycle.py) over the bus: a node of the launch's own
subscribes to each lifecycle node's `~/transition_event` and calls its `~/change_state`
(lifecycle_msgs), each request on a thread of its own, waiting for the service up to
LAUNCHER_LOAD_TIMEOUT (as loads of composable nodes do)."""

from __future__ import annotations

import os
import threading
import time
from collections.abc import Callable
from typing import Any

from launcher.errors import LaunchError
from launcher.runtime.lifecycle import Done

WAIT = 30.0  # s for a lifecycle node's service to appear (LAUNCHER_LOAD_TIMEOUT)


class BusLifecycle:
    def __init__(self, environment: dict[str, str]) -> None:
        self._environment = environment
        self._node: Any = None
        self._lock = threading.Lock()
        self._closed = threading.Event()

    def _bus(self) -> Any:
        with self._lock:
            if self._node is None:
                from launcher.bus.node import Node
                from launcher.bus.session import open_session

                self._node = Node(f"launch_ros_lifecycle_{os.getpid()}", argv=[],
                                  session=open_session(environ=self._environment),
                                  parameter_services=False)
            return self._node

    def watch(self, node: str, seen: Callable[..., None]) -> None:
        def on_event(message: Any) -> None:
            seen(message.start_state.label, message.goal_state.label, message)

        self._bus().create_subscription("lifecycle_msgs/msg/TransitionEvent",
                                        f"{node}/transition_event", on_event, qos=10,
                                        inline=True)

    def change_state(self, node: str, transition: int, done: Done) -> None:
        threading.Thread(target=self._change, args=(node, transition, done), daemon=True,
                         name=f"lifecycle-{node}").start()

    def _change(self, node: str, transition: int, done: Done) -> None:
        bus = self._bus()
        client = bus.create_client("lifecycle_msgs/srv/ChangeState", f"{node}/change_state")
        try:
            wait = float(self._environment.get("LAUNCHER_LOAD_TIMEOUT", WAIT))
            deadline = time.monotonic() + wait
            while not client.wait_for_service(0.1):
                if self._closed.is_set():
                    return
                if time.monotonic() > deadline:
                    done(f"no {node}/change_state service answered within {wait:g} s (is "
                         "it a lifecycle node, and is it running?)")
                    return
            request = bus.message("lifecycle_msgs/srv/ChangeState_Request")
            request.transition.id = transition
            answer = client.call(request, wait)
            done("" if answer.success else "the node refused it (not allowed from its "
                                               "current state, or its callback failed)")
        except LaunchError as exc:
            done(exc.message)
        finally:
            client.destroy()

    def close(self) -> None:
        self._closed.set()
        with self._lock:
            node, self._node = self._node, None
        if node is not None:
            node.destroy_node()
            node.session.close()  # (the node was handed it; see components.BusLoader.close)
