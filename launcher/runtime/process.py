"""Supervision of one process: an explicit state machine, escalation and respawn.

    STARTING ──spawned──▶ RUNNING ──exited, respawn due──▶ BACKOFF ──delay over──▶ STARTING
        │                    │  └──exited, no respawn──▶ EXITED
        └─spawn failed─▶ FATAL   └──stop()──▶ STOPPING ──group gone──▶ EXITED
                                  BACKOFF ──stop()──▶ EXITED
    EXITED, FATAL ──start_again() (the user's `launcher start`)──▶ STARTING

Each process runs in its own session, so it leads its own process group. Stopping sends
SIGINT to the whole group, SIGTERM after `sigterm_timeout`, SIGKILL after `sigkill_timeout`
more; `escalate()` sends the next signal at once. When a process exits on its own, anything it
left running in its group is killed: nothing is left behind. The operating system is reached
only through `system` (runtime/system.py), which tests replace with a recording fake.
"""

from __future__ import annotations

import signal
from collections.abc import Callable
from enum import Enum
from typing import Any, NamedTuple

from launcher.records import dataclass, field
from launcher.runtime.loop import EventLoop, Timer
from launcher.runtime.machine import Machine, RemoteStart
from launcher.runtime.output import Record
from launcher.runtime.system import Processes, System

GIVE_UP_AFTER_SIGKILL = 2.0  # seconds; a process in uninterruptible sleep cannot be waited on
STREAM_GRACE = 0.5  # seconds to keep reading after an exit (something else may hold the pipe)
GROUP_POLL = 0.01  # seconds between checks that a stopped group is empty


class State(Enum):
    STARTING = "starting"
    RUNNING = "running"
    BACKOFF = "backoff"
    STOPPING = "stopping"
    EXITED = "exited"
    FATAL = "fatal"


_EDGES = {
    (State.STARTING, State.RUNNING),  # spawned
    (State.STARTING, State.FATAL),  # a respawn could not spawn
    (State.RUNNING, State.EXITED),  # exited on its own, no respawn due
    (State.RUNNING, State.BACKOFF),  # exited on its own, respawn due after the delay
    (State.RUNNING, State.STOPPING),  # the launcher asked it to stop
    (State.STOPPING, State.EXITED),  # its group is gone (or SIGKILL did not help in time)
    (State.BACKOFF, State.STARTING),  # respawn delay over
    (State.BACKOFF, State.EXITED),  # stopped while waiting to respawn
    (State.EXITED, State.STARTING),  # started again by the user
    (State.FATAL, State.STARTING),  # … after it could not start
}
STABLE = 5.0  # seconds a process must run for its next respawn not to count as a quick one
STORM = 3  # quick respawns in a row that make a storm: its respawns back off from there
BACKOFF_CAP = 30.0  # seconds: the longest wait the back-off of quick respawns reaches
BACKOFF_FIRST = 0.1  # seconds: where it starts when the respawn delay is shorter


@dataclass
class ProcessSpec:
    label: str
    argv: list[str]
    env: dict[str, str]
    cwd: str | None = None
    emulate_tty: bool = False
    # For each stream, where its lines go: any of "screen", "log", "own_log".
    stdout_to: frozenset[str] = frozenset({"log"})
    stderr_to: frozenset[str] = frozenset({"log", "screen"})
    sigterm_timeout: float = 5.0
    sigkill_timeout: float = 5.0
    respawn: bool = False
    respawn_delay: float = 0.0
    respawn_max_retries: int = -1
    node_name: str = ""  # its node's full name, when it is a ROS node with one
    origin: Any = None  # the action that asked for this process (for event handlers)
    joins_graph: bool = False  # it may be a ROS node (the launch then starts the router)
    # roslaunch's order: it starts once the launch files being read are read and the
    # parameters they set are on the graph's server (LaunchService.hold_graph)
    after_loading: bool = False
    # A helper of the launch (one that puts the launch's parameters on the graph and holds
    # them there): once it prints a line holding this text, its work is done; it no longer
    # keeps the launch running, and is stopped when it is all that is left. Until then the
    # processes that may join the graph wait (LaunchService.hold_graph); one that ends before
    # it is done fails the launch.
    helper_done_line: str = ""

    # Where it runs: None, or a machine on this host, here; another host's over ssh, where
    # `remote` says how it starts (its argv then lacks the executable's own words)
    machine: Machine | None = None
    remote: RemoteStart | None = None

    @property
    def program(self) -> str:
        """What it runs, as errors name it: on another host, the executable found there."""
        if self.remote is not None and self.remote.executable:
            return self.remote.executable
        return self.argv[0] if self.argv else self.label


class ProcessHooks(NamedTuple):
    """What a process tells its supervisor; all called on the loop."""

    line: Callable[[ManagedProcess, Record, frozenset[str]], None]
    started: Callable[[ManagedProcess], None]
    exited: Callable[[ManagedProcess, bool], None]  # (process, respawn pending)
    log: Callable[[str, str, str], None]  # (level, source, message)
    group: Callable[[int, bool], None]  # (pgid, alive): for the watchdog


def describe_exit(code: int | None) -> str:
    if code is None:
        return "could not be waited for"
    if code < 0:
        try:
            return f"was killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"was killed by signal {-code}"
    return f"exited with code {code}"


@dataclass
class ManagedProcess:
    spec: ProcessSpec
    hooks: ProcessHooks
    loop: EventLoop
    state: State = State.STARTING
    pid: int | None = None
    returncode: int | None = None
    respawns: int = 0
    restarts: int = 0  # starts after the first: respawns, and the user's start and restart
    started_at: float = 0.0  # the loop's time of its latest start
    held: bool = False  # stopped by the user: not an exit, and it may be started again
    quick: int = 0  # respawns in a row of a process that ran less than STABLE seconds
    failed: bool = False  # it exited with a non-zero code that the launcher did not cause
    helper_done: bool = False  # a helper that has said its work is done (see ProcessSpec)
    system: Processes = field(default_factory=System, repr=False)
    _streams: list[int] = field(default_factory=list, repr=False)  # open output fds
    _leader_gone: bool = False
    _timer: Timer | None = field(default=None, repr=False)  # respawn or escalation step
    _signals_left: list[tuple[signal.Signals, float]] = field(default_factory=list, repr=False)
    _stop_requested: bool = False
    _signalled: set[int] = field(default_factory=set, repr=False)  # sent by the launch

    @property
    def label(self) -> str:
        return self.spec.label

    @property
    def shown(self) -> str:
        """Its name on the screen and in the log: `talker-1@robot2` on another host."""
        machine = self.spec.machine
        return self.label if machine is None or machine.local else f"{self.label}@{machine.name}"

    @property
    def leader_running(self) -> bool:
        """Its process (the group's leader) has not been collected yet."""
        return self.pid is not None and not self._leader_gone

    @property
    def alive(self) -> bool:
        return self.state in (State.STARTING, State.RUNNING, State.BACKOFF, State.STOPPING)

    def _to(self, new: State) -> None:
        if (self.state, new) not in _EDGES:
            raise RuntimeError(f"{self.label}: no transition {self.state.name} -> {new.name}")
        self.state = new

    def _log(self, level: str, message: str) -> None:
        self.hooks.log(level, self.shown, message)

    # --- starting ---------------------------------------------------------------------------
    def spawn(self) -> None:
        """Start the process now. OSError (not found, not executable, bad cwd) propagates."""
        spec = self.spec
        started = self.system.spawn(spec.argv, spec.env, spec.cwd, spec.emulate_tty)
        self.pid, self.returncode, self._leader_gone = started.pid, None, False
        self.started_at = self.loop.time()
        self.hooks.group(self.pid, True)
        self._streams = [started.stdout, started.stderr]
        for fd, stream in ((started.stdout, "stdout"), (started.stderr, "stderr")):
            self.loop.add_reader(fd, self._on_readable, fd, stream, bytearray())
        self.system.watch_exit(self.pid, self.loop, self._on_leader_exit)
        self._to(State.RUNNING)
        self.hooks.started(self)

    def _on_leader_exit(self, returncode: int | None) -> None:
        self.returncode = returncode
        self._leader_gone = True
        if self.state is State.RUNNING:  # exited on its own: end what it left in its group
            self._kill_group(signal.SIGKILL)
        self.loop.call_later(STREAM_GRACE, self._close_streams, self.pid)
        self._maybe_finish()

    # --- output -----------------------------------------------------------------------------
    def _on_readable(self, fd: int, stream: str, buf: bytearray) -> None:
        data = self.system.read(fd)
        if data is None:
            return
        if not data:
            if buf:
                self._emit(stream, bytes(buf))
                buf.clear()
            self._close_stream(fd)
            return
        buf += data
        if b"\n" in data:
            *lines, rest = bytes(buf).split(b"\n")
            buf[:] = rest
            for line in lines:
                self._emit(stream, line)
        if len(buf) > 1 << 20:  # an endless line: pass it on in pieces
            self._emit(stream, bytes(buf))
            buf.clear()

    def _emit(self, stream: str, raw: bytes) -> None:
        text = raw.decode("utf-8", errors="replace").rstrip("\r")
        targets = self.spec.stdout_to if stream == "stdout" else self.spec.stderr_to
        self.hooks.line(self, Record(self.shown, text, stream), targets)

    def _close_stream(self, fd: int) -> None:
        if fd in self._streams:
            self._streams.remove(fd)
            self.loop.remove_reader(fd)
            self.system.close(fd)
            self._maybe_finish()

    def _close_streams(self, pid: int | None = None) -> None:
        if self._leader_gone and pid in (None, self.pid):
            for fd in list(self._streams):
                self._close_stream(fd)

    def _maybe_finish(self) -> None:
        if not self._leader_gone or self._streams:
            return
        if self.state is State.RUNNING:
            self._on_own_exit()
        elif self.state is State.STOPPING:
            self._check_group_gone()

    # --- exiting on its own -----------------------------------------------------------------
    def _on_own_exit(self) -> None:
        code, spec = self.returncode, self.spec
        # (ended by a signal the launch sent it, as asked: the launch caused it)
        caused = code is not None and code < 0 and -code in self._signalled
        self.failed = self.failed or (code != 0 and not caused)
        retries_left = spec.respawn_max_retries < 0 or self.respawns < spec.respawn_max_retries
        if spec.respawn and retries_left and not self._stop_requested:
            self._to(State.BACKOFF)
            self.respawns += 1
            delay = self._respawn_delay()
            if self.quick < STORM:  # (a storm is said once, when it begins: _respawn_delay)
                total = "" if spec.respawn_max_retries < 0 else f" of {spec.respawn_max_retries}"
                self._log("WARN" if code else "INFO",
                          f"process {describe_exit(code)}; respawning in {delay:g} s "
                          f"(attempt {self.respawns}{total})")
            self._gone(respawn=True)
            self._timer = self.loop.call_later(delay, self._respawn)
            return
        if spec.respawn and not retries_left and not self._stop_requested:
            self._log("ERROR", f"process {describe_exit(code)}; not respawning: it was "
                               f"respawned {self.respawns} times, its respawn_max_retries")
        elif code == 0:
            self._log("INFO", f"process has finished cleanly [pid {self.pid}]")
        else:
            self._log("ERROR", f"process {describe_exit(code)} "
                               f"[pid {self.pid}, cmd '{' '.join(spec.argv)}']")
        self._to(State.EXITED)
        self._gone(respawn=False)

    def _respawn_delay(self) -> float:
        """Its respawn_delay, as launch has it; but once a process has exited within STABLE
        seconds of its start STORM times in a row (a respawn storm), a back-off that doubles
        from its delay (from BACKOFF_FIRST when shorter) up to BACKOFF_CAP: the storm is slowed
        and said once, not looped at full speed with a line each time."""
        delay = self.spec.respawn_delay
        if self.loop.time() - self.started_at >= STABLE:
            self.quick = 0
            return delay
        self.quick += 1
        if self.quick < STORM:
            return delay
        doublings = min(self.quick - STORM, 16)  # (past the cap: no use counting on)
        backed = min(BACKOFF_CAP, max(delay, BACKOFF_FIRST) * 2 ** doublings)
        if self.quick == STORM:
            self._log("WARN", f"process {describe_exit(self.returncode)} within {STABLE:g} s "
                              f"of its start {STORM} times in a row: respawning with a "
                              f"back-off (up "
                              f"to {BACKOFF_CAP:g} s between attempts); its respawns are not "
                              f"said again until it runs {STABLE:g} s")
        return max(delay, backed)

    def _gone(self, respawn: bool) -> None:
        if self.pid is not None:
            self.hooks.group(self.pid, False)
        self.hooks.exited(self, respawn)

    def _respawn(self) -> None:
        self._timer = None
        self._start_over("respawn")

    def _start_over(self, what: str) -> bool:
        """Spawn it again (a respawn, the user's start); False when it could not start."""
        self._signalled.clear()
        self._to(State.STARTING)
        self.restarts += 1
        try:
            self.spawn()
        except OSError as exc:
            self._to(State.FATAL)
            self._log("ERROR", f"could not {what}: {exc.strerror or exc}")
            self.hooks.exited(self, False)
            return False
        return True

    # --- the user's hand (launcher stop, start, restart) -------------------------------------
    def hold(self) -> None:
        """Stop it as the launch stops it, for the user: not an exit of its own, no respawn;
        it stays stopped until start_again()."""
        self.held = True
        self.stop()

    def start_again(self) -> bool:
        """Start an exited or held process anew (same command, environment and rules);
        False when it could not start (said in the log)."""
        if self.state not in (State.EXITED, State.FATAL):
            raise RuntimeError(f"{self.label}: cannot start from {self.state.name}")
        self.held, self._stop_requested, self.quick = False, False, 0
        self.respawns = 0  # (its respawn_max_retries count from this start, as from the first)
        return self._start_over("start")

    # --- stopping ---------------------------------------------------------------------------
    def stop(self) -> None:
        """Begin the orderly stop. Safe to call more than once."""
        self._stop_requested = True
        if self.state is State.BACKOFF:
            if self._timer is not None:
                self._timer.cancel()
            self._to(State.EXITED)
            self.hooks.exited(self, False)
        elif self.state is State.RUNNING:
            self._to(State.STOPPING)
            self._signals_left = [(signal.SIGINT, self.spec.sigterm_timeout),
                                  (signal.SIGTERM, self.spec.sigkill_timeout),
                                  (signal.SIGKILL, GIVE_UP_AFTER_SIGKILL)]
            self._next_signal()

    def signal(self, sig: int) -> None:
        """Send `sig` to the running process's group (launch's SignalProcess event)."""
        if self.state is State.RUNNING or self.state is State.STOPPING:
            self._signalled.add(int(sig))
            self._kill_group(sig)

    def escalate(self) -> None:
        """Send the next signal now instead of waiting."""
        if self.state is State.STOPPING and self._signals_left:
            self._next_signal()

    def _next_signal(self) -> None:
        if self._timer is not None:
            self._timer.cancel()
        if not self._signals_left:  # SIGKILL was sent long ago: stop waiting
            self._log("ERROR", "still not gone after SIGKILL; giving up on it")
            self._finish_stop()
            return
        sig, wait = self._signals_left.pop(0)
        if sig is not signal.SIGINT:
            self._log("WARN", f"still running; sending {sig.name}")
        self._kill_group(sig)
        self._timer = self.loop.call_later(wait, self._next_signal)
        self._check_group_gone()

    def _check_group_gone(self) -> None:
        if self.state is not State.STOPPING or not self._leader_gone:
            return
        if self._group_alive():  # the leader is gone but others in its group are not
            self.loop.call_later(GROUP_POLL, self._check_group_gone)
            return
        self._finish_stop()

    def _finish_stop(self) -> None:
        if self.state is not State.STOPPING:
            return
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None
        self._to(State.EXITED)  # before closing streams, which call back into _maybe_finish
        self._close_streams()
        if self._leader_gone:
            self._log("INFO", f"process stopped: it {describe_exit(self.returncode)} "
                              f"[pid {self.pid}]")
        self._gone(respawn=False)

    def _kill_group(self, sig: int) -> None:
        if self.pid is not None:
            self.system.kill_group(self.pid, sig)

    def _group_alive(self) -> bool:
        return self.pid is not None and self.system.group_alive(self.pid)
