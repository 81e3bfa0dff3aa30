"""The launch's processes: their labels, spawning them (recorded before a signal can land),
routing each line they print to the screen, the run's log and the event handlers, and
telling custody (custody.py) about their groups and what they leave behind."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.runtime import events
from launcher.runtime.custody import Custody
from launcher.runtime.hosts import Hosts
from launcher.runtime.logs import RunLog
from launcher.runtime.loop import EventLoop
from launcher.runtime.machine import RemoteStart
from launcher.runtime.output import Printer, Record
from launcher.runtime.process import ManagedProcess, ProcessHooks, ProcessSpec
from launcher.runtime.recent import Recent
from launcher.runtime.system import Processes


class ProcessTable:
    def __init__(self, loop: EventLoop, system: Processes, custody: Custody, printer: Printer,
                 run_log: RunLog | None, log: Callable[[str, str, str], None],
                 emit: Callable[[events.Event], None], listened: Callable[[], bool],
                 changed: Callable[[], None], on_graph: Callable[[], None] | None,
                 helper_over: Callable[[bool], None] = lambda done: None,
                 hosts: Hosts | None = None, recent: Recent | None = None) -> None:
        """`emit` hands events to the handlers (`listened`: whether any would hear a line);
        `changed` is called when a process exits or a helper is done; `on_graph` once, when
        the first process that may join the graph is spawned; `helper_over(done)` when a
        helper says its work is done, or ends before it has (see ProcessSpec); `hosts` starts
        the processes sent to other hosts; `recent` keeps each one's latest lines."""
        self.loop, self.system, self.custody = loop, system, custody
        self.printer, self.run_log, self.log = printer, run_log, log
        self.emit, self.listened, self.changed = emit, listened, changed
        self.on_graph, self.helper_over = on_graph, helper_over
        self.processes: list[ManagedProcess] = []
        self._count = 0
        self.closing = False  # the launch stops them all: held processes no longer keep it
        self._restarting: set[int] = set()  # (ids of) processes to start again once gone
        self.started_again: Callable[[ManagedProcess], None] = lambda process: None
        self.hosts = hosts
        self.recent = recent
        self._hooks = ProcessHooks(line=self._on_line, started=self._on_started,
                                   exited=self._on_exited, log=log, group=custody.group)
        # (a group on another host is that host's to watch: its number means nothing here)
        self._remote_hooks = self._hooks._replace(group=lambda pgid, alive: None)

    def next_label(self, base: str) -> str:
        """`base-N`, N counting every process of this run (as ROS 2 numbers them)."""
        self._count += 1
        return f"{base}-{self._count}"

    def start(self, spec: ProcessSpec) -> ManagedProcess:
        """Spawn now; OSError (not found, not executable, bad cwd) goes to the caller."""
        spec.env = self.custody.stamp(spec.env)
        machine = spec.machine
        if machine is not None and not machine.local and self.hosts is not None:
            system = self.hosts.system_for(machine, spec.remote or RemoteStart(None, None))
            process = ManagedProcess(spec, self._remote_hooks, self.loop, system=system)
        else:
            process = ManagedProcess(spec, self._hooks, self.loop, system=self.system)
        # Ctrl-C in between would leave a running process that the shutdown does not know
        # (and that respawns for ever): the signal waits until it is recorded
        with self.loop.shielded():
            process.spawn()
            self.processes.append(process)
        if spec.joins_graph and self.on_graph is not None:
            hook, self.on_graph = self.on_graph, None
            hook()  # now: the router starts while this process imports
        return process

    # --- what the launch asks of them all ---------------------------------------------------
    def working(self) -> bool:
        """Whether any process runs that is not a helper whose work is done, or one the user
        stopped may be started again (the launch runs on until it is stopped)."""
        return any((p.alive and not p.helper_done) or (p.held and not self.closing)
                   for p in self.processes)

    def alive(self) -> bool:
        return any(p.alive for p in self.processes)

    def failed(self) -> bool:
        return any(p.failed for p in self.processes)

    def stop_started_by(self, origin: Any) -> None:
        """Stop the running processes that the action `origin` started."""
        for process in self.processes:
            if process.spec.origin is origin and process.alive:
                process.stop()

    def stop(self) -> None:
        self.closing = True
        self._restarting.clear()
        for process in self.processes:
            process.stop()

    # --- the user's hand (runtime/control.py) ------------------------------------------------
    def hold(self, process: ManagedProcess) -> None:
        """Stop it for the user: no exit event, no respawn; it waits to be started again."""
        process.hold()

    def start_again(self, process: ManagedProcess) -> bool:
        """Start a stopped or exited process anew; False when it could not start, or when the
        launch is ending or the process runs already (a restart's start, overtaken)."""
        if self.closing or process.alive:
            return False
        with self.loop.shielded():
            started = process.start_again()
        if started:
            self.started_again(process)
        return started

    def restart(self, process: ManagedProcess) -> bool:
        """Stop it (its own signal sequence), then start it anew once its group is gone;
        False when it was not running and could not start."""
        if not process.alive:
            return self.start_again(process)
        self._restarting.add(id(process))
        process.hold()
        return True

    def escalate(self) -> None:
        for process in self.processes:
            process.escalate()

    def look_for_orphans(self) -> None:
        """Custody notes what the launch's processes left below the launcher."""
        owned = {p.pid for p in self.processes
                 if p.leader_running and p.pid and not _remote(p.spec)}
        self.custody.tick(owned | (self.hosts.pids() if self.hosts else set()))

    # --- hooks of each process ---------------------------------------------------------------
    def _on_line(self, process: ManagedProcess, record: Record, targets: frozenset[str]) -> None:
        done = process.spec.helper_done_line
        if done and not process.helper_done and done in record.text:
            process.helper_done = True
            self.loop.call_soon(self.helper_over, True)
            self.loop.call_soon(self.changed)
        if self.recent is not None:
            self.recent.add(process.label, record.stream, record.text)
        if "screen" in targets:
            self.printer.emit(record)
        if self.run_log is not None:
            if "log" in targets:
                self.run_log.write(record)
            if "own_log" in targets:
                self.run_log.write_own(record)
        if self.listened():
            self.emit(events.output(process.spec.origin, process.label, record.stream,
                                    record.text, process.spec.argv, process.pid))

    def _on_started(self, process: ManagedProcess) -> None:
        self.log("INFO", process.shown, f"process started with pid [{process.pid}]")
        spec = process.spec
        self.emit(events.ProcessStarted(action=spec.origin, name=process.label,
                                        cmd=spec.argv, cwd=spec.cwd, env=spec.env,
                                        pid=process.pid or 0))

    def _on_exited(self, process: ManagedProcess, respawn_pending: bool) -> None:
        if process.held:  # the user's stop: not an exit of its own, nothing to tell handlers
            if id(process) in self._restarting:
                self._restarting.discard(id(process))
                self.loop.call_soon(self.start_again, process)
            self.changed()
            return
        if process.spec.helper_done_line and not process.helper_done:
            process.helper_done = True  # (over: it cannot be done later)
            self.helper_over(False)
        spec = process.spec
        self.emit(events.ProcessExited(action=spec.origin, name=process.label, cmd=spec.argv,
                                       cwd=spec.cwd, env=spec.env, pid=process.pid,
                                       returncode=process.returncode))
        if not respawn_pending:
            self.emit(events.ExecutionComplete(action=spec.origin))
        self.changed()


def _remote(spec: ProcessSpec) -> bool:
    return spec.machine is not None and not spec.machine.local


def spec_timeouts(table: ProcessTable) -> tuple[float, float]:
    """The longest SIGTERM and SIGKILL timeouts the launch's processes have (what their
    leftovers get)."""
    specs: list[Any] = [p.spec for p in table.processes]
    return (max((s.sigterm_timeout for s in specs), default=5.0),
            max((s.sigkill_timeout for s in specs), default=5.0))
