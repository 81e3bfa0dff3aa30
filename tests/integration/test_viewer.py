"""The web viewer served by the sim (launcher/sim/viewer.py): a real sim process, fetched by
a real HTTP client. (The browser test that looks at the picture comes with the set-up that
installs Chromium.)"""

from __future__ import annotations

import socket
import time
import urllib.request

import psutil
import pytest


@pytest.fixture
def view_ws(ws):
    return ws.own_bus()


def wait_for(predicate, timeout: float = 30.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(0.05)
    raise AssertionError("timed out")


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def listening(pid: int, port: int) -> list[str]:
    return [c.laddr.ip for c in psutil.Process(pid).net_connections("inet")
            if c.status == psutil.CONN_LISTEN and c.laddr.port == port]


def said(ws) -> str:
    return ws.output("stderr.txt") + ws.output()


def stop(proc) -> None:
    proc.terminate()
    proc.wait(20)


def test_the_sim_serves_the_world_on_loopback_only_and_says_where(view_ws):
    port = free_port()
    proc = view_ws.start("sim", "-r", "-v", "3", f"--gui={port}", "empty.sdf")
    try:
        wait_for(lambda: "the world in a browser" in said(view_ws))
        text = said(view_ws)
        assert f"the world in a browser: http://127.0.0.1:{port}/" in text
        assert listening(proc.pid, port) == ["127.0.0.1"]  # never every interface
        page = urllib.request.urlopen(f"http://127.0.0.1:{port}/", timeout=10).read()
        assert b"<!doctype html>" in page.lower()[:200]
        model = urllib.request.urlopen(f"http://127.0.0.1:{port}/model", timeout=10).read()
        assert len(model) > 1000  # the compiled world, as the page loads it
    finally:
        stop(proc)
    assert proc.returncode == 0


def test_a_taken_port_is_said_and_the_sim_runs_on_headless(view_ws):
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        proc = view_ws.start("sim", "-r", "-v", "3", f"--gui={port}", "empty.sdf")
        try:
            wait_for(lambda: "world 'empty'" in said(view_ws))
            text = said(view_ws)
            assert f"the web viewer cannot listen on 127.0.0.1 port {port}" in text
            assert "runs on without it" in text
            assert proc.poll() is None  # still simulating
            assert "Traceback" not in text
        finally:
            stop(proc)


@pytest.mark.parametrize("args, expected", [
    (["--gui=eighty"], "expected a port number (1-65535), got 'eighty'"),
    (["--gui=70000"], "expected a port number (1-65535), got 70000"),
    (["--gui", "--gui-rate", "500"], "--gui-rate must be between 1 and 60 Hz"),
])
def test_bad_viewer_options(view_ws, args, expected):
    done = view_ws.run("sim", *args, "empty.sdf", timeout=30)
    assert done.returncode == 2
    assert expected in done.stderr


def test_a_mujoco_without_studio_is_said_and_the_sim_runs_on_headless(view_ws):
    """An older MuJoCo has no `mujoco.studio`: here it is hidden from the sim's import."""
    view_ws.write("sitecustomize.py", """
        import sys
        sys.modules["mujoco.studio"] = None  # what an older MuJoCo's import gives: nothing
    """)
    env = {"PYTHONPATH": str(view_ws.root)}
    proc = view_ws.start("sim", "-r", "-v", "3", f"--gui={free_port()}", "empty.sdf", env=env)
    try:
        wait_for(lambda: "world 'empty'" in said(view_ws))
        text = said(view_ws)
        assert "the web viewer needs MuJoCo Studio (mujoco>=4); this is mujoco" in text
        assert "runs on without it" in text and proc.poll() is None
    finally:
        stop(proc)
