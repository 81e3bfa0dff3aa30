"""The suite builds the environment it checks (tests/support/environment.py): a real ROS or
Gazebo tool on the machine is never what a test reaches."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.support import environment
from tests.support.environment import REAL_TOOLS, REPO, clean_path, real_tools_in

MARKER = "FAKE-REAL-ROSPARAM-REACHED"


def test_the_suites_path_holds_no_real_ros_or_gazebo_tool(suite_path):
    assert suite_path.split(os.pathsep)[0] == str(Path(sys.executable).parent)
    for folder in suite_path.split(os.pathsep):
        assert not real_tools_in(Path(folder)), folder


def test_a_planted_rosparam_is_never_reached_by_the_suites_commands(ws, tmp_path):
    """A "real" rosparam that prints a marker, in a system folder beside `sh` and the other
    tools a test needs: the suite's PATH keeps the folder's other tools and drops it, so a
    launched `rosparam` is launcher's own."""
    system = tmp_path / "usr-bin"
    system.mkdir()
    for name in ("rosparam", "other_tool"):
        (system / name).write_text(f"#!/bin/sh\necho {MARKER if name == 'rosparam' else 'OK'}\n")
        (system / name).chmod(0o755)
    path = clean_path(Path(sys.executable).parent, tmp_path / "mirrors",
                      (str(system), "/usr/bin", "/bin"))
    assert str(system) not in path.split(os.pathsep)
    assert shutil.which("other_tool", path=path) is not None  # the rest of the folder stays
    assert shutil.which("rosparam", path=path) is None
    assert not any(shutil.which(tool, path=path) for tool in REAL_TOOLS)
    ws.env["PATH"] = path
    ws.write("script.launch.yaml", """
    launch:
      - executable: {cmd: "rosparam get /nothing_here", output: screen}
      - executable: {cmd: "other_tool", output: screen}
    """)
    done = ws.run("launch", "script.launch.yaml", timeout=60)
    said = done.stdout + done.stderr
    assert MARKER not in said, said
    assert "[other_tool-2] OK" in said, said
    assert "[rosparam-1] error:" in said, said  # launcher's rosparam: no server is running


def test_missing_shared_material_skips_naming_it_and_fails_when_ci_requires_it(monkeypatch):
    """A clone without ../shared skips what needs it, saying what is missing; CI sets
    LAUNCHER_REQUIRE_EXTERNAL=1, under which that is a failure (so CI runs them all)."""
    monkeypatch.delenv(environment.REQUIRE_EXTERNAL, raising=False)
    with pytest.raises(pytest.skip.Exception, match="needs .*/shared/external/no-such-world.sdf"):
        environment.shared("external", "no-such-world.sdf")
    monkeypatch.setenv(environment.REQUIRE_EXTERNAL, "1")
    with pytest.raises(pytest.fail.Exception, match="LAUNCHER_REQUIRE_EXTERNAL=1 makes that"):
        environment.shared("external", "no-such-world.sdf")


def test_a_clone_without_shared_collects_the_whole_suite_with_no_error(tmp_path):
    """A user's clone has no ../shared beside it: every test module must still import (the
    tests that need the material skip when they run, naming it), so `pytest --collect-only`
    of a copy of the repo standing alone exits 0 and collects as many tests as this one."""
    clone = tmp_path / "alone" / REPO.name
    shutil.copytree(REPO, clone, ignore=shutil.ignore_patterns(
        ".git", ".venv", "node_modules", "__pycache__", ".pytest_cache", "site", ".fidelity",
        "test-artefacts", "log"))
    env = {key: value for key, value in os.environ.items()
           if key != environment.REQUIRE_EXTERNAL and not key.startswith("PYTEST_")}
    argv = [sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider",
            "-p", "no:xdist", "tests"]
    alone = subprocess.run(argv, cwd=clone, env=env, capture_output=True, text=True,
                           timeout=300)
    assert not (clone.parent / "shared").exists()
    assert alone.returncode == 0, alone.stdout[-3000:] + alone.stderr[-3000:]
    assert "error" not in alone.stdout.splitlines()[-1], alone.stdout[-3000:]
    here = subprocess.run(argv, cwd=REPO, env=env, capture_output=True, text=True,
                          timeout=300)
    assert collected(alone.stdout) == collected(here.stdout), alone.stdout[-3000:]


def collected(summary: str) -> int:
    """The count in pytest's last line ("2308 tests collected in 4.6s")."""
    return int(summary.splitlines()[-1].split()[0])
