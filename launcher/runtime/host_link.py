"""One other host's link: the ssh process that runs launcher's supervisor there
(`launcher remote-supervisor`), and the frames both ways (remote_frames.py).

Opening it waits, up to the machine's `timeout`, for the supervisor's first line and its
`ready`; whatever a shell or an env-loader printed before that first line is passed over. After
that the link's frames are read on the loop and handed to `on_message` / `on_output`. Frames
to the host go through a writer thread, which also pings whenever `PING` seconds pass without
a frame: a busy loop (a slow xacro) is not mistaken for a dead launcher over there. A link
that hears nothing for `silence` seconds, or whose ssh ends, is lost: `on_lost(reason)` once.

Liveness is the link's own, not ssh's: sshd notices a cut cable only after TCP's keepalive,
and a command run without a terminal gets no SIGHUP when its connection drops.
"""

from __future__ import annotations

import contextlib
import os
import queue
import selectors
import subprocess
import threading
import time
from collections.abc import Callable, Mapping
from typing import Any

from launcher.errors import LaunchError
from launcher.runtime import remote_frames, ssh
from launcher.runtime.loop import EventLoop, Timer
from launcher.runtime.machine import Machine

PING = 0.25  # s between two signs of life, each way
SILENCE_VARIABLE = "LAUNCHER_LINK_TIMEOUT"
SILENCE = 0.75  # s without a frame after which a link is taken as lost
STDERR_KEPT = 8192  # bytes of ssh's own stderr kept to explain a failure
SLICE = 0.05  # s: the longest a wait on a link goes without looking at signals


def silence(environ: Mapping[str, str]) -> float:
    text = environ.get(SILENCE_VARIABLE, "")
    try:
        value = float(text) if text else SILENCE
    except ValueError:
        raise LaunchError(f"{SILENCE_VARIABLE}={text!r}: expected seconds, a number > 0") \
            from None
    if value <= 0:
        raise LaunchError(f"{SILENCE_VARIABLE}={text!r}: expected seconds, a number > 0")
    return value


class HostLink:
    def __init__(self, machine: Machine, loop: EventLoop, control_path: str,
                 environ: Mapping[str, str], stamp: Callable[[dict[str, str]], dict[str, str]],
                 log: Callable[[str, str], None]) -> None:
        """`stamp` marks ssh's environment as the launch's (the watchdog ends it if the
        launcher is killed); `log(level, text)` says what the host said."""
        self.machine, self.loop, self.log = machine, loop, log
        self._control_path, self._environ, self._stamp = control_path, environ, stamp
        self.silence = silence(environ)
        self.ready: dict[str, Any] = {}
        self.on_message: Callable[[dict[str, Any]], None] = lambda body: None
        self.on_output: Callable[[int, int, bytes], None] = lambda ident, stream, data: None
        self.on_lost: Callable[[str], None] = lambda reason: None
        self.lost = ""  # why, once lost
        self._ssh: subprocess.Popen[bytes] | None = None
        self._decoder = remote_frames.Decoder(magic=True)
        self._stderr = bytearray()
        self._outbox: queue.SimpleQueue[bytes | None] = queue.SimpleQueue()
        self._writer: threading.Thread | None = None
        self._heard = 0.0
        self._watch: Timer | None = None
        self._read_fds: tuple[int, ...] = ()

    @property
    def name(self) -> str:
        return self.machine.name

    # --- opening ----------------------------------------------------------------------------
    def open(self, hello: dict[str, Any]) -> dict[str, Any]:
        """Start ssh, send `hello`, wait for the supervisor's `ready`; its body. A LaunchError
        says why it failed (in the words of ssh.explain), with nothing left running."""
        env = self._stamp(dict(self._environ))
        command = ssh.argv(self.machine, self._control_path, self._environ)
        try:
            self._ssh = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                         stderr=subprocess.PIPE, env=env,
                                         start_new_session=True, close_fds=True)
        except OSError as exc:
            raise LaunchError(f"{ssh.describe(self.machine)}: cannot run "
                              f"'{command[0]}' ({exc.strerror}); is OpenSSH's client "
                              f"installed ({ssh.VARIABLE} chooses another)?") from None
        for stream in (self._ssh.stdout, self._ssh.stderr):
            os.set_blocking(stream.fileno(), False)  # type: ignore[union-attr]
        self._writer = threading.Thread(target=self._write_all, name=f"link-{self.name}",
                                        daemon=True)
        self._writer.start()
        self.send(hello)
        try:
            self.ready = self._wait_ready(time.monotonic() + self.machine.timeout)
        except BaseException:  # (a failure, or Ctrl-C while it connects: no ssh left)
            self._kill()
            raise
        self._heard = self.loop.time()
        self._read_fds = (self._ssh.stdout.fileno(), self._ssh.stderr.fileno())  # type: ignore[union-attr]
        self.loop.add_reader(self._read_fds[0], self._on_readable)
        self.loop.add_reader(self._read_fds[1], self._on_stderr)
        self._watch = self.loop.call_later(PING, self._check_silence)
        return self.ready

    def _wait_ready(self, deadline: float) -> dict[str, Any]:
        """Read until the supervisor's first frame (`ready`), ssh's stderr kept."""
        assert self._ssh is not None and self._ssh.stdout and self._ssh.stderr
        out, err = self._ssh.stdout.fileno(), self._ssh.stderr.fileno()
        with selectors.DefaultSelector() as selector:
            selector.register(out, selectors.EVENT_READ)
            selector.register(err, selectors.EVENT_READ)
            while True:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise LaunchError(self._failure(
                        f"{ssh.describe(self.machine)}: did not answer within "
                        f"{self.machine.timeout:g} s (timeout=)"))
                # (in slices: a signal taken by another thread runs its handler here only
                # when this thread next runs Python, and Ctrl-C must not wait for `timeout`)
                for key, _ in selector.select(min(left, SLICE)):
                    data = _read(key.fd)
                    if key.fd == err:
                        self._stderr += data or b""
                        if data == b"":
                            selector.unregister(err)
                        continue
                    if data == b"":  # ssh ended before the supervisor spoke
                        self._ssh.wait(5)
                        raise LaunchError(ssh.explain(self.machine, self._ssh.returncode,
                                                      self._stderr_text(err)))
                    for frame in self._feed(data or b""):
                        if isinstance(frame, remote_frames.Message) and \
                                frame.body.get("t") == "ready":
                            return frame.body

    def _feed(self, data: bytes) -> list[remote_frames.Message | remote_frames.Output]:
        """Frames from `data`; what a shell or env-loader printed first is said at DEBUG."""
        try:
            frames = self._decoder.feed(data)
        except remote_frames.ProtocolMismatch as exc:
            raise LaunchError(f"{ssh.describe(self.machine)} runs launcher {exc.version} "
                              f"(remote protocol {exc.protocol}); this host speaks protocol "
                              f"{remote_frames.PROTOCOL}: install the same launcher on "
                              "both") from None
        for line in self._decoder.noise:
            self.log("DEBUG", line.decode("utf-8", "replace"))
        self._decoder.noise.clear()
        return frames

    def _stderr_text(self, err: int) -> str:
        with contextlib.suppress(OSError):
            while chunk := _read(err):
                self._stderr += chunk
        return self._stderr[-STDERR_KEPT:].decode("utf-8", "replace")

    def _failure(self, text: str) -> str:
        said = [line for line in self._stderr.decode("utf-8", "replace").splitlines()
                if line.strip()][-3:]
        return text + (f"; ssh said: {'; '.join(said)}" if said else "")

    # --- running ----------------------------------------------------------------------------
    def send(self, body: dict[str, Any]) -> None:
        if not self.lost:
            self._outbox.put(remote_frames.message(body))

    def _write_all(self) -> None:
        """The writer thread: frames in order, and a ping whenever PING passes without one."""
        assert self._ssh is not None and self._ssh.stdin is not None
        ping = remote_frames.message({"t": "ping"})
        stdin = self._ssh.stdin
        while True:
            try:
                frame = self._outbox.get(timeout=PING)
            except queue.Empty:
                frame = ping
            if frame is None:
                break
            try:
                stdin.write(frame)
                stdin.flush()
            except (OSError, ValueError):  # ssh is gone: the reader says so
                break
        with contextlib.suppress(OSError, ValueError):
            stdin.close()

    @property
    def stdout_fd(self) -> int:
        assert self._ssh is not None and self._ssh.stdout is not None
        return self._ssh.stdout.fileno()

    def read_now(self) -> None:
        """Read what the host sent, now (a start waiting for its answer)."""
        self._on_readable()

    def _on_readable(self) -> None:
        assert self._ssh is not None and self._ssh.stdout is not None
        data = _read(self._ssh.stdout.fileno())
        if data is None:
            return
        if data == b"":
            self._lose(f"its connection ended{self._exit_said()}")
            return
        self._heard = self.loop.time()
        try:
            frames = self._feed(data)
        except LaunchError as exc:
            self._lose(f"it sent what launcher cannot read ({exc})")
            return
        for frame in frames:
            if isinstance(frame, remote_frames.Output):
                self.on_output(frame.ident, frame.stream, frame.data)
            elif frame.body.get("t") == "log":
                self.log(str(frame.body.get("level", "INFO")), str(frame.body.get("text", "")))
            elif frame.body.get("t") != "ping":
                self.on_message(frame.body)
            if self.lost:
                return

    def _on_stderr(self) -> None:
        assert self._ssh is not None and self._ssh.stderr is not None
        data = _read(self._ssh.stderr.fileno())
        if data == b"":
            self.loop.remove_reader(self._ssh.stderr.fileno())
            self._read_fds = self._read_fds[:1]
        elif data:
            self._stderr = (self._stderr + data)[-STDERR_KEPT:]
            for line in data.decode("utf-8", "replace").splitlines():
                if line.strip():
                    self.log("WARN", line)

    def _check_silence(self) -> None:
        self._watch = None
        if self.lost:
            return
        quiet = self.loop.time() - self._heard
        if quiet > self.silence:
            self._lose(f"nothing heard for {quiet:.2f} s")
            return
        self._watch = self.loop.call_later(PING, self._check_silence)

    def _exit_said(self) -> str:
        if self._ssh is None:
            return ""
        with contextlib.suppress(subprocess.TimeoutExpired):
            self._ssh.wait(0.2)
        said = self._stderr.decode("utf-8", "replace").strip().splitlines()[-1:]
        return f" ({said[0]})" if said else ""

    def _lose(self, reason: str) -> None:
        if self.lost:
            return
        self.lost = reason
        self._close_readers()
        self._kill()
        self.on_lost(reason)

    # --- closing ----------------------------------------------------------------------------
    def say_goodbye(self) -> None:
        """Ask the supervisor to end what is left and exit (it answers `done`)."""
        self.send({"t": "bye"})

    def close(self) -> None:
        """End the link now (after `done`, or when waiting longer is pointless)."""
        if not self.lost:
            self.lost = "closed"
        self._close_readers()
        self._outbox.put(None)
        if self._ssh is not None and self._ssh.poll() is None:
            with contextlib.suppress(subprocess.TimeoutExpired):
                self._ssh.wait(0.5)  # (it ends once the supervisor has)
        self._kill()

    def _close_readers(self) -> None:
        if self._watch is not None:
            self._watch.cancel()
            self._watch = None
        for fd in self._read_fds:
            self.loop.remove_reader(fd)
        self._read_fds = ()

    def _kill(self) -> None:
        self._outbox.put(None)
        if self._ssh is None:
            return
        if self._ssh.poll() is None:
            with contextlib.suppress(ProcessLookupError):
                self._ssh.kill()
            self._ssh.wait()
        for stream in (self._ssh.stdout, self._ssh.stderr):
            if stream is not None:
                with contextlib.suppress(OSError):
                    stream.close()

    @property
    def pid(self) -> int | None:
        return self._ssh.pid if self._ssh is not None else None


def _read(fd: int) -> bytes | None:
    try:
        return os.read(fd, 1 << 16)
    except BlockingIOError:
        return None
