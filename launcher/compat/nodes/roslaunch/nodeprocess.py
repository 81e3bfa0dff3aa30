"""roslaunch.nodeprocess: LocalProcess, a process on this host that roslaunch code starts and
stops itself (its own session; stop is SIGINT, then SIGTERM, then SIGKILL to its group, as
launcher's runtime escalates). The processes of a launch are launcher's runtime's own
(roslaunch.launch); this is for code that makes Processes by hand."""

from __future__ import annotations

import os
import signal
import subprocess
import time
from typing import Any

from roslaunch.core import (  # noqa: F401 (roslaunch.nodeprocess has them)
    PHASE_RUN,
    PHASE_SETUP,
    PHASE_TEARDOWN,
    TEST_TIME_LIMIT_DEFAULT,
    RLException,
    printerrlog,
    printlog,
    setup_env,
)
from roslaunch.node_args import create_local_process_args
from roslaunch.pmon import FatalProcessLaunch, Process

NUM_WORKERS = 3
DEFAULT_TIMEOUT_SIGINT = 15.0
DEFAULT_TIMEOUT_SIGTERM = 2.0


class LocalProcess(Process):
    """A process on this host, started by start() and stopped by stop()."""

    def __init__(self, run_id: str, package: str, name: str, args: list[str],
                 env: dict[str, str], log_output: bool, respawn: bool = False,
                 respawn_delay: float = 0.0, required: bool = False, cwd: str | None = None,
                 is_node: bool = True, sigint_timeout: float = DEFAULT_TIMEOUT_SIGINT,
                 sigterm_timeout: float = DEFAULT_TIMEOUT_SIGTERM) -> None:
        super().__init__(package, name, args, env, respawn, respawn_delay, required)
        self.run_id, self.log_output, self.cwd, self.is_node = run_id, log_output, cwd, is_node
        self.sigint_timeout, self.sigterm_timeout = sigint_timeout, sigterm_timeout
        self.popen: subprocess.Popen | None = None
        self.pid = -1

    def start(self) -> None:
        """Start it, in a session of its own."""
        super().start()
        output = subprocess.DEVNULL if self.log_output else None
        try:
            self.popen = subprocess.Popen(self.args, env=self.env, cwd=self.cwd,
                                          stdout=output, stderr=output,
                                          start_new_session=True)
        except OSError as exc:
            raise FatalProcessLaunch(f"Unable to launch [{self.name}]: {exc}") from None
        self.pid = self.popen.pid

    def is_alive(self) -> bool:
        """Whether it runs."""
        if self.popen is None:
            return False
        self.exit_code = self.popen.poll()
        return self.exit_code is None

    def stop(self, errors: list[str] | None = None) -> None:
        """Stop it and its group: SIGINT, then SIGTERM, then SIGKILL."""
        if self.popen is None:
            return
        for sig, wait in ((signal.SIGINT, self.sigint_timeout),
                          (signal.SIGTERM, self.sigterm_timeout), (signal.SIGKILL, 5.0)):
            if not self.is_alive():
                break
            try:
                os.killpg(self.popen.pid, sig)
            except ProcessLookupError:
                break
            deadline = time.monotonic() + wait
            while self.is_alive() and time.monotonic() < deadline:
                time.sleep(0.02)
        self.time_of_death = time.time()

    def get_info(self) -> dict[str, Any]:
        """Process.get_info, with its pid."""
        return {**super().get_info(), "pid": self.pid}


def create_master_process(run_id: str, type_: str, ros_root: str, port: int,
                          num_workers: int = NUM_WORKERS, timeout: float | None = None,
                          master_logger_level: Any = False,
                          sigint_timeout: float = DEFAULT_TIMEOUT_SIGINT,
                          sigterm_timeout: float = DEFAULT_TIMEOUT_SIGTERM) -> LocalProcess:
    """roslaunch's rosmaster process: launcher's graph has no master to start."""
    raise RLException("launcher's graph has no ROS 1 master to start (it needs none: its "
                      "router starts with the first node)")


def create_node_process(run_id: str, node: Any, master_uri: str,
                        sigint_timeout: float = DEFAULT_TIMEOUT_SIGINT,
                        sigterm_timeout: float = DEFAULT_TIMEOUT_SIGTERM) -> LocalProcess:
    """A LocalProcess for roslaunch Node `node` (not started)."""
    if node.machine is None:
        raise RLException(f"Internal error: no machine selected for node of type "
                          f"[{node.package}/{node.type}]")
    env = setup_env(node, node.machine, master_uri)
    args = create_local_process_args(node, node.machine)
    executable = args[len((node.launch_prefix or "").split())]
    return LocalProcess(run_id, node.package, node.name or node.type, args, env,
                        node.output != "screen", respawn=node.respawn,
                        respawn_delay=node.respawn_delay, required=node.required,
                        cwd=os.path.dirname(executable) if node.cwd == "node" else None,
                        sigint_timeout=sigint_timeout, sigterm_timeout=sigterm_timeout)


from launcher.compat.finder import rest_from_layout  # noqa: E402 - the rest of the real module's names

__getattr__ = rest_from_layout(__name__)
