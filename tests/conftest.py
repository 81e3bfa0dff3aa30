"""Shared fixtures: the suite's own PATH, launch files written inline, the real CLI, and a
leak check. Tests that need ../shared/external (or the seeds) get it through `shared()`, which
skips naming what is missing (tests/environment.py).

Every launcher started by a test carries a unique LAUNCHER_TEST_TAG in its environment, which
its children and grandchildren inherit; after the test, no process may still carry it.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
import uuid
from pathlib import Path

import psutil
import pytest

from tests.environment import REPO, clean_path, shared  # noqa: F401 - shared: for the tests

# A suite started in the background of a script (`pytest &`) inherits SIGINT ignored, and so
# would every process it starts: the tests send SIGINT as a user's Ctrl-C, so give it back.
if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
    signal.signal(signal.SIGINT, signal.default_int_handler)

@pytest.fixture(scope="session", autouse=True)
def suite_path():
    """Every test, and everything it starts, sees PATH as a fresh machine has it: the venv's
    bin, then the system's base folders, and no real ROS or Gazebo tool (tests/environment.py)."""
    mirrors = Path(tempfile.mkdtemp(prefix="launcher-suite-path-"))
    saved = os.environ.get("PATH", "")
    os.environ["PATH"] = clean_path(Path(sys.executable).parent, mirrors)
    try:
        yield os.environ["PATH"]
    finally:
        os.environ["PATH"] = saved
        shutil.rmtree(mirrors, ignore_errors=True)


def launcher_argv() -> list[str]:
    exe = Path(sys.executable).with_name("launcher")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "launcher"]


def tagged_processes(tag: str) -> list[psutil.Process]:
    found = []
    for proc in psutil.process_iter(["pid"]):
        try:
            if proc.environ().get("LAUNCHER_TEST_TAG") == tag and \
                    proc.status() != psutil.STATUS_ZOMBIE:
                found.append(proc)
        except (psutil.NoSuchProcess, psutil.AccessDenied, psutil.ZombieProcess):
            continue
    return found


class Workspace:
    """A temporary folder to write launch files into and run `launcher` against."""

    def __init__(self, root: Path, tag: str) -> None:
        self.root = root
        self.tag = tag
        # A graph of the test's own (its run folder), whose router stops half a second after
        # its last user instead of three: the leak check below waits for it to go.
        self.env = dict(os.environ, LAUNCHER_TEST_TAG=tag,
                        LAUNCHER_LOG_DIR=str(root / "log"), PYTHONUNBUFFERED="1",
                        LAUNCHER_RUN_DIR=str(root / "run"), LAUNCHER_ROUTER_LINGER="0.5")

    def own_bus(self) -> Workspace:
        """Launches and tools started here meet only each other (the run folder of this
        test's), with no router or simulator paths from outside."""
        for name in ("LAUNCHER_ROUTER", "MUJOCO_SIM_RESOURCE_PATH", "MUJOCO_SIM_PLUGIN_PATH",
                     "GZ_SIM_RESOURCE_PATH", "IGN_GAZEBO_RESOURCE_PATH", "GAZEBO_MODEL_PATH",
                     "GAZEBO_RESOURCE_PATH", "GZ_SIM_SYSTEM_PLUGIN_PATH", "GAZEBO_PLUGIN_PATH"):
            self.env.pop(name, None)
        return self

    def write(self, name: str, text: str) -> Path:
        path = self.root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text).lstrip("\n"))
        return path

    def run(self, *args: str, timeout: float = 60, **kwargs) -> subprocess.CompletedProcess:
        """Run `launcher ARGS…` to completion."""
        return subprocess.run(launcher_argv() + list(args), cwd=self.root, env=self.env,
                              capture_output=True, text=True, timeout=timeout, **kwargs)

    def start(self, *args: str, output: str = "stdout.txt",
              env: dict[str, str] | None = None) -> subprocess.Popen:
        """Start `launcher ARGS…` in the background: stdout to `output`, stderr to
        stderr.txt (or to `output` too when it is not the default)."""
        out = open(self.root / output, "w")  # noqa: SIM115
        err = open(self.root / "stderr.txt", "w") if output == "stdout.txt" \
            else subprocess.STDOUT  # noqa: SIM115
        return subprocess.Popen(launcher_argv() + list(args), cwd=self.root,
                                env={**self.env, **(env or {})}, stdout=out, stderr=err,
                                text=True)

    def output(self, name: str = "stdout.txt") -> str:
        return (self.root / name).read_text()

    def wait_for_output(self, needle: str, timeout: float = 30,
                        name: str = "stdout.txt") -> str:
        """The output file `name` once it holds `needle` (fails after `timeout` seconds)."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            text = self.output(name)
            if needle in text:
                return text
            time.sleep(0.02)
        raise AssertionError(f"{needle!r} not in output:\n{self.output(name)}")

    def processes(self) -> list[psutil.Process]:
        return tagged_processes(self.tag)


@pytest.fixture
def ws(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory):
    """A workspace; fails the test if any process it started is still running after it. Its
    folder is named by the test's first letters, not its whole name: the run folders inside
    it hold Unix sockets, whose paths must stay under 108 characters (under pytest-xdist too,
    whose folders are deeper)."""
    name = re.sub(r"\W", "_", request.node.name[:12])
    workspace = Workspace(tmp_path_factory.mktemp(name), uuid.uuid4().hex)
    yield workspace
    end_lingering_routers(workspace.processes())
    deadline = time.monotonic() + 5
    left = workspace.processes()
    while left and time.monotonic() < deadline:
        time.sleep(0.05)
        left = workspace.processes()
    for proc in left:  # do not leak into other tests, but still fail this one
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except OSError:
            proc.kill()
    assert not left, "processes left behind: " + ", ".join(describe(p) for p in left)


def end_lingering_routers(processes: list[psutil.Process]) -> None:
    """The graph's router outlives its last user by LAUNCHER_ROUTER_LINGER, on purpose (the
    next command of a shell finds it up; test_bus checks that it then goes by itself). The
    test is over: it is asked to go now (SIGTERM, its own clean stop), not waited for."""
    for proc in processes:
        try:
            if "launcher.bus.router" in proc.cmdline():
                proc.terminate()
        except psutil.Error:
            continue


def describe(proc: psutil.Process) -> str:
    try:
        return f"{proc.pid} {' '.join(proc.cmdline())}"
    except psutil.Error:
        return f"{proc.pid} (gone or a zombie)"
