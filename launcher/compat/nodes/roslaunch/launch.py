"""roslaunch.launch: ROSLaunchRunner, which runs a loaded ROSLaunchConfig. It runs on
launcher's own runtime: the config's files, as `launcher launch` runs them, in a launch
service of launcher's whose loop turns in a thread of its own (so the caller's thread stays
free, as roslaunch's), on the user's graph. Nodes launched later (`launch_node`, scriptapi's)
are scheduled on that loop; shutdown stops everything the launch started."""

from __future__ import annotations

import tempfile
import threading
import time
from pathlib import Path
from typing import Any

from launcher.api import GroupAction, LaunchDescription, OnProcessExit, RegisterEventHandler
from roslaunch.core import (  # noqa: F401 (roslaunch.launch has them)
    PHASE_RUN,
    PHASE_SETUP,
    PHASE_TEARDOWN,
    TEST_TIME_LIMIT_DEFAULT,
    Node,
    RLException,
    printerrlog,
    printlog,
)
from roslaunch.pmon import Process, ProcessListener  # noqa: F401 (roslaunch.launch has it)

NUM_WORKERS = 3
DEFAULT_TIMEOUT_SIGINT = 15.0
DEFAULT_TIMEOUT_SIGTERM = 2.0
FOREVER = 365 * 24 * 3600.0  # s: keeps a launch up that is not to end when its nodes have
SPIN = 0.1  # s between looks while spinning


class RLTestTimeoutException(RLException):
    """A test that ran past its time limit."""


class ROSLaunchListener:
    """Told when a process of the launch dies."""

    def process_died(self, process_name: str, exit_code: int | None) -> None:
        """Process `process_name` has exited with `exit_code`."""


class ROSRemoteRunnerIF:
    """What a runner of another host's nodes offers (launcher has none: see roslaunch.remote)."""

    def setup(self) -> None:
        """Prepare the remote hosts."""

    def add_process_listener(self, l: Any) -> None:  # noqa: E741 (roslaunch's)
        """Tell `l` of remote processes that die."""

    def launch_remote_nodes(self) -> None:
        """Start the remote nodes."""


def validate_master_launch(m: Any, is_core: bool, is_rostest: bool = False) -> None:
    """roslaunch's check of the master's URI: launcher's graph needs no master, so there is
    nothing to check."""


class LaunchedNode(Process):
    """A node the launch runs: the process of launcher's runtime started with its name."""

    def __init__(self, runner: ROSLaunchRunner, node: Node) -> None:
        super().__init__(node.package, node.name or node.type, node.args.split(), {},
                         node.respawn, node.respawn_delay, node.required)
        self.runner, self.node = runner, node

    def is_alive(self) -> bool:
        """Whether it runs (or is about to start)."""
        managed = self.runner.processes_of(self.node)
        for process in managed:
            self.exit_code = process.returncode
        if managed:
            return any(p.alive for p in managed)
        return self.runner.is_running() and self.node.name not in self.runner.exited

    def stop(self, errors: list[str] | None = None) -> None:
        """Stop it (SIGINT, then SIGTERM and SIGKILL as launcher escalates) and wait."""
        for process in self.runner.processes_of(self.node):
            self.runner.call(process.stop)
        deadline = time.monotonic() + DEFAULT_TIMEOUT_SIGINT + DEFAULT_TIMEOUT_SIGTERM
        while self.is_alive() and time.monotonic() < deadline:
            time.sleep(SPIN / 2)


def _node_name(argv: list[str]) -> str | None:
    return next((w[len("__name:="):] for w in argv if w.startswith("__name:=")), None)


class ROSLaunchRunner:
    """Runs a ROSLaunchConfig on launcher's runtime, in a thread of its own."""

    def __init__(self, run_id: str, config: Any, server_uri: str | None = None,
                 pmon: Any = None, is_core: bool = False, remote_runner: Any = None,
                 is_child: bool = False, is_rostest: bool = False,
                 num_workers: int = NUM_WORKERS, timeout: float | None = None,
                 master_logger_level: Any = False,
                 sigint_timeout: float = DEFAULT_TIMEOUT_SIGINT,
                 sigterm_timeout: float = DEFAULT_TIMEOUT_SIGTERM) -> None:
        self.run_id, self.config, self.server_uri, self.pm = run_id, config, server_uri, pmon
        self.is_core, self.is_rostest, self.is_child = is_core, is_rostest, is_child
        self.remote_runner, self.timeout = remote_runner, timeout
        self.sigint_timeout, self.sigterm_timeout = sigint_timeout, sigterm_timeout
        self.listeners: list[Any] = []
        self.auto_terminate = True  # the launch ends once its processes have
        self.service: Any = None
        self.exited: set[str] = set()  # the names of nodes whose process has exited
        self._thread: threading.Thread | None = None
        self._files = tempfile.TemporaryDirectory(prefix="roslaunch-nodes-")
        self._count = 0

    def add_process_listener(self, l: Any) -> None:  # noqa: E741 (roslaunch's)
        """Tell `l` (a ProcessListener) of each process of the launch that dies."""
        self.listeners.append(l)

    def launch(self) -> tuple[list[str], list[str]]:
        """Start the launch; (the names of the nodes it starts, those that failed: none yet,
        as launcher starts them on its loop)."""
        if self._thread is not None:
            raise RLException("the launch is running already")
        from launcher.cli.launch_command import launch_service
        from launcher.cli.workspace import load_index

        arguments: dict[str, str] = {}
        for _, given in self.config.sources:
            arguments.update(given)
        self.service = launch_service(arguments, load_index(), noninteractive=True)
        if not self.auto_terminate:
            self.service.add_timer(FOREVER, lambda: None)
        self.service.loop.open_posting()
        watch = RegisterEventHandler(OnProcessExit(on_exit=self._on_exit))
        whole = LaunchDescription([watch, *(GroupAction(actions=[description])
                                            for description, _ in self.config.sources)])
        self._thread = threading.Thread(target=self.service.run, args=(whole,),
                                        kwargs={"signals": False}, daemon=True,
                                        name=f"roslaunch-{self.run_id}")
        self._thread.start()
        return [f"{n.namespace}{n.name}" for n in self.config.nodes], []

    def _on_exit(self, event: Any, _context: Any = None) -> None:
        self.exited.add(_node_name(event.cmd) or event.process_name)
        for listener in self.listeners:
            listener.process_died(event.process_name, event.returncode)

    def call(self, callback: Any, *args: Any) -> None:
        """Run `callback(*args)` on the launch's loop."""
        if self.service is not None and self.is_running():
            self.service.loop.call_soon_threadsafe(callback, *args)

    def is_running(self) -> bool:
        """Whether the launch is still up."""
        return self._thread is not None and self._thread.is_alive()

    def launch_node(self, node: Node, core: bool = False) -> tuple[Process, bool]:
        """Start `node` in the running launch: (its process, True)."""
        from launcher.frontend.loader import load_file

        if not self.is_running():
            raise RLException("the launch is not running: start it first")
        if not node.name:  # (roslaunch's scriptapi names it after its type)
            node.name = f"{node.type.replace('.', '_')}_{self._count + 1}"
        self._count += 1
        path = Path(self._files.name) / f"node_{self._count}.launch"
        path.write_text(f"<launch>\n{node.to_xml()}\n</launch>\n", encoding="utf-8")
        description = load_file(path)
        self.call(self.service.schedule, [description])
        node.process_name = node.name
        return LaunchedNode(self, node), True

    def processes_of(self, node: Node) -> list[Any]:
        """The processes of launcher's runtime that run `node` (by its name and namespace)."""
        space = node.namespace.rstrip("/")
        return [p for p in (self.service.processes if self.service else [])
                if _node_name(p.spec.argv) == node.name
                and p.spec.env.get("ROS_NAMESPACE", "").rstrip("/") == space]

    def is_node_running(self, node: Node) -> bool:
        """Whether a process of `node` runs."""
        return any(p.alive for p in self.processes_of(node))

    def run_test(self, test: Any) -> None:
        """Run rostest test `test` until it exits; RLTestTimeoutException past its limit."""
        process, _ = self.launch_node(test)
        deadline = time.monotonic() + test.time_limit
        while process.is_alive():
            if time.monotonic() > deadline:
                process.stop()
                raise RLTestTimeoutException(f"max time [{test.time_limit}s] allotted for "
                                             f"test [{test.test_name}] of type "
                                             f"[{test.package}/{test.type}]")
            time.sleep(SPIN)

    def spin_once(self) -> None:
        """Let the launch run a moment (it runs in its own thread)."""
        if self._thread is not None:
            self._thread.join(SPIN)

    def spin(self) -> None:
        """Wait until the launch has ended."""
        while self.is_running():
            self.spin_once()

    def stop(self) -> None:
        """End the launch: every process it started is stopped, and waited for."""
        if self.is_running():
            self.call(self.service.shutdown, "roslaunch's shutdown() was called")
        if self._thread is not None:
            self._thread.join()
        self._files.cleanup()


from launcher.compat.finder import rest_from_layout  # noqa: E402 - the rest of the real module's names

__getattr__ = rest_from_layout(__name__)
