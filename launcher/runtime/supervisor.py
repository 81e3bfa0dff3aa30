"""The small supervisor a launch runs on another host (`launcher remote-supervisor`, started
there by ssh): it starts the launch's processes on this host and streams what they do back,
in frames (remote_frames.py) on its stdin and stdout.

It keeps no policy (respawn, escalation and exit status are the launching host's) and holds on
to what it starts as a launch does (custody.py): its mark in their environment, this process
their child subreaper, and a watchdog that ends them if this one is killed. It ends them all
and exits when the launch says `bye`, when its stdin closes, when nothing came from the launch
for `silence` seconds (a cut link: ssh would notice only hours later), and on SIGTERM, SIGINT
or SIGHUP; what it wrote for the launch (its folder, remote_files.py) goes with it.
"""

from __future__ import annotations

import errno
import os
import select
import signal
import time
from collections import deque
from collections.abc import Callable
from pathlib import Path
from typing import Any

from launcher import __version__, lineage
from launcher.errors import LaunchError
from launcher.records import dataclass
from launcher.runtime import reaper
from launcher.runtime import remote_frames as frames
from launcher.runtime.custody import TICK, Custody
from launcher.runtime.loop import EventLoop, Timer
from launcher.runtime.remote_children import Children, StartRequest
from launcher.runtime.remote_files import LaunchFolder, rewrite
from launcher.runtime.remote_frames import Decoder, Message, ProtocolError
from launcher.runtime.system import Processes

PING = 0.25  # seconds between pings until the launch says otherwise
HELLO_WAIT = 10.0  # seconds a launch may take to say hello (its ssh's set-up is over)
GRACE = 0.75  # seconds between SIGTERM and SIGKILL at the end
HIGH_WATER = 8 << 20  # bytes queued for the launch above which output is no longer read
LOW_WATER = 1 << 20  # … and below which it is again
FLUSH_WAIT = 1.0  # seconds the last frames may take to leave

# (package, executable, environment) → (the executable's words, its environment); a
# LaunchError says what is not on this host
Resolve = Callable[[str, str, dict[str, str]], tuple[list[str], dict[str, str]]]


@dataclass(frozen=True)
class Host:
    """What this host gives the supervisor (the cli's set-up: its packages, its bus)."""

    name: str
    environment: dict[str, str]  # the children's: this host's, its hooks, shims and tools
    run_folder: Path
    resolve: Resolve
    # how this host joins the launch's graph: the hello's "graph" (and its "domain") → the
    # variables a process here needs for it; a LaunchError says why it cannot
    join_graph: Callable[[LaunchFolder, dict[str, Any]], dict[str, str]]


class Outbox:
    """Frames for the launch, written as fast as its end of the channel takes them:
    non-blocking, queued on the loop. `full(True)` when more than HIGH_WATER waits,
    `full(False)` once less than LOW_WATER does; `broken()` when the channel is gone."""

    def __init__(self, loop: EventLoop, fd: int, full: Callable[[bool], None],
                 broken: Callable[[], None]) -> None:
        self.loop, self.fd, self.full, self.broken = loop, fd, full, broken
        self._queue: deque[memoryview] = deque()
        self.queued = 0
        self._full = False
        self.closed = False

    def send(self, frame: bytes) -> None:
        if self.closed or not frame:
            return
        if not self._queue:
            self.loop.add_writer(self.fd, self._writable)
        self._queue.append(memoryview(frame))
        self.queued += len(frame)
        if not self._full and self.queued > HIGH_WATER:
            self._full = True
            self.full(True)

    def _writable(self) -> None:
        try:
            self._write()
        except BlockingIOError:
            pass
        except OSError:
            self._break()
            return
        if not self._queue:
            self.loop.remove_writer(self.fd)
        if self._full and self.queued < LOW_WATER:
            self._full = False
            self.full(False)

    def _write(self) -> None:
        while self._queue:
            head = self._queue[0]
            written = os.write(self.fd, head)
            self.queued -= written
            if written < len(head):
                self._queue[0] = head[written:]
                return
            self._queue.popleft()

    def _break(self) -> None:
        self.closed = True
        self._queue.clear()
        self.loop.remove_writer(self.fd)
        self.broken()

    def flush(self, timeout: float) -> None:
        """Write what is queued (at the end: the loop no longer runs), for up to `timeout`."""
        deadline = time.monotonic() + timeout
        while self._queue and not self.closed and time.monotonic() < deadline:
            select.select([], [self.fd], [], max(0.0, deadline - time.monotonic()))
            try:
                self._write()
            except BlockingIOError:
                continue
            except OSError:
                self.closed = True


class Supervisor:
    def __init__(self, loop: EventLoop, system: Processes, custody: Custody, host: Host,
                 stdin: int, stdout: int) -> None:
        """`custody` has begun (its watchdog forked before any thread); `stdin` and `stdout`
        are the channel's (stdout a private copy: fd 1 points elsewhere, so that a stray
        print cannot break the frames)."""
        self.loop, self.custody, self.host = loop, custody, host
        self.stdin = stdin
        self.outbox = Outbox(loop, stdout, self._full, lambda: self.end("the launch's end of "
                                                                        "the channel closed"))
        self.children = Children(loop, system, self.outbox.send, custody.group, self._gone)
        self.decoder = Decoder()
        self.folder: LaunchFolder | None = None
        self.graph: dict[str, str] = {}  # variables that join a process to the launch's graph
        self.unjoined = ""  # why this host could not join the launch's graph
        self.domain: int | None = None
        self.ping, self.silence = PING, HELLO_WAIT
        self.heard = loop.time()
        self._silence_timer: Timer | None = None
        self.code: int | None = None  # the exit status, once ending

    def run(self) -> int:
        os.write(self.outbox.fd, frames.magic_line())  # (blocking: the first bytes)
        for fd in (self.stdin, self.outbox.fd):
            os.set_blocking(fd, False)
        for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
            self.loop.add_signal_handler(sig, self._on_signal)
        if self.custody.subreaper:  # collect what is left to this process as it exits
            self.loop.add_signal_handler(signal.SIGCHLD, lambda _sig: self._adopt())
            self.loop.call_later(TICK, self._tick)
        self.loop.add_reader(self.stdin, self._readable)
        self._pinging()
        self._watch_silence()
        try:
            self.loop.run()
        except BaseException:  # a fault of its own: what it started still ends with it
            self.end("it failed", 1)
            raise
        finally:
            self.loop.close()
        return self.code or 0

    # --- the channel --------------------------------------------------------------------------
    def _readable(self) -> None:
        try:
            data = os.read(self.stdin, 1 << 16)
        except BlockingIOError:
            return
        except OSError as exc:
            self.end(f"cannot read the channel: {exc.strerror}", 1)
            return
        if not data:
            self.end("the channel closed (the launch, or its ssh, ended)")
            return
        self.heard = self.loop.time()
        try:
            for frame in self.decoder.feed(data):
                if self.code is not None:
                    return
                if isinstance(frame, Message):
                    self._dispatch(frame.body)
        except ProtocolError as exc:
            self._log("ERROR", f"the launch sent what the protocol does not allow: {exc}")
            self.end(str(exc), 1)

    def _pinging(self) -> None:
        if self.code is None:
            self.outbox.send(frames.message({"t": "ping"}))
            self.loop.call_later(self.ping, self._pinging)

    def _watch_silence(self) -> None:
        """After the readers have run (the loop runs them before timers), so that a busy
        supervisor does not take its own delay for the launch's silence."""
        due = self.heard + self.silence
        if self.loop.time() >= due:
            self.end(f"nothing heard from the launch for {self.silence:g} s", 1)
            return
        self._silence_timer = self.loop.call_later(due - self.loop.time(), self._watch_silence)

    def _log(self, level: str, text: str) -> None:
        self.outbox.send(frames.message({"t": "log", "level": level, "text": text}))

    def _full(self, full: bool) -> None:
        self.children.pause(full)

    # --- messages -----------------------------------------------------------------------------
    def _dispatch(self, body: dict[str, Any]) -> None:
        kind = body["t"]
        if kind == "ping":
            return
        if kind == "hello":
            self._hello(body)
        elif kind == "start":
            self._start(body)
        elif kind == "signal":
            self._signal(body)
        elif kind == "graph":
            self._join(body)
        elif kind == "bye":
            self.end("the launch said bye", bye=True)
        else:  # a newer launch's: it learns this one does not know it
            self._log("WARN", f"{self.host.name}: launcher {__version__} does not know the "
                              f"message {kind!r}; ignored")

    def _hello(self, body: dict[str, Any]) -> None:
        if self.folder is not None:
            raise ProtocolError("a second hello")
        ping, silence = body.get("ping"), body.get("silence")
        if not all(isinstance(v, int | float) and not isinstance(v, bool) and v > 0
                   for v in (ping, silence)):
            raise ProtocolError(f"hello: ping {ping!r} and silence {silence!r}: expected "
                                "seconds > 0")
        domain, graph = body.get("domain"), body.get("graph")
        if domain is not None and (not isinstance(domain, int) or isinstance(domain, bool)):
            raise ProtocolError(f"hello: domain {domain!r}: expected a number or null")
        if graph is not None and not isinstance(graph, dict):
            raise ProtocolError(f"hello: graph {str(graph)[:80]!r}: expected null or "
                                "{\"router\": an endpoint, \"credentials\": their text}")
        try:
            self.folder = LaunchFolder(self.host.run_folder, str(body.get("launch")))
        except LaunchError as exc:
            raise ProtocolError(f"hello: {exc}") from None
        self.ping, self.silence, self.domain = float(ping), float(silence), domain
        if self._silence_timer is not None:  # (it waited for the hello: now the launch's)
            self._silence_timer.cancel()
        self._watch_silence()
        if graph is not None:
            self._join(graph)
        self.outbox.send(frames.message({"t": "ready", "host": self.host.name,
                                         "pid": os.getpid(),
                                         "ssh": os.environ.get("SSH_CONNECTION", "")}))

    def _join(self, graph: dict[str, Any]) -> None:
        """The processes started from now on join the launch's graph (hello's "graph", or a
        `graph` message once the launch knows the address this host reaches it at)."""
        if self.folder is None:
            raise ProtocolError("graph before hello")
        if not (isinstance(graph.get("router"), str) and isinstance(graph.get("credentials"),
                                                                     str)):
            raise ProtocolError("graph: expected {\"router\": an endpoint, \"credentials\": "
                                "their text}")
        try:
            self.graph = self.host.join_graph(self.folder, {**graph, "domain": self.domain})
        except LaunchError as exc:  # (no way back to the launch's graph: its starts fail)
            self.unjoined = str(exc)
            self._log("ERROR", self.unjoined)
        self.heard = self.loop.time()  # (joining was this side's wait, not the launch's silence)

    def _start(self, body: dict[str, Any]) -> None:
        ident = body.get("id")
        if not isinstance(ident, int) or isinstance(ident, bool):
            raise ProtocolError(f"start: 'id' is {ident!r}; expected a number")
        if ident in self.children.running:
            self._failed(ident, errno.EEXIST, f"process id {ident} is still running")
            return
        if self.folder is None:
            raise ProtocolError("start before hello")
        argv: list[str] = []
        try:
            request = StartRequest.parse(body)
            argv, env = self._command(request)
            pid = self.children.start(ident, argv, env, request.cwd, request.tty)
        except ProtocolError as exc:
            self._failed(ident, errno.EINVAL, str(exc))
        except LaunchError as exc:  # (not on this host: a package, an executable)
            self._failed(ident, errno.ENOENT, str(exc))
        except OSError as exc:  # (not found, not executable, a bad cwd, a full disk)
            self.folder.forget(ident)
            what = f"'{argv[0]}'" if argv else f"process {ident}"
            self._failed(ident, exc.errno or errno.EIO,
                         f"cannot start {what} on {self.host.name}: {exc.strerror or exc}")
        else:
            self.outbox.send(frames.message({"t": "started", "id": ident, "pid": pid}))

    def _failed(self, ident: int, number: int, text: str) -> None:
        self.outbox.send(frames.message({"t": "failed", "id": ident, "errno": number,
                                         "text": text}))

    def _command(self, request: StartRequest) -> tuple[list[str], dict[str, str]]:
        """Its argv and environment here: this host's environment with the launch's changes,
        its executable found here, its files written here and their paths rewritten."""
        if self.unjoined:
            raise LaunchError(self.unjoined)
        env = {k: v for k, v in self.host.environment.items() if k not in request.env_unset}
        if self.domain is not None:
            env["ROS_DOMAIN_ID"] = str(self.domain)
        # (the launching host's marks mean nothing here, and a process marked detached would
        # be passed over by the clean-up)
        env.update({k: v for k, v in request.env_set.items()
                    if not k.startswith(lineage.MARK_PREFIX) and k != lineage.DETACHED})
        env.update(self.graph)
        words: list[str] = []
        if request.package is not None:
            words, env = self.host.resolve(request.package, request.executable or "", env)
        elif request.executable is not None:  # launch_ros: an executable without a package
            words = [request.executable]
        argv = [*request.argv[:request.at], *words, *request.argv[request.at:]]
        if not argv:
            raise ProtocolError("start: nothing to run (argv and executable are empty)")
        assert self.folder is not None
        argv, env = rewrite(argv, env, self.folder.ship(request.ident, request.files))
        return argv, self.custody.stamp(env)

    def _signal(self, body: dict[str, Any]) -> None:
        ident, sig = body.get("id"), body.get("sig")
        if not isinstance(ident, int) or not isinstance(sig, int) or \
                not 0 < sig < signal.NSIG:
            raise ProtocolError(f"signal: id {ident!r}, sig {sig!r}: expected numbers (a "
                                f"signal 1 to {signal.NSIG - 1})")
        self.children.signal(ident, sig)

    def _gone(self, ident: int) -> None:
        if self.folder is not None:
            self.folder.forget(ident)

    # --- adopted processes --------------------------------------------------------------------
    def _adopt(self) -> None:
        """Note what was left to this process (for the watchdog), collect what has exited."""
        if self.code is None:
            self.custody.tick(self.children.leaders())

    def _tick(self) -> None:
        if self.code is None:
            self._adopt()
            self.loop.call_later(TICK, self._tick)

    # --- the end ------------------------------------------------------------------------------
    def _on_signal(self, sig: int) -> None:
        self.end(f"received {signal.Signals(sig).name}", 128 + sig)

    def end(self, reason: str, code: int = 0, bye: bool = False) -> None:
        """End every process of the launch here (their groups, and whatever carries the mark:
        daemons too), remove the launch's folder, and exit; after `bye`, say `done`."""
        if self.code is not None:
            return
        self.code = code
        self.loop.remove_reader(self.stdin)
        if self._silence_timer is not None:
            self._silence_timer.cancel()
        self.children.end_all()
        left = self._clean_up()
        if self.folder is not None:
            self.folder.remove()
        self.custody.end(nothing_left=not left)
        if code:
            os.write(2, f"launcher remote-supervisor: {reason}\n".encode())
        if bye:
            self.outbox.send(frames.message({"t": "done", "left": len(left)}))
        self.outbox.flush(FLUSH_WAIT)
        self.loop.stop()

    def _clean_up(self) -> set[int]:
        """SIGTERM to everything of the launch, SIGKILL GRACE seconds later; what is left."""
        launch = reaper.Launch(self.custody.mark)
        launch.groups = self.children.groups()
        launch.pids = self.custody.leftovers()
        launch.clean_up(grace=GRACE)
        return self.custody.leftovers()
