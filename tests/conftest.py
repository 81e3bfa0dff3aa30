"""Shared fixtures: the suite's own PATH, a workspace to run the real CLI in, and a leak check.
The helpers tests share live in tests/support/ (a test that needs ../shared/external, or the
seeds, gets it through `tests.support.environment.shared()`, which skips naming what is missing).

Every launcher started by a test carries a unique LAUNCHER_TEST_TAG in its environment, which
its children and grandchildren inherit; after the test, no process may still carry it.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import sys
import tempfile
import time
import uuid
from pathlib import Path

import pytest

from tests.support.environment import clean_path
from tests.support.processes import describe, end_lingering_routers
from tests.support.sshd import SshHosts, require
from tests.support.workspace import Workspace

# A suite started in the background of a script (`pytest &`) inherits SIGINT ignored, and so
# would every process it starts: the tests send SIGINT as a user's Ctrl-C, so give it back.
if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
    signal.signal(signal.SIGINT, signal.default_int_handler)

@pytest.fixture(scope="session", autouse=True)
def suite_path():
    """Every test, and everything it starts, sees PATH as a fresh machine has it: the venv's
    bin, then the system's base folders, and no real ROS or Gazebo tool
    (tests/support/environment.py)."""
    mirrors = Path(tempfile.mkdtemp(prefix="launcher-suite-path-"))
    saved = os.environ.get("PATH", "")
    os.environ["PATH"] = clean_path(Path(sys.executable).parent, mirrors)
    try:
        yield os.environ["PATH"]
    finally:
        os.environ["PATH"] = saved
        shutil.rmtree(mirrors, ignore_errors=True)


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


@pytest.fixture(scope="module")
def ssh_hosts(tmp_path_factory: pytest.TempPathFactory):
    """robot1, robot2 and robot3: real OpenSSH hosts, each in a network namespace of its own,
    and a launching host to run ssh (and launcher) in (tests/support/sshd.py). Skips without
    root or OpenSSH."""
    require()
    with SshHosts(tmp_path_factory.mktemp("ssh")) as hosts:
        yield hosts
