"""The remote supervisor's parts with the operating system faked: what a `start` may hold, the
order in which a process's end is told, output held back while the launch is slow to take it,
the environment and command a process gets on its host, and the launch's folder there."""

from __future__ import annotations

import contextlib
import errno
import itertools
import os
import stat
from pathlib import Path

import pytest

from launcher.errors import LaunchError
from launcher.runtime import remote_frames as frames
from launcher.runtime.custody import Custody
from launcher.runtime.loop import EventLoop
from launcher.runtime.remote_children import Children, StartRequest
from launcher.runtime.remote_files import LaunchFolder, rewrite, sweep_stale
from launcher.runtime.remote_frames import Decoder, Message, Output, ProtocolError
from launcher.runtime.supervisor import HIGH_WATER, Host, Outbox, Supervisor
from launcher.runtime.system import Started
from tests.support.fake_loop import FakeLoop


class FakeSystem:
    """Records spawns and signals; the test says what a process writes, when it exits, and
    whether its group still holds anything."""

    def __init__(self) -> None:
        self.pids = itertools.count(100)
        self.fds = itertools.count(10)
        self.spawned: list[tuple[list[str], dict[str, str], str | None, bool]] = []
        self.signals: list[tuple[int, int]] = []
        self.group: dict[int, bool] = {}
        self.exits: dict[int, object] = {}
        self.output: dict[int, list[bytes]] = {}
        self.fail: OSError | None = None

    def spawn(self, argv, env, cwd, tty):
        if self.fail is not None:
            raise self.fail
        self.spawned.append((argv, env, cwd, tty))
        pid = next(self.pids)
        self.group[pid] = True
        started = Started(pid, next(self.fds), next(self.fds))
        self.output[started.stdout], self.output[started.stderr] = [], []
        return started

    def watch_exit(self, pid, loop, exited):
        self.exits[pid] = exited

    def read(self, fd):
        chunks = self.output[fd]
        return chunks.pop(0) if chunks else None

    def close(self, fd):
        self.output.pop(fd)

    def kill_group(self, pgid, sig):
        self.signals.append((pgid, sig))

    def group_alive(self, pgid):
        return self.group[pgid]


class Sent:
    """What the supervisor's parts send the launch, decoded."""

    def __init__(self) -> None:
        self.decoder = Decoder()
        self.frames: list = []

    def __call__(self, data: bytes) -> None:
        self.frames += self.decoder.feed(data)

    def kinds(self) -> list[str]:
        return [f.body["t"] if isinstance(f, Message) else f"O{f.stream}" for f in self.frames]


def children() -> tuple[Children, FakeLoop, FakeSystem, Sent, list]:
    loop, system, sent, told = FakeLoop(), FakeSystem(), Sent(), []
    table = Children(loop, system, sent, lambda pgid, alive: told.append((pgid, alive)),
                     lambda ident: told.append(("gone", ident)))
    return table, loop, system, sent, told


# --- one process's life, as the launch is told it -------------------------------------------
def test_output_then_each_streams_end_then_the_exit_then_the_empty_group():
    table, loop, system, sent, told = children()
    pid = table.start(7, ["talker"], {}, None, False)
    out, err = sorted(loop.readers)
    system.output[out] += [b"hello\n", b""]
    system.output[err] += [b"oops\n", b""]
    for fd in (out, err, out, err):
        loop.ready(fd)
    system.group[pid] = False
    system.exits[pid](-2)
    assert sent.kinds() == ["O1", "O2", "eof", "eof", "exited", "group"]
    assert sent.frames[0] == Output(7, 1, b"hello\n")
    assert sent.frames[4] == Message({"t": "exited", "id": 7, "code": -2})
    assert sent.frames[5] == Message({"t": "group", "id": 7, "alive": False})
    assert told == [(pid, True), (pid, False), ("gone", 7)]


def test_a_group_that_outlives_its_leader_is_told_empty_once_it_is():
    table, loop, system, sent, _ = children()
    pid = table.start(1, ["sh"], {}, None, False)
    for fd in sorted(loop.readers):
        system.output[fd].append(b"")
        loop.ready(fd)
    system.exits[pid](0)
    loop.advance(0.5)
    assert sent.kinds()[-1] == "exited"
    system.group[pid] = False
    loop.advance(0.02)
    assert sent.kinds()[-1] == "group" and table.running == {}


def test_streams_held_open_by_what_it_left_end_half_a_second_after_it():
    """(a daemon it started holds its pipes: its exit is told all the same, as locally)"""
    table, loop, system, sent, _ = children()
    pid = table.start(1, ["sh"], {}, None, False)
    system.exits[pid](0)
    loop.advance(0.4)
    assert sent.kinds() == []
    loop.advance(0.2)
    assert sent.kinds() == ["eof", "eof", "exited"]


def test_output_is_not_read_while_the_launch_is_slow_to_take_it():
    table, loop, system, sent, _ = children()
    table.start(1, ["yes"], {}, None, False)
    table.pause(True)
    assert loop.readers == {}
    table.pause(False)
    assert len(loop.readers) == 2


def test_a_paused_processs_pipes_are_read_to_their_end_before_its_exit_is_told():
    table, loop, system, sent, _ = children()
    pid = table.start(1, ["yes"], {}, None, False)
    table.pause(True)
    system.exits[pid](0)
    loop.advance(2.0)
    assert sent.kinds() == []
    table.pause(False)
    out, err = sorted(loop.readers)
    system.output[out] += [b"last words\n"]
    loop.ready(out)
    loop.advance(0.5)
    assert sent.kinds() == ["O1", "eof", "eof", "exited"]


def test_a_signal_goes_to_the_processs_group_and_not_to_one_that_is_gone():
    table, loop, system, sent, _ = children()
    pid = table.start(1, ["sleep"], {}, None, False)
    table.signal(1, 2)
    table.signal(99, 9)
    assert system.signals == [(pid, 2)]


# --- what a start may hold --------------------------------------------------------------------
START = {"t": "start", "id": 7, "label": "talker-3", "argv": ["--ros-args"], "package": "demo",
         "executable": "talker", "at": 0, "env_set": {"A": "1"}, "env_unset": ["B"],
         "cwd": None, "tty": False, "files": [{"path": "/p/talker.yaml", "text": "a: 1\n"}]}


def test_a_start_is_read_with_every_field():
    request = StartRequest.parse(START)
    assert (request.ident, request.label, request.package, request.executable) == \
        (7, "talker-3", "demo", "talker")
    assert request.files == [("/p/talker.yaml", "a: 1\n")]


@pytest.mark.parametrize(("change", "said"), [
    ({"id": "7"}, "'id' is '7'; expected a number"),
    ({"id": True}, "'id' is 'True'; expected a number"),
    ({"argv": "talker"}, "'argv' is 'talker'; expected a list"),
    ({"argv": ["a", 3]}, "argv, env_set and env_unset hold strings only"),
    ({"at": 2}, "'at' is 2; expected an index into argv (0 to 1)"),
    ({"at": -1}, "'at' is -1"),
    ({"env_set": {"A": 1}}, "hold strings only"),
    ({"env_unset": "B"}, "'env_unset' is 'B'; expected a list"),
    ({"package": 3}, "'package' is '3'; expected a name or null"),
    ({"tty": "no"}, "'tty' is 'no'; expected true or false"),
    ({"files": [{"path": "", "text": ""}]}, "expected {\"path\": a path"),
    ({"files": [{"path": "/p"}]}, "expected {\"path\": a path, \"text\": its text}"),
], ids=["id text", "id bool", "argv text", "argv number", "at past", "at negative", "env number",
        "unset text", "package number", "tty text", "empty path", "no text"])
def test_a_start_that_is_not_what_start_takes_is_refused(change, said):
    with pytest.raises(ProtocolError) as caught:
        StartRequest.parse({**START, **change})
    assert said in str(caught.value)


def test_a_start_without_argv_is_refused():
    with pytest.raises(ProtocolError, match="'argv' is missing"):
        StartRequest.parse({k: v for k, v in START.items() if k != "argv"})


# --- the command and environment a process gets here ------------------------------------------
class Remote:
    """A supervisor on a fake system, its frames read back from its pipe."""

    def __init__(self, tmp_path: Path, environment: dict[str, str] | None = None) -> None:
        self.system = FakeSystem()
        self.read_end, write_end = os.pipe()
        os.set_blocking(write_end, False)
        self.host = Host(name="robot2", environment=environment or {"PATH": "/robot/bin",
                                                                      "B": "gone", "C": "kept"},
                         run_folder=tmp_path / "run", resolve=self.resolve,
                         join_graph=lambda folder, graph: {
                             "LAUNCHER_ROUTER": graph["router"],
                             "LAUNCHER_CREDENTIALS": str(folder.credentials(
                                 graph["credentials"]))})
        self.loop = FakeLoop()
        self.supervisor = Supervisor(self.loop, self.system, Custody(), self.host,  # type: ignore[arg-type]
                                     os.open(os.devnull, os.O_RDONLY), write_end)
        self.decoder = Decoder()

    @staticmethod
    def resolve(package, executable, env):
        if package != "demo":
            raise LaunchError(f"package '{package}' not found on robot2; searched: /ws")
        return ["/robot/ws/demo/talker", "--flag"], {**env, "PYTHONPATH": "/robot/ws/demo"}

    def send(self, body: dict) -> None:
        self.supervisor._dispatch(body)

    def said(self) -> list[dict]:
        self.supervisor.outbox.flush(1.0)
        data = b""
        with contextlib.suppress(BlockingIOError):
            os.set_blocking(self.read_end, False)
            data = os.read(self.read_end, 1 << 20)
        return [f.body for f in self.decoder.feed(data) if f.body["t"] != "ping"]

    def close(self) -> None:
        self.loop.close()


@pytest.fixture
def remote(tmp_path):
    made = Remote(tmp_path)
    made.send({"t": "hello", "launch": "ab12", "ping": 0.25, "silence": 0.75, "domain": 4,
               "graph": {"router": "tcp/10.0.0.1:7447", "credentials": "launcher:secret\n"}})
    yield made
    made.close()


def test_hello_is_answered_with_this_host(remote):
    [ready] = remote.said()
    assert ready["t"] == "ready" and ready["host"] == "robot2" and ready["pid"] == os.getpid()


def test_the_environment_is_this_hosts_with_the_launchs_changes(remote):
    remote.send({**START, "env_set": {"A": "1", "LAUNCHER_LAUNCH_00ff": "9",
                                      "LAUNCHER_DETACHED": "1"}})
    env = remote.system.spawned[0][1]
    assert env["PATH"] == "/robot/bin" and env["C"] == "kept" and env["A"] == "1"
    assert "B" not in env
    assert env["ROS_DOMAIN_ID"] == "4"
    assert env["PYTHONPATH"] == "/robot/ws/demo"  # (what the executable here needs)
    assert "LAUNCHER_LAUNCH_00ff" not in env and "LAUNCHER_DETACHED" not in env


def test_the_graph_is_joined_with_the_launchs_credentials_written_here_0600(remote):
    remote.send(START)
    env = remote.system.spawned[0][1]
    assert env["LAUNCHER_ROUTER"] == "tcp/10.0.0.1:7447"
    credentials = Path(env["LAUNCHER_CREDENTIALS"])
    assert credentials.read_text() == "launcher:secret\n"
    assert stat.S_IMODE(credentials.stat().st_mode) == 0o600
    assert stat.S_IMODE(credentials.parent.stat().st_mode) == 0o700


def test_a_graph_message_joins_the_processes_started_after_it(tmp_path):
    made = Remote(tmp_path)
    made.send({"t": "hello", "launch": "ab", "ping": 0.25, "silence": 0.75})
    made.send({**START, "id": 1})
    made.send({"t": "graph", "router": "tcp/10.0.0.1:1", "credentials": "launcher:x\n"})
    made.send({**START, "id": 2})
    first, second = (spawned[1] for spawned in made.system.spawned)
    assert "LAUNCHER_ROUTER" not in first and second["LAUNCHER_ROUTER"] == "tcp/10.0.0.1:1"
    made.close()


def test_a_graph_before_hello_breaks_the_protocol(tmp_path):
    made = Remote(tmp_path)
    with pytest.raises(ProtocolError, match="graph before hello"):
        made.send({"t": "graph", "router": "tcp/10.0.0.1:1", "credentials": "launcher:x\n"})
    made.close()


def test_the_executable_found_here_goes_where_the_launch_said(remote):
    remote.send({**START, "argv": ["valgrind", "--ros-args", "-r", "x:=y"], "at": 1})
    assert remote.system.spawned[0][0] == ["valgrind", "/robot/ws/demo/talker", "--flag",
                                           "--ros-args", "-r", "x:=y"]
    assert remote.said()[-1] == {"t": "started", "id": 7, "pid": 100}


def test_an_executable_without_a_package_is_run_as_a_command(remote):
    remote.send({**START, "package": None, "executable": "/usr/bin/env", "argv": ["FOO=1"]})
    assert remote.system.spawned[0][0] == ["/usr/bin/env", "FOO=1"]


def test_a_shipped_files_path_is_rewritten_in_argv_and_environment(remote):
    remote.send({**START, "argv": ["--params-file", "/p/talker.yaml", "__params:=/p/talker.yaml"],
                 "env_set": {"PARAMS": '["--params-file", "/p/talker.yaml"]'}})
    argv, env = remote.system.spawned[0][:2]
    here = argv[-1].removeprefix("__params:=")
    assert argv[-2] == here and Path(here).read_text() == "a: 1\n"
    assert env["PARAMS"] == f'["--params-file", "{here}"]'
    assert here.startswith(str(remote.host.run_folder / "launches" / "ab12" / "files" / "7"))


def test_a_package_not_on_this_host_fails_the_start_with_its_reason(remote):
    remote.send({**START, "package": "demu"})
    assert remote.said()[-1] == {"t": "failed", "id": 7, "errno": errno.ENOENT,
                                 "text": "package 'demu' not found on robot2; searched: /ws"}
    assert remote.system.spawned == []


def test_a_command_that_cannot_start_fails_with_its_errno(remote):
    remote.system.fail = FileNotFoundError(errno.ENOENT, "No such file or directory")
    remote.send(START)
    assert remote.said()[-1] == {
        "t": "failed", "id": 7, "errno": errno.ENOENT,
        "text": "cannot start '/robot/ws/demo/talker' on robot2: No such file or directory"}


def test_a_bad_start_fails_that_start_only(remote):
    remote.send({**START, "at": 5})
    assert remote.said()[-1]["errno"] == errno.EINVAL
    remote.send(START)
    assert remote.said()[-1]["t"] == "started"


def test_an_id_still_running_is_not_started_twice(remote):
    remote.send(START)
    remote.send(START)
    assert remote.said()[-1] == {"t": "failed", "id": 7, "errno": errno.EEXIST,
                                 "text": "process id 7 is still running"}


def test_a_message_this_launcher_does_not_know_is_answered_with_a_warning(remote):
    remote.send({"t": "graph_later"})
    said = remote.said()[-1]
    assert said["t"] == "log" and said["level"] == "WARN" and "'graph_later'" in said["text"]


def test_a_start_before_hello_breaks_the_protocol(tmp_path):
    made = Remote(tmp_path)
    with pytest.raises(ProtocolError, match="start before hello"):
        made.send(START)
    made.close()


@pytest.mark.parametrize(("hello", "said"), [
    ({"ping": 0}, "expected seconds > 0"),
    ({"silence": "1"}, "expected seconds > 0"),
    ({"launch": "../../etc"}, "launch id '../../etc': expected 1 to 64 hex digits"),
    ({"domain": "0"}, "domain '0': expected a number or null"),
    ({"graph": {"router": "tcp/x:1"}}, "graph: expected {\"router\": an endpoint"),
    ({"graph": "tcp/x:1"}, "graph 'tcp/x:1': expected null or"),
], ids=["ping", "silence", "launch id", "domain", "graph fields", "graph text"])
def test_a_hello_that_is_not_what_hello_takes_breaks_the_protocol(tmp_path, hello, said):
    made = Remote(tmp_path)
    with pytest.raises(ProtocolError) as caught:
        made.send({"t": "hello", "launch": "ab", "ping": 0.25, "silence": 0.75, "domain": 0,
                   "graph": None, **hello})
    assert said in str(caught.value)
    made.close()


# --- frames leaving for the launch -------------------------------------------------------------
def test_the_outbox_keeps_what_the_channel_cannot_take_and_says_when_it_is_full():
    loop = EventLoop()
    read, write = os.pipe()
    os.set_blocking(write, False)
    full: list[bool] = []
    outbox = Outbox(loop, write, full.append, lambda: full.append("broken"))
    chunk = frames.output(1, 1, b"x" * frames.MAX_OUTPUT)
    for _ in range(HIGH_WATER // len(chunk) + 2):
        outbox.send(chunk)
    assert full == [True]
    received = 0
    while outbox.queued:
        loop._run_once()
        received += len(os.read(read, 1 << 20))
    assert full == [True, False]
    assert received == (HIGH_WATER // len(chunk) + 2) * len(chunk)
    loop.close()
    os.close(read)
    os.close(write)


def test_the_outbox_says_when_the_channel_is_gone():
    loop = EventLoop()
    read, write = os.pipe()
    os.close(read)
    broken: list[bool] = []
    outbox = Outbox(loop, write, lambda full: None, lambda: broken.append(True))
    outbox.send(frames.message({"t": "ping"}))
    loop._run_once()
    assert broken == [True] and outbox.closed
    outbox.send(frames.message({"t": "ping"}))  # (dropped, no error)
    loop.close()
    os.close(write)


# --- the launch's folder on this host ----------------------------------------------------------
def test_the_launch_folder_is_private_and_names_its_supervisor(tmp_path):
    folder = LaunchFolder(tmp_path, "ab12")
    assert stat.S_IMODE(folder.path.stat().st_mode) == 0o700
    assert (folder.path / "pid").read_text() == f"{os.getpid()}\n"


def test_shipped_files_are_0600_and_keep_their_names_even_two_of_one_name(tmp_path):
    folder = LaunchFolder(tmp_path, "ab12")
    moved = folder.ship(3, [("/a/params.yaml", "a: 1"), ("/b/params.yaml", "b: 2")])
    first, second = Path(moved["/a/params.yaml"]), Path(moved["/b/params.yaml"])
    assert first.name == second.name == "params.yaml" and first != second
    assert (first.read_text(), second.read_text()) == ("a: 1", "b: 2")
    assert stat.S_IMODE(first.stat().st_mode) == stat.S_IMODE(second.stat().st_mode) == 0o600
    folder.forget(3)
    assert not first.exists()
    folder.remove()
    assert not folder.path.exists()


def test_a_path_that_begins_another_is_not_rewritten_inside_it():
    argv, env = rewrite(["/p/a.yaml", "/p/a.yaml.bak", "x=/p/a.yaml"], {"V": "/p/a.yaml.bak"},
                        {"/p/a.yaml": "/here/a.yaml", "/p/a.yaml.bak": "/here/a.yaml.bak"})
    assert argv == ["/here/a.yaml", "/here/a.yaml.bak", "x=/here/a.yaml"]
    assert env == {"V": "/here/a.yaml.bak"}


def test_stale_launch_folders_go_and_live_ones_stay(tmp_path):
    live = LaunchFolder(tmp_path, "aa")
    dead = LaunchFolder(tmp_path, "bb")
    (dead.path / "pid").write_text("999999999\n")
    unwritten = tmp_path / "launches" / "cc"
    unwritten.mkdir()
    sweep_stale(tmp_path)
    assert live.path.exists() and not dead.path.exists() and unwritten.exists()
