"""Every entry point reports a failure the same way, through the one reporter: one line on
stderr, nothing on stdout, the exit status of the error (2 for usage, 1 otherwise), and a
traceback only when debugging (`--debug`, or LAUNCHER_DEBUG=1 that it hands to nodes)."""

from __future__ import annotations

import subprocess
import sys

import pytest

from tests.support.processes import launcher_argv

PY = sys.executable


def node(module: str, *args: str) -> list[str]:
    return [PY, "-m", f"launcher.nodes.{module}", *args]


CASES = {
    "launch: a missing file": (
        launcher_argv() + ["launch", "missing.launch.yaml"], 1, "error: /"),
    "launch: a usage error": (
        launcher_argv() + ["launch", "ok.launch.yaml", "speed=2"], 2,
        "error: malformed launch argument 'speed=2'"),
    "launcher sim: a world not found": (
        launcher_argv() + ["sim", "nowhere.sdf"], 1, "[sim] error: world 'nowhere.sdf' not found"),
    "launcher sim: a bad --world-arg": (
        launcher_argv() + ["sim", "--world-arg", "size", "empty.sdf"], 2,
        "[sim] error: --world-arg expects NAME=VALUE, got 'size'"),
    "launcher gz: an unknown verb": (
        launcher_argv() + ["gz", "modle"], 2, "error: gz: unknown command 'modle'"),
    "snapshot: no sim": (
        launcher_argv() + ["sim", "snapshot", "-o", "x.png", "--timeout", "1"], 1,
        "error: no sim answered"),
    "create: a bad option": (node("create", "-fiel", "robot.urdf"), 2,
                             "[create] error: unknown option '-fiel'"),
    "create: no sim": (node("create", "-file", "robot.urdf", "-timeout", "1"), 1,
                       "[create] error: no sim answered"),
    "parameter_bridge: a missing config": (
        node("parameter_bridge", "--ros-args", "-p", "config_file:=nope.yaml"), 1,
        "[parameter_bridge] error: bridge config file 'nope.yaml' does not exist"),
    "robot_state_publisher: no description": (
        node("robot_state_publisher"), 1,
        "[robot_state_publisher] error: parameter robot_description is missing or empty"),
}


@pytest.fixture
def quiet_ws(ws):
    ws.own_bus()
    ws.write("ok.launch.yaml", "launch: []\n")
    ws.env["LAUNCHER_BUS_TIMEOUT"] = "1"
    return ws


@pytest.mark.parametrize("case", list(CASES))
def test_one_line_on_stderr_nothing_on_stdout_the_errors_exit_status(quiet_ws, case):
    argv, code, expected = CASES[case]
    done = subprocess.run(argv, cwd=quiet_ws.root, env=quiet_ws.env, capture_output=True,
                          text=True, timeout=60)
    errors = [line for line in done.stderr.splitlines() if "error:" in line]
    assert done.returncode == code, done.stderr
    assert len(errors) == 1 and errors[0].startswith(expected), done.stderr
    if case == "launch: a missing file":
        assert errors[0].endswith("missing.launch.yaml: no such launch file")
    assert "Traceback" not in done.stderr
    assert done.stdout == "", done.stdout


@pytest.mark.parametrize("case", ["launcher sim: a world not found", "create: a bad option",
                                  "parameter_bridge: a missing config"])
def test_debugging_adds_the_traceback(quiet_ws, case):
    argv, code, expected = CASES[case]
    done = subprocess.run(argv, cwd=quiet_ws.root, env={**quiet_ws.env, "LAUNCHER_DEBUG": "1"},
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == code
    assert "Traceback (most recent call last)" in done.stderr and expected in done.stderr
