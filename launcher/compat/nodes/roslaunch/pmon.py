"""roslaunch.pmon: a launched process as roslaunch hands it out (Process), what hears of a
process's death (ProcessListener), and a small ProcessMonitor of Processes. The processes of a
launch are supervised by launcher's runtime (respawn, escalation, custody); these are the
faces ROS 1 code holds."""

from __future__ import annotations

import threading
from typing import Any

from roslaunch.core import RLException, printerrlog, printlog, printlog_bold  # noqa: F401

POLL = 0.1  # s between a monitor's looks at its processes


class FatalProcessLaunch(RLException):
    """A process that must run could not be started."""


class ProcessListener:
    """Told when a process of the launch dies."""

    def process_died(self, process_name: str, exit_code: int | None) -> None:
        """Process `process_name` has exited with `exit_code`."""


class Process:
    """A process of the launch: its name, command line and environment, and its life."""

    def __init__(self, package: str, name: str, args: list[str], env: dict[str, str],
                 respawn: bool = False, respawn_delay: float = 0.0,
                 required: bool = False) -> None:
        self.package, self.name, self.args, self.env = package, name, list(args), dict(env)
        self.respawn, self.respawn_delay, self.required = respawn, respawn_delay, required
        self.lock = threading.Lock()
        self.exit_code: int | None = None
        self.spawn_count = 0
        self.time_of_death: float | None = None

    def __str__(self) -> str:
        return f"Process<{self.name}>"

    def get_info(self) -> dict[str, Any]:
        """What roslaunch says of the process: its name, command line, env, respawn and
        exit code."""
        return {"spawn_count": self.spawn_count, "args": self.args, "env": self.env,
                "package": self.package, "name": self.name, "alive": self.is_alive(),
                "respawn": self.respawn, "respawn_delay": self.respawn_delay,
                "required": self.required, **({} if self.exit_code is None
                                              else {"exit_code": self.exit_code})}

    def start(self) -> None:
        """Start the process (the base class only counts)."""
        self.time_of_death = None
        self.spawn_count += 1

    def is_alive(self) -> bool:
        """Whether it runs."""
        return False

    def should_respawn(self) -> bool:
        """Whether it is to be started again now: launcher's runtime respawns, so never."""
        return False

    def stop(self, errors: list[str] | None = None) -> None:
        """Stop the process."""

    def get_exit_description(self) -> str:
        """How it ended, in words."""
        if self.exit_code is None:
            return "process has died"
        return "process has finished cleanly" if self.exit_code == 0 else \
            f"process has died [exit code {self.exit_code}]"


class DeadProcess(Process):
    """What is kept of a process that has died."""

    def __init__(self, p: Process) -> None:
        super().__init__(p.package, p.name, p.args, p.env, p.respawn, p.respawn_delay,
                         p.required)
        self.exit_code, self.spawn_count = p.exit_code, p.spawn_count
        self.description = p.get_exit_description()

    def get_exit_description(self) -> str:
        """How it ended, in words, as it was said when it died."""
        return self.description


class ProcessMonitor(threading.Thread):
    """Watches registered Processes and tells its listeners of each one that dies (launcher's
    runtime supervises the launch's own; this is for Processes code makes itself)."""

    def __init__(self, name: str = "ProcessMonitor") -> None:
        super().__init__(name=name, daemon=True)
        self.procs: list[Process] = []
        self.core_procs: list[Process] = []
        self.dead_list: list[DeadProcess] = []
        self.listeners: list[ProcessListener] = []
        self.is_shutdown = False
        self._registrations_complete = False
        self._lock = threading.RLock()
        self._stopped = threading.Event()

    def add_process_listener(self, l: ProcessListener) -> None:  # noqa: E741 (roslaunch's)
        """Tell `l` of each process that dies."""
        self.listeners.append(l)

    def register(self, p: Process) -> None:
        """Watch process `p`."""
        with self._lock:
            if self.has_process(p.name):
                raise RLException(f"cannot add process with duplicate name '{p.name}'")
            if self.is_shutdown:
                raise RLException("cannot add process: monitor is shut down")
            self.procs.append(p)

    def register_core_proc(self, p: Process) -> None:
        """Watch `p`, a core process (stopped last)."""
        self.register(p)
        self.core_procs.append(p)

    def registrations_complete(self) -> None:
        """No more processes will be registered: the monitor ends once all have died."""
        self._registrations_complete = True

    def unregister(self, p: Process) -> None:
        """Stop watching `p`."""
        with self._lock:
            self.procs = [q for q in self.procs if q is not p]

    def has_process(self, name: str) -> bool:
        """Whether a process named `name` is watched."""
        return any(p.name == name for p in self.procs)

    def get_process(self, name: str) -> Process | None:
        """The watched process named `name`, if any."""
        return next((p for p in self.procs if p.name == name), None)

    def has_main_thread_jobs(self) -> bool:
        """roslaunch's: launcher runs no process starts on the main thread."""
        return False

    def do_main_thread_jobs(self) -> None:
        """roslaunch's: nothing to do here."""

    def kill_process(self, name: str) -> bool:
        """Stop the process named `name`; whether one was found."""
        p = self.get_process(name)
        if p is None:
            return False
        self.unregister(p)
        p.stop([])
        return True

    def get_active_names(self) -> list[str]:
        """The names of the processes watched."""
        return [p.name for p in self.procs]

    def get_process_names_with_spawn_count(self) -> list[list[Any]]:
        """[[(name, spawn count) of the live ones], [those of the dead ones]]."""
        return [[(p.name, p.spawn_count) for p in self.procs],
                [(p.name, p.spawn_count) for p in self.dead_list]]

    def mainthread_spin_once(self) -> bool:
        """Whether the monitor still runs."""
        return not self.is_shutdown

    def mainthread_spin(self) -> None:
        """Wait until the monitor is shut down."""
        while not self._stopped.wait(POLL) and not self.is_shutdown:
            pass

    def run(self) -> None:
        """Look at the processes until shutdown: tell the listeners of each that died."""
        while not self._stopped.wait(POLL):
            with self._lock:
                dead = [p for p in self.procs if not p.is_alive()]
                self.procs = [p for p in self.procs if p not in dead]
            for p in dead:
                self.dead_list.append(DeadProcess(p))
                for listener in self.listeners:
                    listener.process_died(p.name, p.exit_code)
                if p.required:
                    printerrlog(f"REQUIRED process [{p.name}] has died!")
                    self.is_shutdown = True
            if self.is_shutdown or (self._registrations_complete and not self.procs):
                break
        self.shutdown()

    def shutdown(self) -> None:
        """Stop every process, core ones last."""
        self.is_shutdown = True
        self._stopped.set()
        with self._lock:
            procs, self.procs = self.procs, []
        for p in sorted(procs, key=lambda q: q in self.core_procs):
            p.stop([])


_monitors: list[ProcessMonitor] = []


def start_process_monitor() -> ProcessMonitor:
    """A new, running ProcessMonitor (shut down with the others by pmon_shutdown)."""
    monitor = ProcessMonitor()
    _monitors.append(monitor)
    monitor.start()
    return monitor


def shutdown_process_monitor(process_monitor: ProcessMonitor | None) -> bool:
    """Shut `process_monitor` down; whether there was one."""
    if process_monitor is None or process_monitor.is_shutdown:
        return False
    process_monitor.shutdown()
    return True


def pmon_shutdown() -> None:
    """Shut every monitor started here down."""
    while _monitors:
        shutdown_process_monitor(_monitors.pop())


def rl_signal(sig: int, stackframe: Any) -> None:
    """roslaunch's signal handler: shut the monitors down."""
    pmon_shutdown()
