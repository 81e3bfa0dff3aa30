"""`launcher remote-supervisor`, what a launch runs on another host over ssh, driven over its
pipes by the test playing the launch's end (no ssh needed): processes started there, their
output, exit and group told in order, nodes found in that host's packages, files shipped, and
everything it started ended, daemons included, however the link ends."""

from __future__ import annotations

import contextlib
import os
import select
import signal
import socket
import stat
import subprocess
import sys
import time
import uuid
from collections.abc import Callable
from pathlib import Path

import psutil
import pytest

from launcher.runtime import remote_frames as frames
from launcher.runtime.remote_frames import Decoder, Message, Output
from tests.support.packages import make_tree, manifest
from tests.support.processes import launcher_argv
from tests.support.workspace import Workspace

PING = 0.2  # seconds between the test's pings
# double-forks into its own session, says its pid, and sleeps (its pipes held open)
DAEMON = ("import os, sys, time\n"
          "if os.fork(): os._exit(0)\n"
          "os.setsid()\n"
          "if os.fork(): os._exit(0)\n"
          "os.write(1, b'daemon %d\\n' % os.getpid())\n"
          "time.sleep(120)\n")


class Channel:
    """The launch's end of the channel: a supervisor on pipes, frames both ways."""

    def __init__(self, ws: Workspace, env: dict[str, str] | None = None) -> None:
        self.launch = uuid.uuid4().hex[:16]
        self.errors = open(ws.root / "supervisor.err", "wb")  # noqa: SIM115
        self.process = subprocess.Popen([*launcher_argv(), "remote-supervisor"],
                                        stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        stderr=self.errors, cwd=ws.root,
                                        env={**ws.env, **(env or {})})
        self.run_folder = Path((env or {}).get("LAUNCHER_RUN_DIR") or ws.env["LAUNCHER_RUN_DIR"])
        self.decoder = Decoder(magic=True)
        self.frames: list[Message | Output] = []
        self.pinging = True
        self.ended = False  # its stdout closed
        self._pinged = 0.0

    def send(self, body: dict) -> None:
        self.process.stdin.write(frames.message(body))
        self.process.stdin.flush()

    def hello(self, **fields) -> dict:
        self.send({"t": "hello", "launch": self.launch, "ping": 0.25, "silence": 0.75,
                   "domain": 0, "graph": None, **fields})
        return self.wait_for(lambda b: b["t"] == "ready")

    def start(self, ident: int, argv: list[str], **fields) -> dict:
        self.send({"t": "start", "id": ident, "label": f"p-{ident}", "argv": argv,
                   "package": None, "executable": None, "at": 0, "env_set": {},
                   "env_unset": [], "cwd": None, "tty": False, "files": [], **fields})
        return self.wait_for(lambda b: b["t"] in ("started", "failed") and b["id"] == ident)

    def read(self, timeout: float) -> None:
        """Read what comes within `timeout`, pinging as a live launch does."""
        if self.pinging and time.monotonic() - self._pinged > PING:
            self._pinged = time.monotonic()
            if self.process.poll() is None:
                self.send({"t": "ping"})
        ready, _, _ = select.select([self.process.stdout], [], [], timeout)
        if not ready:
            return
        data = os.read(self.process.stdout.fileno(), 1 << 20)
        if not data:
            self.ended = True
            return
        self.frames += self.decoder.feed(data)

    def wait_for(self, wanted: Callable[[dict], bool], timeout: float = 15.0) -> dict:
        deadline = time.monotonic() + timeout
        seen = 0
        while time.monotonic() < deadline and not self.ended:
            for frame in self.frames[seen:]:
                if isinstance(frame, Message) and wanted(frame.body):
                    return frame.body
            seen = len(self.frames)
            self.read(0.05)
        raise AssertionError(f"not received; got {self.messages()}")

    def wait_until_ended(self, timeout: float = 10.0) -> int:
        """Its exit status, once its stdout has closed."""
        deadline = time.monotonic() + timeout
        while not self.ended and time.monotonic() < deadline:
            self.read(0.05)
        assert self.ended, f"still running; got {self.messages()}"
        return self.process.wait(timeout)

    def messages(self, kind: str | None = None) -> list[dict]:
        return [f.body for f in self.frames if isinstance(f, Message) and f.body["t"] != "ping"
                and kind in (None, f.body["t"])]

    def output(self, ident: int, stream: int = frames.STDOUT) -> bytes:
        return b"".join(f.data for f in self.frames
                        if isinstance(f, Output) and (f.ident, f.stream) == (ident, stream))

    def wait_for_output(self, ident: int, needle: bytes, timeout: float = 15.0) -> bytes:
        deadline = time.monotonic() + timeout
        while needle not in self.output(ident) and time.monotonic() < deadline:
            self.read(0.05)
        assert needle in self.output(ident), self.output(ident)
        return self.output(ident)

    def close(self) -> None:
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        for stream in (self.process.stdin, self.process.stdout):
            with contextlib.suppress(BrokenPipeError):  # (a frame it never read)
                stream.close()
        self.errors.close()


@pytest.fixture
def channel(ws):
    made = Channel(ws)
    made.hello()
    yield made
    made.close()


def gone(pids: list[int], timeout: float = 5.0) -> list[int]:
    """Those of `pids` still running after `timeout` (zombies count as gone)."""
    deadline = time.monotonic() + timeout
    while True:
        left = [pid for pid in pids if _running(pid)]
        if not left or time.monotonic() > deadline:
            return left
        time.sleep(0.02)


def _running(pid: int) -> bool:
    try:
        return psutil.Process(pid).status() != psutil.STATUS_ZOMBIE
    except psutil.NoSuchProcess:
        return False


def daemon_pid(channel: Channel, ident: int) -> int:
    text = channel.wait_for_output(ident, b"daemon ").decode()
    return int(text.split("daemon ")[1].split()[0])


def start_a_sleeper_and_a_daemon(channel: Channel) -> list[int]:
    """pids of a process and of a daemon another one left (in a session of its own)."""
    sleeper = channel.start(1, ["sleep", "120"])["pid"]
    channel.start(2, [sys.executable, "-c", DAEMON])
    return [sleeper, daemon_pid(channel, 2)]


# --- processes there ----------------------------------------------------------------------------
def test_it_says_who_it_is_after_the_magic_line_and_nothing_before(ws):
    made = Channel(ws, {"SSH_CONNECTION": "10.0.0.1 51234 10.0.0.2 22"})
    ready = made.hello()
    assert made.decoder.noise == [] and made.decoder.peer[0] == frames.PROTOCOL
    assert ready == {"t": "ready", "host": socket.gethostname(), "pid": made.process.pid,
                     "ssh": "10.0.0.1 51234 10.0.0.2 22"}
    made.send({"t": "bye"})
    assert made.wait_until_ended() == 0
    made.close()


def test_a_command_runs_and_its_output_then_its_ends_come_back_in_order(channel):
    started = channel.start(1, ["sh", "-c", "echo out; echo err >&2; exit 3"])
    channel.wait_for(lambda b: b["t"] == "group")
    assert channel.output(1) == b"out\n" and channel.output(1, frames.STDERR) == b"err\n"
    ends = [b for b in channel.messages() if b.get("id") == 1][1:]
    assert sorted(ends[:2], key=lambda b: b["stream"]) == [
        {"t": "eof", "id": 1, "stream": 1}, {"t": "eof", "id": 1, "stream": 2}]
    assert ends[2:] == [{"t": "exited", "id": 1, "code": 3},
                        {"t": "group", "id": 1, "alive": False}]
    assert gone([started["pid"]]) == []


def test_a_signal_frame_stops_its_process(channel):
    pid = channel.start(1, ["sleep", "120"])["pid"]
    channel.send({"t": "signal", "id": 1, "sig": int(signal.SIGTERM)})
    assert channel.wait_for(lambda b: b["t"] == "exited")["code"] == -signal.SIGTERM
    channel.wait_for(lambda b: b["t"] == "group")
    assert gone([pid]) == []


def test_a_command_that_is_not_there_fails_with_its_errno(channel):
    failed = channel.start(1, ["/nonexistent/talker"])
    assert failed == {"t": "failed", "id": 1, "errno": 2,
                      "text": f"cannot start '/nonexistent/talker' on {socket.gethostname()}: "
                              f"No such file or directory"}


def test_a_flood_of_output_arrives_whole_while_the_supervisor_holds_little(channel):
    """A launch slow to read: the supervisor stops reading the process (which then waits)
    rather than keeping all it writes."""
    size = 64 << 20
    pid = channel.start(1, ["head", "-c", str(size), "/dev/zero"])["pid"]
    supervisor = psutil.Process(channel.process.pid)
    before = supervisor.memory_info().rss
    deadline = time.monotonic() + 1.5
    while time.monotonic() < deadline:  # pinging, not reading
        channel.send({"t": "ping"})
        time.sleep(PING)
    held = supervisor.memory_info().rss - before
    assert _running(pid)  # (it waits for the launch)
    channel.wait_for(lambda b: b["t"] == "exited", timeout=60)
    assert len(channel.output(1)) == size
    assert held < 32 << 20, f"the supervisor grew by {held >> 20} MiB"


# --- nodes found on this host ---------------------------------------------------------------------
@pytest.fixture
def package_channel(ws):
    make_tree(ws.root / "src", {
        "demo/package.xml": manifest("demo"),
        "demo/scripts/talker": "#!/bin/sh\necho \"$GREETING from talker: $*\"\n",
    }, executable=("demo/scripts/talker",))
    made = Channel(ws, {"LAUNCHER_PACKAGE_PATH": str(ws.root / "src")})
    made.hello()
    yield made
    made.close()


def test_a_nodes_executable_is_found_in_this_hosts_packages_and_put_where_the_launch_said(
        package_channel):
    started = package_channel.start(1, ["env", "GREETING=hello", "--ros-args", "-r",
                                        "__node:=talker"],
                                    package="demo", executable="talker", at=2)
    assert started["t"] == "started", started
    package_channel.wait_for(lambda b: b["t"] == "exited")
    assert package_channel.output(1) == b"hello from talker: --ros-args -r __node:=talker\n"


def test_a_package_not_on_this_host_fails_saying_where_it_looked(package_channel, ws):
    failed = package_channel.start(1, [], package="demu", executable="talker")
    assert failed["t"] == "failed" and failed["errno"] == 2
    assert failed["text"].startswith(f"package 'demu' not found on {socket.gethostname()} "
                                     f"(did you mean 'demo'?); searched: ")
    assert f"{ws.root / 'src'} (workspace)" in failed["text"]


def test_an_executable_not_in_the_package_fails_naming_the_host(package_channel):
    failed = package_channel.start(1, [], package="demo", executable="talkr")
    assert failed["text"] == (f"on {socket.gethostname()}: package 'demo' has no executable "
                              f"'talkr' (did you mean 'talker'?); it has: talker")


def test_a_shipped_params_file_is_written_here_0600_and_its_path_rewritten(channel):
    local = "/on/the/launching/host/params/talker.yaml"
    text = "talker:\n  ros__parameters:\n    rate: 5\n"
    channel.start(1, ["sh", "-c", 'cat "$1"; stat -c %a "$1"; echo "$PARAMS"', "sh", local],
                  env_set={"PARAMS": f"__params:={local}"},
                  files=[{"path": local, "text": text}])
    channel.wait_for(lambda b: b["t"] == "exited")
    here = channel.run_folder / "launches" / channel.launch / "files" / "1" / "talker.yaml"
    assert channel.output(1).decode() == f"{text}600\n__params:={here}\n"
    channel.send({"t": "bye"})
    channel.wait_for(lambda b: b["t"] == "done")
    assert not (channel.run_folder / "launches" / channel.launch).exists()


def test_the_graphs_credentials_are_written_here_0600_for_the_hosts_bridge(channel):
    channel.send({"t": "graph", "router": "tcp/127.0.0.1:1", "credentials": "launcher:pw\n"})
    channel.wait_for(lambda b: b["t"] == "log")  # (nothing listens there: the bridge failed)
    credentials = channel.run_folder / "launches" / channel.launch / "credentials"
    assert credentials.read_text() == "launcher:pw\n"
    assert stat.S_IMODE(credentials.stat().st_mode) == 0o600


# --- however the link ends, nothing is left -------------------------------------------------------
def test_bye_ends_everything_then_says_done_and_exits_0(channel):
    pids = start_a_sleeper_and_a_daemon(channel)
    channel.send({"t": "bye"})
    assert channel.wait_for(lambda b: b["t"] == "done") == {"t": "done", "left": 0}
    assert gone(pids, timeout=0) == []  # (before it said done)
    assert channel.wait_until_ended() == 0
    assert not (channel.run_folder / "launches" / channel.launch).exists()


def test_silence_from_the_launch_ends_everything_it_started_a_daemon_included(channel):
    pids = start_a_sleeper_and_a_daemon(channel)
    channel.pinging = False
    began = time.monotonic()
    assert channel.wait_until_ended() == 1
    assert time.monotonic() - began < 3.0
    assert gone(pids, timeout=0) == []
    assert "nothing heard from the launch for 0.75 s" in \
        (Path(channel.errors.name)).read_text()


def test_its_stdin_closing_ends_everything_it_started(channel):
    pids = start_a_sleeper_and_a_daemon(channel)
    channel.process.stdin.close()
    channel.pinging = False
    assert channel.wait_until_ended() == 0
    assert gone(pids, timeout=0) == []


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGHUP], ids=["SIGTERM", "SIGHUP"])
def test_a_signal_to_it_ends_everything_it_started(channel, sig):
    pids = start_a_sleeper_and_a_daemon(channel)
    channel.process.send_signal(sig)
    assert channel.wait_until_ended() == 128 + sig
    assert gone(pids, timeout=0) == []


def test_killed_with_sigkill_its_watchdog_ends_everything_and_its_end_is_seen_at_once(channel):
    pids = start_a_sleeper_and_a_daemon(channel)
    # (one that ignores SIGTERM keeps the watchdog at work for its grace period)
    pids.append(channel.start(3, ["sh", "-c", "trap '' TERM; sleep 120"])["pid"])
    channel.pinging = False
    channel.process.kill()
    began = time.monotonic()
    channel.wait_until_ended()
    assert time.monotonic() - began < 0.5  # (its watchdog holds no copy of its stdout)
    assert gone(pids, timeout=5.0) == []


def test_a_launch_breaking_the_protocol_ends_everything(channel):
    pid = channel.start(1, ["sleep", "120"])["pid"]
    channel.process.stdin.write(b"\x00\x00\x00\x03X{}")
    channel.process.stdin.flush()
    assert channel.wait_for(lambda b: b["t"] == "log")["level"] == "ERROR"
    assert channel.wait_until_ended() == 1
    assert gone([pid], timeout=0) == []


def test_a_stale_launch_folder_of_a_killed_supervisor_is_removed_by_the_next(ws):
    stale = ws.root / "run" / "launches" / "dead"
    stale.mkdir(parents=True)
    (stale / "pid").write_text("999999999\n")
    made = Channel(ws)
    made.hello()
    assert not stale.exists()
    assert stat.S_IMODE((ws.root / "run" / "launches").stat().st_mode) == 0o700
    made.send({"t": "bye"})
    made.wait_until_ended()
    made.close()
