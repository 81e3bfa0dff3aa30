"""`launcher router --join`: a host's graph joined to another's through the router listening
there (bus/bridge.py), with real routers, each "host" a run folder of its own; and a launch's
other host that cannot reach the launch's graph (its supervisor's bridge fails)."""

from __future__ import annotations

import select
import socket
import subprocess
import time

import pytest

from launcher.runtime import remote_frames as frames
from launcher.runtime.remote_frames import Decoder, Message
from tests.support.processes import launcher_argv


def closed_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


@pytest.fixture
def hosts(ws):
    """Two "hosts": the workspace's run folder (`here`) and robot2's, each its own router."""
    there = ws.root / "robot2-run"
    there.mkdir(mode=0o700)
    secrets = ws.write("credentials", "launcher:the-graphs-own\n")
    secrets.chmod(0o600)
    ws.env["LAUNCHER_CREDENTIALS"] = str(secrets)
    return ws, {**ws.env, "LAUNCHER_RUN_DIR": str(there)}


def start(ws, env: dict[str, str], *args: str) -> subprocess.Popen:
    return subprocess.Popen([*launcher_argv(), *args], env=env, cwd=ws.root,
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)


@pytest.fixture
def gateway(hosts):
    """A standing router here that robot2 can join at tcp/127.0.0.1:PORT."""
    ws, _ = hosts
    endpoint = f"tcp/127.0.0.1:{closed_port()}"
    router = start(ws, ws.env, "router", "--listen", endpoint)
    assert "listening on" in router.stdout.readline()
    yield endpoint
    router.terminate()
    assert router.wait(10) == 0


def test_a_bridge_says_once_it_has_joined_and_ends_when_its_stdin_closes(hosts, gateway):
    ws, robot2 = hosts
    bridge = start(ws, robot2, "router", "--join", gateway)
    assert bridge.stdout.readline().endswith(f"joined to {gateway}\n")
    bridge.stdin.close()
    assert bridge.wait(10) == 0


def test_a_shell_on_the_joined_host_sees_the_nodes_of_the_other(hosts, gateway):
    ws, robot2 = hosts
    talker = start(ws, ws.env, "topic", "pub", "-r", "5", "/joined", "std_msgs/msg/String",
                   "{data: from here}")
    bridge = start(ws, robot2, "router", "--join", gateway)
    try:
        assert "joined to" in bridge.stdout.readline()
        heard = subprocess.run([*launcher_argv(), "topic", "echo", "/joined",
                                "std_msgs/msg/String", "--once"], env=robot2, cwd=ws.root,
                               capture_output=True, text=True, timeout=60)
        assert "data: from here" in heard.stdout, heard.stderr
    finally:
        for process in (talker, bridge):
            process.terminate()
            process.wait(10)


def test_a_bridge_where_nothing_answers_says_so_within_seconds(hosts):
    ws, robot2 = hosts
    endpoint = f"tcp/127.0.0.1:{closed_port()}"
    began = time.monotonic()
    bridge = start(ws, robot2, "router", "--join", endpoint)
    _, said = bridge.communicate(timeout=30)
    assert bridge.returncode == 1
    assert time.monotonic() - began < 15
    assert f"--join {endpoint}: nothing answered there within 3 s (Connection refused): is " \
           "its router running" in said


def test_a_bridge_with_other_credentials_is_refused_naming_its_file(hosts, gateway):
    ws, robot2 = hosts
    other = ws.write("other-credentials", "launcher:someone-elses\n")
    other.chmod(0o600)
    bridge = start(ws, {**robot2, "LAUNCHER_CREDENTIALS": str(other)}, "router", "--join",
                   gateway)
    _, said = bridge.communicate(timeout=30)
    assert bridge.returncode == 1
    assert "something answers there but did not take the link: is it launcher's router " \
           f"(`launcher router --listen`), and does it hold the credentials of {other}" in said


# --- a launch's host that cannot reach the launch's graph -------------------------------------
def test_a_host_that_cannot_reach_the_launchs_graph_says_so_and_fails_its_starts(hosts):
    ws, robot2 = hosts
    router = f"tcp/127.0.0.1:{closed_port()}"
    supervisor = subprocess.Popen([*launcher_argv(), "remote-supervisor"], env=robot2,
                                  cwd=ws.root, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL)
    said = Said(supervisor)
    said.send({"t": "hello", "launch": "ab12", "ping": 0.25, "silence": 60.0, "domain": 0,
               "graph": {"router": router, "credentials": "launcher:the-graphs-own\n"}})
    error = said.wait_for(lambda b: b["t"] == "log")
    assert error["level"] == "ERROR"
    assert error["text"].startswith(f"{socket.gethostname()} cannot reach this host's graph "
                                    f"at {router}: nothing answered there within 3 s")
    said.wait_for(lambda b: b["t"] == "ready")
    said.send({"t": "start", "id": 1, "label": "p-1", "argv": ["true"], "package": None,
               "executable": None, "at": 0, "env_set": {}, "env_unset": [], "cwd": None,
               "tty": False, "files": []})
    failed = said.wait_for(lambda b: b.get("id") == 1)
    assert failed["t"] == "failed" and failed["text"] == error["text"]
    said.send({"t": "bye"})
    said.wait_for(lambda b: b["t"] == "done")
    assert supervisor.wait(10) == 0


class Said:
    """The launch's end of a supervisor's channel: frames to it, its messages back."""

    def __init__(self, process: subprocess.Popen) -> None:
        self.process, self.decoder = process, Decoder(magic=True)
        self.messages: list[dict] = []

    def send(self, body: dict) -> None:
        self.process.stdin.write(frames.message(body))
        self.process.stdin.flush()

    def wait_for(self, wanted, timeout: float = 30.0) -> dict:
        deadline = time.monotonic() + timeout
        while True:
            for body in self.messages:
                if wanted(body):
                    self.messages.remove(body)
                    return body
            left = deadline - time.monotonic()
            assert left > 0, f"not said within {timeout:g} s: {self.messages}"
            if select.select([self.process.stdout], [], [], left)[0]:
                data = self.process.stdout.read1(1 << 16)
                assert data, f"the supervisor ended: {self.messages}"
                self.messages += [f.body for f in self.decoder.feed(data)
                                  if isinstance(f, Message) and f.body["t"] != "ping"]
