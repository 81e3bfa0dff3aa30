"""A running launch on its graph (runtime/control.py's face): a node of the launch's own,
`_launcher_<pid>` (hidden, as ROS 2 hides a name that begins with `_`), whose services
`launcher ps`, `stop`, `start`, `restart`, `logs` and the viewer's processes page call. It is
on the graph only, behind the graph's token, as every node is; a request that says it comes
from another user is refused.

Its requests arrive on the node's own thread and are answered on the launch's loop (no state
of the launch is touched elsewhere); a launch busy for more than ANSWER_WAIT, or ending, says
so instead of holding the asker.
"""

from __future__ import annotations

import os
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from launcher.bus import discovery
from launcher.bus.launches import CONTROL, LIST, OUTPUT
from launcher.errors import LaunchError
from launcher.runtime.control import ProcessControl, Refused

ANSWER_WAIT = 5.0  # seconds a request waits for the launch's loop
CLOSE_WAIT = 2.0  # seconds the launch's end waits for the node's thread (once it serves)
MOST_LINES = 5000  # lines one output answer carries at most


def node_name(pid: int | None = None) -> str:
    return f"_launcher_{os.getpid() if pid is None else pid}"


class LaunchControl:
    """Serves `control` on the graph from a thread of its own, until `close()`."""

    def __init__(self, control: ProcessControl, environment: dict[str, str],
                 file: Path | None, log_folder: Path | None) -> None:
        self.control, self.environment = control, environment
        self.file, self.log_folder = file, log_folder
        self._node: Any = None
        self._lock = threading.Lock()
        self._closed = threading.Event()
        self._thread = threading.Thread(target=self._serve, name="launch-control",
                                        daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        try:
            from launcher.bus.node import Node
            from launcher.bus.session import open_session

            session = open_session("client", environ=self.environment)
        except LaunchError as exc:  # (no graph: the launch runs on without the control)
            self.control.loop.call_soon_threadsafe(
                self.control.log, "WARN", "launch",
                f"`launcher ps` and its kin cannot reach this launch: {exc.message}")
            return
        node = Node(node_name(), argv=[], session=session, parameter_services=False)
        node.create_service(LIST, "~/list_processes", self._list)
        node.create_service(CONTROL, "~/control_process", self._act)
        node.create_service(OUTPUT, "~/process_output", self._output)
        with self._lock:
            if self._closed.is_set():  # (the launch ended while this opened: gone at once)
                node.destroy_node()
                session.close()
                return
            self._node = node
        node.spin()

    def close(self) -> None:
        """The node goes. A thread still opening its session (a router slow to answer) is
        waited for as long as the session's own wait, so nothing is left inside Zenoh as the
        interpreter ends."""
        with self._lock:
            self._closed.set()
            node = self._node
        if node is not None:
            node.shutdown()
        self._thread.join(CLOSE_WAIT if node is not None else
                          discovery.timeout(self.environment) + 1.0)
        if node is not None:
            node.destroy_node()
            node.session.close()  # (see components.BusLoader.close)

    # --- the services (on the node's thread) ----------------------------------------------------
    def _on_loop(self, work: Callable[[], Any]) -> tuple[bool, Any]:
        """(True, what `work()` returned) on the launch's loop, or (False, why not)."""
        box: list[tuple[bool, Any]] = []
        done = threading.Event()

        def run() -> None:
            try:
                box.append((True, work()))
            except Refused as exc:
                box.append((False, str(exc)))
            except Exception as exc:  # noqa: BLE001 - a fault of its own: said, the launch on
                box.append((False, f"internal error: {type(exc).__name__}: {exc}"))
            finally:
                done.set()

        if self._closed.is_set() or not self.control.loop.call_soon_threadsafe(run):
            return False, "the launch is ending"
        deadline = time.monotonic() + ANSWER_WAIT
        while not done.wait(0.1):  # (in slices: the launch's end does not wait on it)
            if self._closed.is_set():
                return False, "the launch is ending"
            if time.monotonic() > deadline:
                return False, f"the launch did not answer within {ANSWER_WAIT:g} s"
        return box[0]

    def _list(self, _request: Any, response: Any) -> Any:
        ok, rows_or_why = self._on_loop(self.control.rows)
        response.launch = self.file.name if self.file else ""
        response.file = str(self.file or "")
        response.pid, response.uid, response.host = os.getpid(), os.getuid(), self.control.host
        response.log_folder = str(self.log_folder or "")
        response.uptime = self.control.loop.time() - self.control.started
        if ok:
            message = self._node.message
            response.processes = [message(
                "launcher_interfaces/msg/Process", name=r.name, names=r.names, node=r.node,
                pid=r.pid, host=r.host, state=r.state, has_exit_code=r.exit_code is not None,
                exit_code=r.exit_code or 0, restarts=r.restarts, uptime=r.uptime, cpu=r.cpu,
                memory=r.memory) for r in rows_or_why]
        else:
            response.message = rows_or_why
        return response

    def _act(self, request: Any, response: Any) -> Any:
        ok, said = self._on_loop(lambda: self.control.act(request.verb, request.name,
                                                          request.uid))
        response.success, response.message = ok, said
        return response

    def _output(self, request: Any, response: Any) -> Any:
        ok, said = self._on_loop(lambda: self.control.output(request.name, request.after))
        response.success = ok
        if not ok:
            response.message = said
            return response
        first, lines = said
        lines = lines[-MOST_LINES:]
        response.first = first
        response.last = lines[-1].number if lines else request.after
        response.streams = [line.stream for line in lines]
        response.stamps = [line.stamp for line in lines]
        response.lines = [line.text for line in lines]
        return response


def serving(environment: dict[str, str], file: Path | None,
            log_folder: Callable[[], Path | None]) -> Callable[[ProcessControl],
                                                               Callable[[], None]]:
    """LaunchService's `serve_control`: the control on the graph, and what ends it."""
    def serve(control: ProcessControl) -> Callable[[], None]:
        return LaunchControl(control, environment, file, log_folder()).close

    return serve
