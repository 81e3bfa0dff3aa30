"""What a hostile or careless user can send the stack: requests that would freeze or brick the
sim, worlds it cannot run, files that are not files, bridge entries of no known type. Each is
refused with a clear, located message; the stack keeps running; nothing is left behind."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys

import pytest

from tests.support.sim import ROBOT, SIM_LAUNCH

PY = sys.executable

# The sim's own side, as a gz-transport client: requests that would freeze or brick it.
PROBE = """
import json, time
from launcher.bus import keys
from launcher.bus.node import Node
node = Node("probe", space=keys.SIM)
result = {}
clocks = []
node.create_subscription("mujoco_sim/msg/Clock", "/world/empty/clock", clocks.append)
control = node.create_client("mujoco_sim/srv/Control", "/world/empty/control")
create = node.create_client("mujoco_sim/srv/Create", "/world/empty/create")
set_pose = node.create_client("mujoco_sim/srv/SetPose", "/world/empty/set_pose")
assert control.wait_for_service(20)

def call(client, kind, **fields):
    return client.call(node.message(f"mujoco_sim/srv/{kind}_Request", **fields), timeout=10)

huge = call(control, "Control", pause=True, multi_step=4000000000)
result["huge"] = [huge.success, huge.message]
started = time.monotonic()
long = call(control, "Control", pause=True, multi_step=50000000)  # ~14 h of sim time
result["long"] = [long.success, long.message, time.monotonic() - started < 5]
node.spin(0.5)
stepping = clocks[-1].iterations
node.spin(0.5)
result["stepping"] = clocks[-1].iterations > stepping  # stepping, and the bus is served
stop = call(control, "Control", pause=True)  # answered while stepping; ends the steps
result["stop"] = stop.success
node.spin(0.5)
held = clocks[-1].iterations
node.spin(0.5)
result["held"] = clocks[-1].iterations == held
far = call(create, "Create", name="far", sdf_filename=__import__("sys").argv[1],
           pose={"position": {"x": 1e300}})
result["far"] = [far.success, far.message]
moved = call(set_pose, "SetPose", name="bot", pose={"position": {"x": -1e300}})
result["moved"] = [moved.success, moved.message]
call(control, "Control", pause=False)
node.spin(0.5)
running = clocks[-1].iterations
node.spin(0.5)
result["running"] = clocks[-1].iterations > running
print("RESULT", json.dumps(result), flush=True)
node.destroy_node()
"""


def test_the_sim_refuses_what_would_freeze_or_brick_it(ws):
    ws.own_bus()
    ws.write("sim.launch.yaml", SIM_LAUNCH)
    proc = ws.start("launch", "sim.launch.yaml", output="launch.out")
    try:
        ws.wait_for_output("spawned 'bot' into world 'empty'", 60, "launch.out")
        ws.write("probe.py", PROBE)
        probe = subprocess.run([PY, "probe.py", ROBOT], cwd=ws.root, env=ws.env,
                               capture_output=True, text=True, timeout=120)
        assert probe.returncode == 0, probe.stderr
        result = json.loads(probe.stdout.split("RESULT", 1)[1])
        assert result["huge"] == [False, "multi_step 4000000000 is past the limit of "
                                         "100,000,000 steps in one request"]
        assert result["long"] == [True, "paused; stepping 50000000", True]
        assert result["stepping"] and result["stop"] and result["held"]
        assert not result["far"][0] and "out of range" in result["far"][1] and \
            "within ±1e+06 m" in result["far"][1]
        assert not result["moved"][0] and "out of range" in result["moved"][1]
        assert result["running"]  # the world was not bricked
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130


@pytest.mark.parametrize("world, expected", [
    ('<mujoco><option timestep="-1"/><worldbody/></mujoco>\n',
     "bad.xml:1:17: the timestep must be > 0 s, got -1"),
    ('<mujoco><option timestep="0"/><worldbody/></mujoco>\n',
     "bad.xml:1:17: the timestep must be > 0 s, got 0"),
    ('<mujoco>\n  <asset><mesh name="m" file="nosuch.stl"/></asset>\n'
     '  <worldbody><geom type="mesh" mesh="m"/></worldbody>\n</mujoco>\n',
     "bad.xml:2:31: MuJoCo could not compile the world: Error: Error opening file "
     "'nosuch.stl'"),
])
def test_worlds_the_sim_cannot_run_are_located_errors(ws, world, expected):
    ws.own_bus()
    path = ws.write("bad.xml", world)
    result = ws.run("sim", "--iterations", "10", str(path), timeout=60)
    assert result.returncode == 1
    assert expected in result.stderr, result.stderr
    assert "Traceback" not in result.stderr


@pytest.fixture
def fifo_ws(ws):
    ws.own_bus()
    os.mkfifo(ws.root / "fifo")
    return ws


def test_a_fifo_as_world_params_file_or_launch_file_is_refused(fifo_ws):
    ws = fifo_ws
    (ws.root / "world.sdf").symlink_to(ws.root / "fifo")
    world = ws.run("sim", str(ws.root / "world.sdf"), timeout=60)
    assert world.returncode == 1
    assert "fifo: a FIFO (named pipe), not a regular file" in world.stderr, world.stderr
    (ws.root / "params.yaml").symlink_to(ws.root / "fifo")
    ws.write("params.launch.yaml", """
    launch:
      - node: {pkg: robot_state_publisher, exec: robot_state_publisher,
               param: [{from: params.yaml}]}
    """)
    params = ws.run("launch", "params.launch.yaml", timeout=60)
    assert params.returncode == 1
    assert "params.yaml: a FIFO (named pipe), not a regular file" in params.stdout + \
        params.stderr
    (ws.root / "pipe.launch.yaml").symlink_to(ws.root / "fifo")
    (ws.root / "zero.launch.yaml").symlink_to("/dev/zero")
    for name, kind in (("pipe", "a FIFO (named pipe)"), ("zero", "a character device")):
        launched = ws.run("launch", f"{name}.launch.yaml", timeout=60)
        assert launched.returncode == 1
        assert f"{name}.launch.yaml: cannot be a launch file: {kind}, not a regular file" in \
            launched.stderr


def test_a_fifo_as_a_hook_is_refused(fifo_ws):
    ws = fifo_ws
    (ws.root / "src/busy/hooks").mkdir(parents=True)
    (ws.root / "src/busy/package.xml").write_text(
        '<package format="3"><name>busy</name><version>0.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">m</maintainer>'
        '<license>MIT</license></package>\n')
    (ws.root / "src/busy/hooks/busy.dsv").symlink_to(ws.root / "fifo")
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "src")
    ws.write("ok.launch.yaml", "launch: []\n")
    result = ws.run("launch", "ok.launch.yaml", timeout=60)
    assert result.returncode == 1
    assert "busy.dsv: a FIFO (named pipe), not a regular file" in result.stderr, result.stderr


def test_a_bridge_entry_of_no_known_type_is_a_located_error(ws):
    ws.own_bus()
    ws.write("bridge.yaml", """
    - ros_topic_name: chatter
      gz_topic_name: chatter
      ros_type_name: std_msgs/msg/Strin
      gz_type_name: gz.msgs.StringMsg
    """)
    ws.write("bridge.launch.yaml", """
    launch:
      - node:
          pkg: ros_gz_bridge
          exec: parameter_bridge
          output: screen
          param: [{name: config_file, value: bridge.yaml}]
    """)
    result = ws.run("launch", "bridge.launch.yaml", timeout=60)
    assert result.returncode == 1
    text = result.stdout + result.stderr
    assert "bridge.yaml:3:18: entry 1: ros_type_name: unknown message type " \
           "'std_msgs/msg/Strin' (did you mean 'std_msgs/msg/String'" in text, text
    assert "nothing to bridge: every entry was left out" in text
    assert "Traceback" not in text
