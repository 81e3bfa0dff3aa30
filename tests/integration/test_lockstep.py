"""The sim in lockstep with the nodes on sim time (`gz sim --lockstep`, LAUNCHER_SIM_LOCKSTEP):
real sim, bridge, robot_state_publisher, xacro, create and driver processes. A run repeats
exactly; time stands still while no node on sim time is there; a node that stops answering
does not hold the sim."""

from __future__ import annotations

import re
import subprocess
import sys
import time

import pytest

from tests.support.environment import REPO
from tests.support.processes import launcher_argv

BRIDGE = REPO / "packages" / "robot_bringup" / "config" / "bridge.yaml"

# The demo's robot, spawned while time stands still (no node on sim time yet); the driver
# starts once it is there and the recorder hears odometry, so a run's every step is the same
# and the recorder (no lockstep member: it is not on sim time) misses none of them.
SCENARIO = """
launch:
  - executable:
      cmd: gz sim -v 3 -s -r --lockstep robot.world
      output: screen
  - node: {{pkg: ros_gz_bridge, exec: parameter_bridge, output: screen,
           args: "--ros-args -p config_file:={bridge}"}}
  - node:
      pkg: robot_state_publisher
      exec: robot_state_publisher
      param:
        - name: robot_description
          value: "$(command 'xacro $(find-pkg-share robot_description)/urdf/robot.xacro')"
  - node:
      pkg: ros_gz_sim
      exec: create
      args: "-entity my_robot -topic robot_description"
      on_exit:
        - executable:
            cmd: "{python} wait_ready.py"
            on_exit:
              - node: {{pkg: robot_application, exec: driver, output: screen,
                       param: [{{name: use_sim_time, value: true}}]}}
  - executable: {{cmd: "{python} recorder.py", output: screen, on_exit: shutdown}}
"""

# Where odometry says the robot is at whole seconds of sim time, to the last bit. It says
# it is ready once it has found the odometry's publisher.
RECORDER = """
from pathlib import Path

import rclpy
from nav_msgs.msg import Odometry

rclpy.init()
node = rclpy.create_node("recorder")
done = []


def on_odom(message):
    stamp = round(message.header.stamp.sec + message.header.stamp.nanosec / 1e9, 3)
    if stamp in (1.0, 2.0, 3.0):
        p = message.pose.pose.position
        print(f"AT {stamp} {p.x!r} {p.y!r}", flush=True)
        done.append(stamp == 3.0)


node.create_subscription(Odometry, "/odom", on_odom, 1000)  # (none dropped)
while not node.count_publishers("/odom"):
    rclpy.spin_once(node, timeout_sec=0.05)
Path("recorder.ready").touch()
while not any(done):
    rclpy.spin_once(node, timeout_sec=0.1)
node.destroy_node()
rclpy.shutdown()
"""

WAIT_READY = """
import sys
import time
from pathlib import Path

deadline = time.monotonic() + 60
while not Path("recorder.ready").exists():
    if time.monotonic() > deadline:
        sys.exit("the recorder never found the odometry")
    time.sleep(0.02)
"""


@pytest.fixture
def scenario(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(REPO / "packages")
    ws.write("recorder.py", RECORDER)
    ws.write("wait_ready.py", WAIT_READY)
    ws.write("scenario.launch.yaml", SCENARIO.format(bridge=BRIDGE, python=sys.executable))
    return ws


def run_scenario(ws) -> list[str]:
    done = ws.run("launch", "scenario.launch.yaml", "--noninteractive", timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    lines = [line.split("] ", 1)[-1] for line in done.stdout.splitlines() if "] AT " in line]
    assert len(lines) == 3, done.stdout + done.stderr
    return lines


def test_a_run_in_lockstep_repeats_exactly(scenario):
    first, second = run_scenario(scenario), run_scenario(scenario)
    assert first == second
    x, y = (float(v) for v in first[-1].split()[2:])
    assert x * x + y * y > 1.0  # three seconds at 0.5 m/s: it drove


def test_the_driver_joins_the_lockstep_and_the_bridge_with_it(scenario):
    done = scenario.run("launch", "scenario.launch.yaml", "--noninteractive", timeout=120)
    assert "lockstep: /parameter_bridge (a bridge) joined" in done.stdout
    assert "lockstep: /driver (a node on sim time) joined" in done.stdout


def clock_after(ws, seconds: float) -> str:
    """The sim's time (its clock's `sim` part, through `gz topic`) after `seconds` of wall
    time."""
    time.sleep(seconds)
    out = ws.run("gz", "topic", "-e", "-t", "/clock", "-n", "1", timeout=30).stdout
    assert out.startswith("real {") or out.startswith("sim {"), out  # a clock came
    found = re.search(r"^sim \{[^}]*\}", out, re.MULTILINE)
    return found.group(0) if found else "sim {}"  # (zero: left out, as protobuf's text)


def test_time_stands_still_while_no_node_on_sim_time_is_there(scenario):
    sim = scenario.start("sim", "-v", "3", "-s", "-r", "--lockstep", "robot.world",
                         output="sim.out")
    try:
        scenario.wait_for_output("in lockstep", 60, "sim.out")
        first = clock_after(scenario, 0.5)
        assert clock_after(scenario, 1.0) == first
    finally:
        sim.send_signal(2)
        sim.wait(30)


HANGER = """
import time
from launcher.bus.node import Node
node = Node("hanger")
state = {"calls": 0}
def tick():
    state["calls"] += 1
    if state["calls"] == 3:
        time.sleep(600)  # stops answering: its executor never comes back
node.create_timer(0.1, tick, node.get_clock())
node.spin()
"""


def test_a_node_that_stops_answering_is_said_and_does_not_hold_the_sim(scenario):
    scenario.write("hanger.py", HANGER)
    scenario.write("hang.launch.yaml", f"""
launch:
  - executable: {{cmd: gz sim -v 3 -s -r --lockstep robot.world, output: screen}}
  - node: {{pkg: ros_gz_bridge, exec: parameter_bridge,
           args: "--ros-args -p config_file:={BRIDGE}"}}
  - executable: {{cmd: "{sys.executable} hanger.py --ros-args -p use_sim_time:=true",
                 output: screen}}
""")
    launch = scenario.start("launch", "hang.launch.yaml", output="hang.out")
    try:
        text = scenario.wait_for_output("going on without it", 60, "hang.out")
        assert re.search(r"lockstep: /hanger did not answer for sim time 0\.3\d\d s within 2 s "
                         r"of wall time; going on without it until it answers", text), text
        before = clock_after(scenario, 0.1)
        assert clock_after(scenario, 1.0) != before  # the sim went on
    finally:
        launch.send_signal(2)
        assert launch.wait(60) == 130


def sim_error(ws, *words: str, env: dict | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([*launcher_argv(), "sim", *words], cwd=ws.root,
                          env={**ws.env, **(env or {})}, capture_output=True, text=True,
                          timeout=60)


def test_a_bad_lockstep_variable_is_said_with_what_it_takes(ws):
    done = sim_error(ws, "-s", env={"LAUNCHER_SIM_LOCKSTEP": "fast"})
    assert done.returncode == 2
    assert "LAUNCHER_SIM_LOCKSTEP='fast': expected true, false or a tick in seconds (> 0)" \
        in done.stderr


def test_lockstep_and_a_pace_are_refused_together(ws):
    done = sim_error(ws, "-s", "--lockstep", "-z", "100")
    assert done.returncode == 2
    assert "argument -z/--rate: not allowed with argument --lockstep" in done.stderr


def test_a_lockstep_tick_must_be_positive(ws):
    done = sim_error(ws, "-s", "--lockstep", "--lockstep-tick", "0")
    assert done.returncode == 2 and "--lockstep-tick must be > 0 s, got 0" in done.stderr
