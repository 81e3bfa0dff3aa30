"""The launch service: visits actions, runs processes and timers, shuts down, and exits.

Actions are visited depth first on the event loop. Processes are supervised by
`ManagedProcess`; `Custody` (custody.py) holds on to everything they start in turn, and its
watchdog ends it all if this process dies. The launch ends when no process, timer or action is
left; what the processes left running (daemons, processes that left their group) is stopped
then, with the same escalation.
Exit status: 0 when everything ended cleanly; 1 when the launch description was invalid, an
action failed, or a process exited with a non-zero code the launcher did not cause; 130 after
SIGINT and 143 after SIGTERM. A signal during a shutdown that something else began hurries
the shutdown on (the next signal of the escalation) and keeps that shutdown's exit status.
"""

from __future__ import annotations

import os
import signal
from collections import deque
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from launcher.errors import ExecutionError, Interrupted, LaunchError, did_you_mean
from launcher.runtime import events
from launcher.runtime.composition import Loader, LoadRequest
from launcher.runtime.context import LaunchContext
from launcher.runtime.custody import TICK, Custody, Sweep
from launcher.runtime.logs import RunLog
from launcher.runtime.loop import EventLoop, Timer
from launcher.runtime.output import Printer, Record
from launcher.runtime.process import ManagedProcess, ProcessHooks, ProcessSpec
from launcher.runtime.system import Processes, System


class LaunchService:
    def __init__(
        self,
        *,
        printer: Printer | None = None,
        log_root: Path | None = None,
        environment: dict[str, str] | None = None,
        configurations: dict[str, str] | None = None,
        launch_prefix: str = "",
        debug: bool = False,
        loop: EventLoop | None = None,
        load_description: Callable[[Path], Any] | None = None,
        parse_text: Callable[[str, str], Any] | None = None,
        packages: Any = None,
        system: Processes | None = None,
        custody: Custody | None = None,
        loader: Loader | None = None,
        on_graph: Callable[[], None] | None = None,
    ) -> None:
        self.system = system or System()
        self.printer = printer or Printer()
        self.run_log = RunLog(log_root) if log_root is not None else None
        self.context = LaunchContext(
            environment, configurations, service=self,
            log_dir=self.run_log.folder if self.run_log else None,
            load_description=load_description, packages=packages, parse_text=parse_text,
        )
        self.loop = loop or EventLoop()
        self.launch_prefix = launch_prefix
        self.debug = debug
        self.processes: list[ManagedProcess] = []
        self._queue: deque[Any] = deque()
        self._draining = False
        self._given = set(configurations or {})  # the command line's name:=value names
        self._handlers: list[events.EventHandler] = []
        self._timers: dict[Timer, bool] = {}  # timer -> cancel on shutdown
        self._label_count = 0
        self._shutting_down = False
        self._signal_code: int | None = None
        self._signals = 0
        self._error = False
        self._finished = False
        self.custody = custody or Custody()
        self._sweep: Sweep | None = None
        self.loader = loader
        # once, when the first process that may join the graph is spawned (`launcher launch`
        # starts the graph's router there)
        self._on_graph = on_graph
        self._loads = 0  # composable nodes asked for and not answered yet
        self._hooks = ProcessHooks(line=self._on_line, started=self._on_started,
                                   exited=self._on_exited, log=self.log, group=self._on_group)

    # --- entry point ------------------------------------------------------------------------
    def run(self, description: Any) -> int:
        """Run the description until the launch ends; return the exit status."""
        # First: the watchdog's fork must not inherit signal handling. (`launcher launch` has
        # begun the custody already, before the hooks ran; this is for the API's launches.)
        self.custody.begin(self.context.environment)
        for sig in (signal.SIGINT, signal.SIGTERM):
            self.loop.add_signal_handler(sig, self._on_signal)
        if self.custody.subreaper:  # collect adopted processes as they exit, and look anyway
            self.loop.add_signal_handler(signal.SIGCHLD, self._on_child)
            self.loop.call_later(TICK, self._tick)
        try:
            if self.run_log is not None:
                self.log("INFO", "launch", f"All log files can be found below "
                                           f"{self.run_log.folder}")
            self.schedule([description])
            self.loop.run()
        finally:
            if self.loader is not None:
                self.loader.close()
            self.loop.close()
            # its last look (the sweep) found nothing left: the watchdog need not look again
            self.custody.end(nothing_left=self._finished and not (
                self._sweep is not None and self._sweep.gave_up))
            if self.run_log is not None:
                self.run_log.close()
        return self.exit_code

    @property
    def exit_code(self) -> int:
        if self._signal_code is not None:
            return self._signal_code
        if self._error or any(p.failed for p in self.processes):
            return 1
        return 0

    def _graph_needed(self) -> None:
        hook, self._on_graph = self._on_graph, None
        if hook is None:
            return
        try:
            hook()
        except LaunchError as exc:
            self.report(exc)

    # --- visiting actions -------------------------------------------------------------------
    def schedule(self, actions: Sequence[Any]) -> None:
        """Queue actions to visit after the ones already queued."""
        self._queue.extend(actions)
        if not self._draining:
            self.loop.call_soon(self._drain)

    def _drain(self) -> None:
        self._draining = True
        try:
            while self._queue:
                action = self._queue.popleft()
                try:
                    with self.loop.interruptible():
                        more = action.visit(self.context)
                except Interrupted as exc:  # Ctrl-C while evaluating: stop at once
                    self._on_signal(exc.signum)
                    continue
                except LaunchError as exc:
                    self.fail(exc)
                    continue
                except Exception as exc:  # a bug, or user Python code (a callback) failing
                    self.fail(unexpected(exc, getattr(action, "where", None)))
                    continue
                if more:
                    self._queue.extendleft(reversed(list(more)))
        finally:
            self._draining = False
        self._check_given()
        self._check_idle()

    def _check_given(self) -> None:
        """Once the launch files have been read (the first drain: includes are read as they
        are met), a command-line argument no `arg` declared is said (ROS 2 takes a misspelt
        one silently, as a configuration nothing reads)."""
        given, self._given = self._given, set()
        for name in sorted(given - self.context.declared):
            hint = did_you_mean(name, self.context.declared)
            self.log("WARN", "launch", f"launch argument '{name}' was given, but no launch "
                                       f"file declares it{hint} (it is set as a configuration "
                                       f"all the same)")

    def report(self, exc: LaunchError) -> None:
        """An error that does not end the launch (one node it cannot start): logged, and the
        launch's exit status becomes 1."""
        self._error = True
        self.log("ERROR", "launch", str(exc))

    def fail(self, exc: LaunchError) -> None:
        """An action failed: report it once and shut the launch down."""
        self._error = True
        self.log("ERROR", "launch", str(exc))
        if self.debug:
            import traceback  # only with --debug: start-up time

            cause = exc.__cause__ or exc
            self.log("DEBUG", "launch", "".join(traceback.format_exception(cause)).rstrip())
        self.shutdown(f"error: {exc.message}")

    # --- processes --------------------------------------------------------------------------
    def next_label(self, base: str) -> str:
        """`base-N`, N counting every process of this run (as ROS 2 numbers them)."""
        self._label_count += 1
        return f"{base}-{self._label_count}"

    def start_process(self, spec: ProcessSpec) -> ManagedProcess | None:
        """Spawn now; OSError (not found, not executable, bad cwd) goes to the caller."""
        if self._shutting_down:
            self.log("DEBUG", spec.label, "not started: the launch is shutting down")
            return None
        spec.env = self.custody.stamp(spec.env)
        process = ManagedProcess(spec, self._hooks, self.loop, system=self.system)
        # Ctrl-C in between would leave a running process that the shutdown does not know
        # (and that respawns for ever): the signal waits until it is recorded
        with self.loop.shielded():
            process.spawn()
            self.processes.append(process)
        if spec.joins_graph:
            self._graph_needed()  # now: the router starts while this process imports
        return process

    def _on_line(self, process: ManagedProcess, record: Record, targets: frozenset[str]) -> None:
        done = process.spec.helper_done_line
        if done and not process.helper_done and done in record.text:
            process.helper_done = True
            self.loop.call_soon(self._check_idle)
        if "screen" in targets:
            self.printer.emit(record)
        if self.run_log is not None:
            if "log" in targets:
                self.run_log.write(record)
            if "own_log" in targets:
                self.run_log.write_own(record)
        if self._handlers:
            self.emit(events.ProcessIO(process.spec.origin, process.label, record.stream,
                                       record.text))

    def _on_started(self, process: ManagedProcess) -> None:
        self.log("INFO", process.label, f"process started with pid [{process.pid}]")
        self.emit(events.ProcessStarted(process.spec.origin, process.label, process.pid or 0))

    def _on_exited(self, process: ManagedProcess, _respawn_pending: bool) -> None:
        self.emit(events.ProcessExited(process.spec.origin, process.label, process.pid,
                                       process.returncode))
        self._check_idle()

    def _on_group(self, pgid: int, alive: bool) -> None:
        self.custody.group(pgid, alive)

    def _tick(self) -> None:
        if self._finished:
            return
        self._on_child()
        self.loop.call_later(TICK, self._tick)

    def _on_child(self, _signum: int = 0) -> None:
        self.custody.tick({p.pid for p in self.processes if p.leader_running and p.pid})

    # --- composable nodes -------------------------------------------------------------------
    def load_components(self, container: str, requests: list[LoadRequest],
                        alive: Callable[[], bool] | None) -> None:
        """Ask `container` to load `requests`; each answer is logged, a failure reported (the
        launch goes on, its exit status becomes 1). The launch does not end while one is out."""
        if self.loader is None:
            raise ExecutionError("composable nodes need the bus, which this run lacks "
                                 "(run it with `launcher launch`)")
        if not requests or self._shutting_down:
            return
        self.loop.open_posting()
        self._loads += len(requests)

        def done(request: LoadRequest, name: str, error: str) -> None:  # a loader's thread
            self.loop.call_soon_threadsafe(self._on_loaded, container, request, name, error)

        self.loader.load(container, requests, dict(self.context.environment), alive, done)

    def _on_loaded(self, container: str, request: LoadRequest, name: str, error: str) -> None:
        self._loads = max(0, self._loads - 1)
        if error and not self._shutting_down:
            self.report(ExecutionError(f"composable node '{request.label}' "
                                       f"({request.plugin}) was not loaded into "
                                       f"'{container}': {error}", request.where))
        elif not error:
            self.log("INFO", "launch", f"Loaded node '{name}' in container '{container}'")
        self._check_idle()

    # --- events and timers ------------------------------------------------------------------
    def register_handler(self, handler: events.EventHandler) -> None:
        self._handlers.append(handler)

    def emit(self, event: events.Event) -> None:
        for handler in list(self._handlers):
            if not handler.matches(event):
                continue
            try:
                with self.loop.interruptible():
                    actions = handler.handle(event, self.context)
            except Interrupted as exc:
                self._on_signal(exc.signum)
                continue
            except LaunchError as exc:
                self.fail(exc)
                continue
            except Exception as exc:  # the user's callback raised
                self.fail(unexpected(exc, None))
                continue
            if actions:
                self.schedule(actions)

    def add_timer(self, period: float, callback: Callable[[], None],
                  cancel_on_shutdown: bool = True) -> Timer:
        def fire() -> None:
            self._timers.pop(timer, None)
            callback()
            self._check_idle()

        timer = self.loop.call_later(period, fire)
        self._timers[timer] = cancel_on_shutdown
        return timer

    # --- shutting down ----------------------------------------------------------------------
    @property
    def shutting_down(self) -> bool:
        return self._shutting_down

    def shutdown(self, reason: str) -> None:
        """End the launch: OnShutdown handlers run, timers stop, processes are stopped."""
        if self._shutting_down:
            return
        self._shutting_down = True
        self.log("DEBUG", "launch", f"shutting down: {reason}")
        self._queue.clear()
        self.emit(events.Shutdown(reason))
        for timer, cancel in list(self._timers.items()):
            if cancel:
                timer.cancel()
                del self._timers[timer]
        for process in self.processes:
            process.stop()
        if self.loader is not None:
            self.loader.cancel()
        self._loads = 0
        self._check_idle()

    def _on_signal(self, sig: int) -> None:
        self._signals += 1
        name = signal.Signals(sig).name
        if self._signals == 1 and self._shutting_down:  # hurry on; keep its exit status
            self.log("WARN", "launch", f"{name} during the shutdown: escalating to the next "
                                       f"signal")
            self._escalate()
        elif self._signals == 1:
            self._signal_code = 128 + sig
            what = "user interrupted with ctrl-c (SIGINT)" if sig == signal.SIGINT else \
                f"received {name}"
            self.log("WARN", "launch", f"{what}: stopping all processes")
            self.shutdown(f"signal {name}")
        else:
            self.log("WARN", "launch", f"{name} again: escalating to the next signal")
            self._escalate()

    def _escalate(self) -> None:
        for process in self.processes:
            process.escalate()
        if self._sweep is not None:
            self._sweep.escalate()

    def _check_idle(self) -> None:
        """The launch ends when no process runs and no timer or action is pending, and what
        its processes left running is stopped."""
        if self._finished or self._queue or self._draining or self._timers or self._loads:
            return
        if any(p.alive and not p.helper_done for p in self.processes):
            return
        if any(p.alive for p in self.processes):  # helpers alone, their work done
            self.shutdown("only the launch's helpers are left")
            return
        if self._sweep is None:
            left = self.custody.leftovers()
            if left:
                specs = [p.spec for p in self.processes]  # their leftovers get their timeouts
                self._sweep = Sweep(self.custody, self.loop,
                                    lambda level, text: self.log(level, "launch", text),
                                    self._check_idle,
                                    max((s.sigterm_timeout for s in specs), default=5.0),
                                    max((s.sigkill_timeout for s in specs), default=5.0))
                self._sweep.start(left)
        if self._sweep is not None and not self._sweep.finished:
            return
        self._finished = True
        self.loop.stop()

    # --- the launcher's own messages --------------------------------------------------------
    def log(self, level: str, source: str, message: str) -> None:
        record = Record(source, message, "launcher", level)
        if self.run_log is not None:
            self.run_log.write(record)
        if level != "DEBUG" or self.debug:
            self.printer.emit(record)


def unexpected(exc: Exception, where: Any) -> LaunchError:
    """An exception that is not a LaunchError, as one: the message, never a bare traceback."""
    error = ExecutionError(f"{type(exc).__name__}: {exc} (run with --debug for the traceback)",
                           where)
    error.__cause__ = exc
    return error


def default_environment() -> dict[str, str]:
    """The environment children get: ours, with Python output unbuffered (as ROS 2 sets)."""
    env = dict(os.environ)
    env.setdefault("PYTHONUNBUFFERED", "1")
    return env
