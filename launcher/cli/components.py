"""The launch's Loader (runtime/composition.py): it asks containers over the bus.

It joins the graph only when a launch has composable nodes, as a node named
`launch_ros_<pid>` (launch_ros's name for it), from one worker thread per container, so one
slow container does not hold up another. As launch_ros runs each LoadComposableNodes action
on its own, the loads of several actions go to a container at once (IN_FLIGHT at most; the
container makes them at once), each action's own loads in their order: fifty robots' nodes
load in a fraction of the time one after another would take.

launch_ros waits for a container's service for ever, printing nothing; here a container this
launch started is waited for while it runs (its exit fails what it was asked at once), and any
other container for WAIT seconds (LAUNCHER_LOAD_TIMEOUT sets it), after which the error lists
the containers that are running.
"""

from __future__ import annotations

import os
import queue
import threading
import time
from collections.abc import Callable
from typing import Any

from launcher.errors import LaunchError, did_you_mean
from launcher.runtime.composition import Done, LoadRequest

LOAD = "composition_interfaces/srv/LoadNode"
SUFFIX = "/_container/load_node"
WAIT = 30.0  # s for a container not started by this launch to appear
WAIT_VARIABLE = "LAUNCHER_LOAD_TIMEOUT"
ANSWER_WAIT = 75.0  # s for one load's answer (the container gives a constructor 60 s)
CLOSE_WAIT = 3.0  # s the launch's end waits for the workers to leave the bus
IN_FLIGHT = 32  # actions whose loads one container is sent at once (launch_ros's pool's most)


class BusLoader:
    def __init__(self) -> None:
        self._node: Any = None
        self._lock = threading.Lock()
        self._workers: dict[str, queue.SimpleQueue[Any]] = {}
        self._threads: list[threading.Thread] = []
        self._cancelled = threading.Event()

    def load(self, container: str, requests: list[LoadRequest], environment: dict[str, str],
             alive: Callable[[], bool] | None, done: Done) -> None:
        with self._lock:
            work = self._workers.get(container)
            if work is None:
                work = self._workers[container] = queue.SimpleQueue()
                thread = threading.Thread(target=self._serve, args=(container, work),
                                          name=f"load-{container}", daemon=True)
                self._threads.append(thread)
                thread.start()
        work.put((requests, environment, alive, done))

    def cancel(self) -> None:
        self._cancelled.set()

    def close(self) -> None:
        """The workers are stopped (each within a wait's step) before the node goes: one
        still inside a Zenoh call as the interpreter ends would abort the process."""
        self._cancelled.set()
        with self._lock:
            for work in self._workers.values():
                work.put(None)
            threads = list(self._threads)
        deadline = time.monotonic() + CLOSE_WAIT
        for thread in threads:
            thread.join(max(0.0, deadline - time.monotonic()))
        with self._lock:
            node, self._node = self._node, None
        if node is not None:
            node.destroy_node()
            node.session.close()  # (the node was handed it: left open, its threads would
            # call into the interpreter as it ends, and abort the process)
        # A worker still waiting for an answer (a load past the launch's end) is woken by the
        # closed session, and waited for: one inside Zenoh as the interpreter ends aborts it.
        with self._lock:
            threads = list(self._threads)
        for thread in threads:
            thread.join(CLOSE_WAIT)

    # --- the workers ------------------------------------------------------------------------
    def _serve(self, container: str, work: queue.SimpleQueue[Any]) -> None:
        client = None
        gate = threading.Semaphore(IN_FLIGHT)
        while not self._cancelled.is_set():
            item = work.get()
            if item is None:  # (close)
                return
            requests, environment, alive, done = item
            try:
                if client is None:
                    client = self._bus(environment).create_client(LOAD, container + SUFFIX)
                self._wait(client, container, alive, _wait_time(environment))
            except LaunchError as exc:
                for request in requests:
                    done(request, "", exc.message)
                client = None if alive is not None else client
                continue
            except Exception:  # noqa: BLE001 - Zenoh's, once close() has closed the session
                if not self._cancelled.is_set():
                    raise
                return
            gate.acquire()
            self._start(self._load_all, client, requests, done, gate)

    def _start(self, target: Callable[..., None], *args: Any) -> None:
        thread = threading.Thread(target=target, args=args, daemon=True)
        with self._lock:
            self._threads = [t for t in self._threads if t.is_alive()]
            self._threads.append(thread)
        thread.start()

    def _load_all(self, client: Any, requests: list[LoadRequest], done: Done,
                  gate: threading.Semaphore) -> None:
        """One action's loads, in their order."""
        try:
            for request in requests:
                if self._cancelled.is_set():
                    return
                done(request, *self._load(client, request))
        finally:
            gate.release()

    def _bus(self, environment: dict[str, str]) -> Any:
        with self._lock:
            if self._node is None:
                from launcher.bus.node import Node
                from launcher.bus.session import open_session

                self._node = Node(f"launch_ros_{os.getpid()}", argv=[],
                                  session=open_session(environ=environment),
                                  parameter_services=False)
            return self._node

    def _wait(self, client: Any, container: str, alive: Callable[[], bool] | None,
              wait: float) -> None:
        deadline = time.monotonic() + wait
        while not client.wait_for_service(0.1):
            if self._cancelled.is_set():
                raise LaunchError("the launch is ending")
            if alive is not None and not alive():
                raise LaunchError(f"the container '{container}' exited before it loaded it")
            if alive is None and time.monotonic() > deadline:
                running = self._containers()
                raise LaunchError(
                    f"no container named '{container}' answered within {wait:g} s"
                    f"{did_you_mean(container, running)}; containers running: "
                    f"{', '.join(running) or 'none'}")

    def _containers(self) -> list[str]:
        from launcher.bus import graph, keys

        found = graph.entities(self._node.graph_session(), 0.5)
        return sorted({e.topic[:-len(SUFFIX)] for e in found
                       if e.kind == keys.SERVICE and e.topic.endswith(SUFFIX)})

    def _load(self, client: Any, request: LoadRequest) -> tuple[str, str]:
        """(full node name, error)."""
        from launcher.bus import ros_args
        from launcher.bus.parameters import to_message

        try:
            values: dict[str, Any] = {}
            for path in request.param_files:
                values.update(ros_args.load_params_file(path, request.node_name,
                                                        request.namespace))
            values.update(request.parameters)
            node = self._node
            message = node.message(
                LOAD + "_Request", package_name=request.package, plugin_name=request.plugin,
                node_name=request.node_name, node_namespace=request.namespace,
                remap_rules=[f"{a}:={b}" for a, b in request.remaps])
            message.parameters = [_parameter(node, name, to_message(value))
                                  for name, value in values.items()]
            message.extra_arguments = [_parameter(node, name, to_message(value))
                                       for name, value in request.extra_arguments.items()]
            response = client.call(message, timeout=ANSWER_WAIT)
        except LaunchError as exc:
            return "", exc.message
        except Exception:  # noqa: BLE001 - Zenoh's, once close() has closed the session
            if not self._cancelled.is_set():
                raise
            return "", "the launch ended before the container answered"
        if not response.success:
            return "", response.error_message or "the container refused it"
        return response.full_node_name, ""


def _wait_time(environment: dict[str, str]) -> float:
    text = environment.get(WAIT_VARIABLE, "")
    try:
        return max(0.0, float(text)) if text else WAIT
    except ValueError:
        raise LaunchError(f"{WAIT_VARIABLE}={text!r}: expected seconds, e.g. 30") from None


def _parameter(node: Any, name: str, value: Any) -> Any:
    parameter = node.message("rcl_interfaces/msg/Parameter", name=name)
    parameter.value = value
    return parameter
