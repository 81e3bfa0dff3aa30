"""The launch service: visits actions, answers what they ask of the runtime, and exits.
Events go to their handlers (handlers.py), timers run on the loop (timers.py).

Actions are visited depth first on the event loop. The processes they start are kept by the
process table (process_table.py), each supervised by `ManagedProcess`; `Custody` (custody.py)
holds on to everything they start in turn, and its watchdog ends it all if this process dies.
How the launch ends, and its exit status, is ending.py's: 0 when everything ended cleanly; 1
when the launch description was invalid, an action failed, or a process exited with a
non-zero code the launcher did not cause; 130 after SIGINT and 143 after SIGTERM.
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
from launcher.runtime.component_loads import ComponentLoads
from launcher.runtime.composition import Loader, LoadRequest
from launcher.runtime.context import LaunchContext
from launcher.runtime.control import ProcessControl
from launcher.runtime.coroutines import Coroutines
from launcher.runtime.custody import TICK, Custody
from launcher.runtime.ending import Ending
from launcher.runtime.figures import Figures
from launcher.runtime.handlers import Handlers
from launcher.runtime.hosts import Graph, Hosts
from launcher.runtime.lifecycle import Lifecycle, LifecycleRequests
from launcher.runtime.logs import DEFAULT_LIMIT, RunLog
from launcher.runtime.loop import EventLoop, Timer
from launcher.runtime.output import Printer, Record
from launcher.runtime.process import ManagedProcess, ProcessSpec
from launcher.runtime.process_table import ProcessTable
from launcher.runtime.recent import Recent
from launcher.runtime.start_gate import StartGate
from launcher.runtime.system import Processes, System
from launcher.runtime.timers import LaunchTimers
from launcher.runtime.warm import warm_starts

# seconds into a launch at which it answers on the graph (launcher ps): a launch of `true`s
# (0.1 s) never opens a session for it, and one whose nodes are up (the demo's, 0.8 s once
# they started warm and linked to the router alone) answers by then
CONTROL_AFTER = 0.3
FLUSH = 0.5  # seconds between flushes of the run's log files


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
        parse_text: Callable[..., Any] | None = None,
        packages: Any = None,
        system: Processes | None = None,
        custody: Custody | None = None,
        loader: Loader | None = None,
        on_graph: Callable[[], None] | None = None,
        lifecycle: Lifecycle | None = None,
        remote_graph: Graph | None = None,
        serve_control: Callable[[ProcessControl], Callable[[], None]] | None = None,
        log_limit: int = DEFAULT_LIMIT,
    ) -> None:
        """`on_graph` runs once, when the first process that may join the graph is spawned
        (`launcher launch` starts the graph's router there); `remote_graph(address)` says how
        another host, which reaches this one at `address`, joins the launch's graph;
        `serve_control(control)` puts the user's hand on the launch (`launcher ps`, …) on the
        graph, and returns what ends that; `log_limit`: the size in bytes at which each log
        file rotates (no log files at all without `log_root`)."""
        self.printer = printer or Printer()
        self.run_log = RunLog(log_root, log_limit) if log_root is not None else None
        self.context = LaunchContext(
            environment, configurations, service=self,
            log_dir=self.run_log.folder if self.run_log else None,
            load_description=load_description, packages=packages, parse_text=parse_text,
        )
        self.loop = loop or EventLoop()
        self.launch_prefix = launch_prefix
        self.debug = debug
        self.custody = custody or Custody()
        self._queue: deque[Any] = deque()
        self._draining = False
        self._started_events: list[events.ProcessStarted] = []  # (see emit)
        self._given = set(configurations or {})  # the command line's name:=value names
        self.handlers = Handlers(self.context, self._guarded, self.schedule)
        self.timers = LaunchTimers(self.loop, self._check_idle)
        hosts = Hosts(self.loop, self.context.environment, self.custody.stamp, self.log,
                      os.urandom(8).hex(), remote_graph)
        self.recent = Recent()
        # (a process forked by a warm start's server is the launcher's own child only where
        # the launcher is the child subreaper: it is reparented to it)
        self._system: Processes = system or System(
            warm_starts(self.context.environment) if self.custody.subreaper else None)
        self.table = ProcessTable(self.loop, self._system, self.custody, self.printer,
                                  self.run_log, self.log, self.emit,
                                  lambda: bool(self.handlers.registered),
                                  self._check_idle, on_graph and reporting(on_graph, self.report),
                                  lambda done: self.gate.helper_over(done), hosts, self.recent)
        self.loads = ComponentLoads(self.loop, loader, self.log, self.report, self._check_idle)
        self.table.started_again = self._started_again
        self._serve_control = serve_control
        self._end_control: Callable[[], None] | None = None
        self.control: ProcessControl | None = None
        self.coroutines = Coroutines(self.loop.call_soon_threadsafe, self._coroutine_failed,
                                     self._check_idle)
        self.lifecycles = LifecycleRequests(self.loop, lifecycle, self.emit, self.log,
                                            self.report, self._check_idle)
        self.gate = StartGate(self.start_process, self.fail, self.report,
                              lambda: self.ending.shutting_down, lambda: self._draining)
        # (the ending tells the handlers its Shutdown itself: emit() would shut down again)
        self.ending = Ending(self.loop, self.table, self.custody, self.log,
                             lambda event: self.handlers.emit(event), self._pending,
                             self._queue.clear, self._cancel)

    # --- entry point ------------------------------------------------------------------------
    def run(self, description: Any, *, signals: bool = True) -> int:
        """Run the description until the launch ends; return the exit status. `signals`:
        SIGINT and SIGTERM end the launch (only the main thread can take them: a launch run
        in another thread, as launch_pytest's, is ended by `shutdown` and still looks for
        adopted processes on its tick)."""
        # First: the watchdog's fork must not inherit signal handling. (`launcher launch` has
        # begun the custody already, before the hooks ran; this is for the API's launches.)
        self.custody.begin(self.context.environment)
        if signals:
            unacted = [each for sig in (signal.SIGINT, signal.SIGTERM)
                       for each in self.loop.add_signal_handler(sig, self.ending.on_signal)]
            for signum, where in unacted:  # (said once both are the loop's)
                self.log("WARN", "launch", f"{signal.Signals(signum).name} came while the "
                                           f"launch was being read, and was lost there (it "
                                           f"landed at {where}, in code that went on): acting "
                                           f"on it now")
        if self.custody.subreaper and signals:  # collect adopted processes as they exit
            self.loop.add_signal_handler(signal.SIGCHLD, lambda _sig: self.table
                                         .look_for_orphans())
        if self.custody.subreaper:  # and look anyway
            self.loop.call_later(TICK, self._tick)
        try:
            self.printer.start()
            figures = Figures(self.run_log.folder, self.run_log.limit) if self.run_log \
                else Figures(None)
            self.control = ProcessControl(self.table, self.loop, figures, self.recent,
                                          self.log)
            # (on the graph after a moment: a launch over sooner, as `true`, never pays)
            self.loop.call_later(CONTROL_AFTER, self._open_control)
            self.loop.call_later(FLUSH, self._flush_logs)
            if self.run_log is not None:
                self.log("INFO", "launch", f"All log files can be found below "
                                           f"{self.run_log.folder}")
            self.schedule([description])
            self.loop.run()
        finally:
            if self._end_control is not None:  # (its requests are answered "ending" now)
                self._end_control()
            if self.control is not None:
                self.control.close()
            self.loads.close()
            self.lifecycles.close()
            self.coroutines.close()
            self.loop.close()
            self._system.end_servers()  # (ended already, unless the launch failed to end)
            # its last look (the sweep) found nothing left: the watchdog need not look again
            self.custody.end(nothing_left=self.ending.swept_all)
            if self.run_log is not None:
                self.run_log.close()
            self.printer.close()
        return self.exit_code

    @property
    def exit_code(self) -> int:
        return self.ending.exit_code

    def _open_control(self) -> None:
        """The launch answers `launcher ps` and its kin on the graph from now on."""
        if self._serve_control is not None and self.control is not None and \
                not self.ending.shutting_down:
            self._end_control = self._serve_control(self.control)

    def _started_again(self, process: ManagedProcess) -> None:
        """The user started a process anew: a container's composable nodes load again."""
        container = getattr(process.spec.origin, "fqn", "")
        if container:
            self.loads.reload(container)

    @property
    def processes(self) -> list[ManagedProcess]:
        return self.table.processes

    def _tick(self) -> None:
        if self.ending.finished:
            return
        self.table.look_for_orphans()
        self.loop.call_later(TICK, self._tick)

    def _flush_logs(self) -> None:
        """What the run's log holds reaches its files every FLUSH seconds: a launcher that
        is killed leaves its log behind, all but its last moments."""
        if self.run_log is not None and not self.ending.finished:
            self.run_log.flush()
            self.loop.call_later(FLUSH, self._flush_logs)

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
                more = self._guarded(lambda action=action: action.visit(self.context),
                                     getattr(action, "where", None))
                if more:
                    self._queue.extendleft(reversed(list(more)))
        finally:
            self._draining = False
        started, self._started_events = self._started_events, []
        for event in started:
            self.emit(event)
        checks, self.context.loaded_checks = self.context.loaded_checks, []
        for check in checks:
            self._guarded(check, None)
        self.gate.release()
        self._check_given()
        self._check_idle()

    def _guarded(self, run: Callable[[], Any], where: Any) -> Any:
        """What `run()` returns; a signal while it runs, or its failure, ends the launch."""
        try:
            with self.loop.interruptible():
                return run()
        except Interrupted as exc:  # Ctrl-C while evaluating: stop at once
            self.loop.took(exc.signum)
            self.ending.on_signal(exc.signum)
        except LaunchError as exc:
            self.fail(exc)
        except Exception as exc:  # a bug, or user Python code (a callback) failing
            self.fail(unexpected(exc, where))
        return None

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
        self.ending.error = True
        self.log("ERROR", "launch", str(exc))

    def fail(self, exc: LaunchError) -> None:
        """An action failed: report it once and shut the launch down."""
        self.report(exc)
        if self.debug:
            import traceback  # only with --debug: start-up time

            cause = exc.__cause__ or exc
            self.log("DEBUG", "launch", "".join(traceback.format_exception(cause)).rstrip())
        self.shutdown(f"error: {exc.message}")

    # --- what actions ask of the runtime (context.Runtime) ---------------------------------
    def next_label(self, base: str) -> str:
        return self.table.next_label(base)

    def start_process(self, spec: ProcessSpec,
                      started: Callable[[ManagedProcess], None] | None = None) -> None:
        """Spawn now, and call `started` with it; OSError (not found, not executable, bad
        cwd) goes to the caller. A process that may join the graph waits while the graph is
        held (hold_graph), one `after_loading` also until the actions queued now are visited
        (the launch files read); it is spawned after (an OSError then is reported)."""
        if self.ending.shutting_down:
            self.log("DEBUG", spec.label, "not started: the launch is shutting down")
            return
        if self.gate.keeps(spec, started):
            self.log("DEBUG", spec.label, "waits for the launch files and their parameters")
            return
        process = self.table.start(spec)
        if started is not None:
            started(process)

    def hold_graph(self) -> None:
        """A helper is coming that puts the launch's parameters on the graph (ROS 1's): the
        processes that may join the graph wait until it is done, as roslaunch sets every
        parameter before it starts a node. A helper that ends before it is done fails the
        launch, and they never start (start_gate.py)."""
        self.gate.hold()

    def load_components(self, container: str, requests: list[LoadRequest],
                        alive: Callable[[], bool] | None) -> None:
        self.loads.load(container, requests, dict(self.context.environment), alive)

    def watch_lifecycle(self, node: str, origin: Any) -> None:
        self.lifecycles.watch(node, origin)

    def change_states(self, node: str, transitions: list[int], where: Any) -> None:
        self.lifecycles.change_states(node, transitions, where)

    def register_handler(self, handler: events.EventHandler) -> None:
        self.handlers.register(handler)

    def unregister_handler(self, handler: events.EventHandler) -> None:
        self.handlers.unregister(handler)

    def emit(self, event: events.Event) -> None:
        """An event to the handlers; the ones the launch acts on itself (Shutdown,
        ShutdownProcess and SignalProcess for the processes they name, and
        IncludeLaunchDescription, whose description joins the launch) are acted on."""
        if isinstance(event, events.Shutdown):
            self.shutdown(event.reason)  # (which tells the OnShutdown handlers)
            return
        if self._draining and isinstance(event, events.ProcessStarted):
            # as in launch, where a process starts once the actions being visited are: a
            # handler registered after the process's action still hears of its start
            self._started_events.append(event)
            return
        if isinstance(event, events.ProcessTargetedEvent):
            self._target(event)
        elif isinstance(event, events.IncludeLaunchDescription):
            self.schedule([event.launch_description])  # (launch's own handler of it)
        self.handlers.emit(event)

    def would_handle(self, event: events.Event) -> bool:
        return self.handlers.would_handle(event)

    def _target(self, event: events.ProcessTargetedEvent) -> None:
        for process in self.table.processes:
            if not process.alive or not event.process_matcher(process.spec.origin):
                continue
            if isinstance(event, events.SignalProcess):
                process.signal(event.signal)
            else:
                process.stop()

    def add_timer(self, period: float, callback: Callable[[], None],
                  cancel_on_shutdown: bool = True) -> Timer:
        return self.timers.add(period, callback, cancel_on_shutdown)

    @property
    def shutting_down(self) -> bool:
        return self.ending.shutting_down

    def shutdown(self, reason: str) -> None:
        """End the launch: OnShutdown handlers run, timers stop, processes are stopped."""
        self.ending.shutdown(reason)

    def log(self, level: str, source: str, message: str) -> None:
        """The launcher's own messages: to the run's log, and (DEBUG with --debug) the
        screen."""
        record = Record(source, message, "launcher", level)
        if self.run_log is not None:
            self.run_log.write(record)
        if level != "DEBUG" or self.debug:
            self.printer.emit(record)

    # --- what the ending asks ---------------------------------------------------------------
    def _pending(self) -> bool:
        return bool(self._queue or self._draining or self.timers.live or self.loads.out or
                    self.lifecycles.out or self.gate.waiting or self.coroutines.out)

    def _coroutine_failed(self, exc: BaseException) -> None:
        self.fail(exc if isinstance(exc, LaunchError) else unexpected(exc, None))  # type: ignore[arg-type]

    def _cancel(self) -> None:
        self.coroutines.cancel()
        self.timers.cancel()
        self.loads.cancel()
        self.lifecycles.cancel()

    def _check_idle(self) -> None:
        self.ending.check()


def reporting(run: Callable[[], None],
              report: Callable[[LaunchError], None]) -> Callable[[], None]:
    """`run`, with its LaunchError reported instead of raised (the graph's start: a launch
    whose router cannot start goes on to say so, and ends with status 1)."""
    def reported() -> None:
        try:
            run()
        except LaunchError as exc:
            report(exc)

    return reported


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
