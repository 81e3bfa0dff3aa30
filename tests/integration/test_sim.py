"""The sim and create as real processes: real MuJoCo, real Zenoh, launched by launcher."""

from __future__ import annotations

import json
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.sim import ROBOT, SIM_LAUNCH

PY = sys.executable


# Talks to the running sim over the bus, as any node would, and prints what it saw as JSON.
PROBE = """
import json, time
from launcher.bus import keys
from launcher.bus.node import Node
node = Node("probe", space=keys.SIM)  # the sim's own side, as a gz-transport client
result = {}
clocks = []
odom = []
node.create_subscription("mujoco_sim/msg/Clock", "/world/empty/clock", clocks.append)
node.create_subscription("mujoco_sim/msg/Odometry", "/model/bot/odometry", odom.append)
control = node.create_client("mujoco_sim/srv/Control", "/world/empty/control")
assert control.wait_for_service(20)

def call(**fields):
    response = control.call(node.message("mujoco_sim/srv/Control_Request", **fields))
    node.spin(0.3)
    return response

def sim_time(c):
    return c.sim.sec + c.sim.nanosec * 1e-9

deadline = time.monotonic() + 20
while not odom and time.monotonic() < deadline:
    node.spin_once(0.1)
call(pause=True)
paused = clocks[-1]
call(pause=True, multi_step=250)
stepped = clocks[-1]
result["paused"] = paused.paused
result["step"] = [paused.iterations, stepped.iterations, sim_time(paused), sim_time(stepped)]
node.spin(0.3)
result["still"] = clocks[-1].iterations == stepped.iterations
call(pause=False)
cmd = node.create_publisher("mujoco_sim/msg/Twist", "/model/bot/cmd_vel")
start = odom[-1].pose.position.x
end = time.monotonic() + 2.0
while time.monotonic() < end:
    cmd.publish(node.message("mujoco_sim/msg/Twist", linear={"x": 0.5}))
    node.spin(0.1)
result["odom_moved"] = odom[-1].pose.position.x - start
times = [sim_time(c) for c in clocks]
result["monotonic"] = all(b >= a for a, b in zip(times, times[1:]))
result["clock_matches_steps"] = all(abs(sim_time(c) - c.iterations * 0.001) < 1e-6
                                    for c in clocks)
call(pause=False, reset_all=True)
result["after_reset"] = sim_time(clocks[-1])
states = []
node.create_subscription("mujoco_sim/msg/ModelStates", "/world/empty/model_states",
                         states.append)
set_pose = node.create_client("mujoco_sim/srv/SetPose", "/world/empty/set_pose")
moved = set_pose.call(node.message("mujoco_sim/srv/SetPose_Request", name="bot",
                                   pose={"position": {"x": 4.0, "y": 2.0, "z": 0.06}}))
node.spin(0.3)
bot = list(states[-1].name).index("bot")  # after the world's own ground_plane
result["set_pose"] = [moved.success, states[-1].pose[bot].position.x]
remove = node.create_client("mujoco_sim/srv/Remove", "/world/empty/remove")
gone = remove.call(node.message("mujoco_sim/srv/Remove_Request", name="bot"))
again = remove.call(node.message("mujoco_sim/srv/Remove_Request", name="bot"))
node.spin(0.3)
result["remove"] = [gone.success, again.success, again.message, list(states[-1].name)]
print("RESULT", json.dumps(result), flush=True)
node.destroy_node()
"""

DESCRIPTION = """
from pathlib import Path
import sys
from launcher.bus.node import Node
from launcher.bus.qos import LATCHED
node = Node("robot_state_publisher")
node.create_publisher("std_msgs/msg/String", "robot_description", LATCHED).publish(
    node.message("std_msgs/msg/String", data=Path(sys.argv[1]).read_text()))
print("description published", flush=True)
node.spin()
node.destroy_node()
"""


@pytest.fixture
def sim_ws(ws):
    return ws.own_bus()


def start_sim(ws, body: str = SIM_LAUNCH):
    ws.write("sim.launch.yaml", body)
    proc = ws.start("launch", "sim.launch.yaml", output="launch.out")
    return proc


def run_py(ws, name: str, text: str, *args: str, timeout: float = 60):
    ws.write(name, text)
    return subprocess.run([PY, name, *args], cwd=ws.root, env=ws.env, capture_output=True,
                          text=True, timeout=timeout)


def stop(proc) -> int:
    proc.send_signal(signal.SIGINT)
    return proc.wait(30)


def test_the_sim_serves_control_clock_and_drives_a_spawned_robot(sim_ws):
    proc = start_sim(sim_ws)
    sim_ws.wait_for_output("spawned 'bot' into world 'empty'", 60, "launch.out")
    probe = run_py(sim_ws, "probe.py", PROBE)
    assert probe.returncode == 0, probe.stderr
    result = json.loads(probe.stdout.split("RESULT", 1)[1])
    assert result["paused"] is True
    before, after, t_before, t_after = result["step"]
    assert after - before == 250 and t_after - t_before == pytest.approx(0.25, abs=1e-9)
    assert result["still"]  # paused: no steps without a request
    assert result["odom_moved"] > 0.3  # ~0.5 m/s for 2 s, commanded over the bus
    assert result["monotonic"] and result["clock_matches_steps"]
    assert result["after_reset"] < 0.5
    assert result["set_pose"][0] and result["set_pose"][1] == pytest.approx(4.0, abs=0.05)
    assert result["remove"][:2] == [True, False] and "no entity named 'bot'" in \
        result["remove"][2] and result["remove"][3] == ["ground_plane"]
    assert stop(proc) == 130
    out = sim_ws.output("launch.out")
    assert "world 'empty'" in out and "process has finished cleanly" in out or \
        "process stopped" in out


def test_create_from_a_latched_topic_and_the_sims_refusals(sim_ws):
    proc = start_sim(sim_ws, """
launch:
  - node: {pkg: mujoco_sim, exec: sim, args: "-r -v 3", output: screen}
""")
    sim_ws.wait_for_output("world 'empty'", 60, "launch.out")  # its router is up
    sim_ws.write("desc.py", DESCRIPTION)

    describer = subprocess.Popen([PY, "desc.py", ROBOT], cwd=sim_ws.root, env=sim_ws.env,
                                 stdout=subprocess.PIPE, text=True)
    try:
        assert "description published" in describer.stdout.readline()
        first = sim_ws.run("sim", "--help")  # the CLI's own help, not the launcher's
        assert "--iterations N" in first.stdout
        create = [PY, "-m", "launcher.nodes.create"]
        done = subprocess.run(create + ["-entity", "my_robot", "-topic", "robot_description",
                                        "-z", "0.06"], cwd=sim_ws.root, env=sim_ws.env,
                              capture_output=True, text=True, timeout=60)
        assert done.returncode == 0, done.stderr
        assert "spawned 'my_robot'" in done.stdout
        again = subprocess.run(create + ["-name", "my_robot", "-file", ROBOT], cwd=sim_ws.root,
                               env=sim_ws.env, capture_output=True, text=True, timeout=60)
        assert again.returncode == 1
        assert "the sim refused: an entity named 'my_robot' already exists" in again.stderr
        renamed = subprocess.run(create + ["-name", "my_robot", "-file", ROBOT,
                                           "-allow_renaming", "true", "-x", "2"],
                                 cwd=sim_ws.root, env=sim_ws.env, capture_output=True,
                                 text=True, timeout=60)
        assert renamed.returncode == 0 and "spawned 'my_robot_1'" in renamed.stdout
        params = subprocess.run(create + ["--ros-args", "-p", "name:=third", "-p",
                                          f"file:={ROBOT}", "-p", "y:=2.0"],
                                cwd=sim_ws.root, env=sim_ws.env, capture_output=True,
                                text=True, timeout=60)
        assert params.returncode == 0 and "spawned 'third'" in params.stdout, params.stderr
        inline = subprocess.run(create + ["-name", "inline", "-x", "4", "-string",
                                          Path(ROBOT).read_text()], cwd=sim_ws.root,
                                env=sim_ws.env, capture_output=True, text=True, timeout=60)
        assert inline.returncode == 0 and "spawned 'inline'" in inline.stdout, inline.stderr
        from_param = subprocess.run(create + ["-param", "robot_description", "-name", "p",
                                              "-x", "6", "--ros-args", "-p",
                                              f"robot_description:={Path(ROBOT).read_text()}"],
                                    cwd=sim_ws.root, env=sim_ws.env, capture_output=True,
                                    text=True, timeout=60)
        assert from_param.returncode == 0, from_param.stderr
        states = sim_ws.run("topic", "echo", "--sim", "/world/empty/model_states", "--once",
                            "--field", "name")
        assert "my_robot" in states.stdout and "third" in states.stdout, states.stderr
    finally:
        describer.send_signal(signal.SIGINT)
        describer.wait(10)
    assert stop(proc) == 130


def test_create_without_a_sim_exits_1_after_its_timeout(sim_ws):
    sim_ws.env["LAUNCHER_BUS_TIMEOUT"] = "0.5"
    done = run_py(sim_ws, "c.py", "from launcher.nodes.create import main; "
                  "raise SystemExit(main())", "-file", ROBOT, "-timeout", "1")
    assert done.returncode == 1
    assert "no sim answered" in done.stderr and "within 1 s" in done.stderr
    assert "Traceback" not in done.stderr


@pytest.mark.parametrize("args, expected", [
    ([], "nothing to spawn: give one of -file, -string, -param or -topic"),
    (["-file", "a.urdf", "-string", "<robot/>"], "give one source, not -file, -string"),
    (["-fle", "a.urdf"], "unknown option '-fle' (did you mean '-file'"),
    (["-file", "a.urdf", "-x", "nan"], "-x: expected a finite number, got 'nan'"),
    (["-file", "a.urdf", "-timeout", "-1"], "-timeout: expected a number ≥ 0, got -1"),
])
def test_create_bad_arguments(sim_ws, args, expected):
    done = run_py(sim_ws, "c.py", "from launcher.nodes.create import main; "
                  "raise SystemExit(main())", *args)
    assert done.returncode == 2 and expected in done.stderr, done.stderr
    assert "Traceback" not in done.stderr


def test_a_bad_world_name_lists_the_places_searched(sim_ws):
    sim_ws.env["MUJOCO_SIM_RESOURCE_PATH"] = str(sim_ws.root / "worlds")
    (sim_ws.root / "worlds").mkdir()
    (sim_ws.root / "worlds" / "robot.xml").write_text("<mujoco model='robot'/>")
    done = sim_ws.run("sim", "robto.xml")
    assert done.returncode == 1
    assert "world 'robto.xml' not found; searched:" in done.stderr
    assert str(sim_ws.root / "worlds") in done.stderr and "did you mean 'robot.xml'" in done.stderr
    assert "Traceback" not in done.stderr


def test_iterations_stops_the_sim_and_an_unrunnable_world_is_one_clean_error(sim_ws):
    done = sim_ws.run("sim", "-r", "--iterations", "500", "-z", "0")
    assert done.returncode == 0, done.stderr
    (sim_ws.root / "bad.xml").write_text('<mujoco model="bad">\n<worldbody>\n'
                                         '<geom type="box" size="1"/>\n</worldbody>\n</mujoco>\n')
    bad = sim_ws.run("sim", "bad.xml")
    assert bad.returncode == 1 and "bad.xml" in bad.stderr and "line 3" in bad.stderr.lower()
    assert "Traceback" not in bad.stderr


def png_size_and_pixels(path: Path) -> tuple[int, int, bytes]:
    import struct
    import zlib

    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])
    idat = data.index(b"IDAT")
    length = struct.unpack(">I", data[idat - 4:idat])[0]
    return width, height, zlib.decompress(data[idat + 4:idat + 4 + length])


def test_snapshot_renders_the_running_world_to_png(sim_ws):
    proc = start_sim(sim_ws)
    try:
        sim_ws.wait_for_output("spawned 'bot'", 60, "launch.out")
        done = sim_ws.run("sim", "snapshot", "-o", "world.png", "--width", "320",
                          "--height", "240", "--track", "bot")
        assert done.returncode == 0, done.stdout + done.stderr
        assert "wrote world.png (320x240, world 'empty')" in done.stdout
        width, height, rows = png_size_and_pixels(sim_ws.root / "world.png")
        assert (width, height) == (320, 240) and len(rows) == 240 * (320 * 3 + 1)
        assert len(set(rows)) > 20  # a picture, not one flat colour
        bad = {  # each refused with the reason, the sim still running
            ("--camera", "top"): "no camera 'top' in world 'empty'",
            ("--track", "boot"): "no entity 'boot' in world 'empty' (did you mean 'bot'?)",
            ("--width", "0"): "--width 0: each side must be 1 to 4096 pixels",
            ("--height", "5000"): "--height 5000: each side must be 1 to 4096 pixels",
            ("--world", "nowhere", "--timeout", "1"): "no sim with world 'nowhere' answered",
        }
        for args, message in bad.items():
            refused = sim_ws.run("sim", "snapshot", "-o", "x.png", *args)
            assert refused.returncode == 1 and message in refused.stderr, refused.stderr
            assert "Traceback" not in refused.stderr
        missing = sim_ws.run("sim", "snapshot", "-o", "no/such/folder/x.png")
        assert missing.returncode == 1 and "the folder 'no/such/folder' does not exist" \
            in missing.stderr
        assert not (sim_ws.root / "x.png").exists()
    finally:
        assert stop(proc) == 130


def test_snapshot_without_a_sim_says_so(sim_ws):
    done = sim_ws.run("sim", "snapshot", "-o", "x.png", "--timeout", "1")
    assert done.returncode == 1
    assert "no /world/<name>/snapshot service appeared within 1 s; is the sim running?" \
        in done.stderr


MJCF_ROBOT = """<mujoco model="bot"><worldbody><body name="base">
<geom type="box" size=".2 .1 .05"/><body name="arm" pos="0 0 .1"><joint name="j" axis="0 0 1"/>
<geom type="capsule" size=".02 .1"/></body></body></worldbody></mujoco>"""


def test_create_spawns_an_mjcf_robot_from_a_file_as_it_spawns_an_sdf_one(sim_ws):
    sim_ws.write("bot.xml", MJCF_ROBOT)
    sim = sim_ws.start("sim", "-r", "-v", "3", output="sim.out")
    try:
        sim_ws.wait_for_output("world 'empty'", 60, "sim.out")
        done = sim_ws.run("run", "ros_gz_sim", "create", "-file", "bot.xml", "-name", "r1",
                          "-x", "2", "-z", "1", timeout=60)
        assert done.returncode == 0, done.stderr
        listed = sim_ws.run("gz", "model", "--list", timeout=30).stdout
        pose = sim_ws.run("gz", "model", "-m", "r1", "-p", timeout=30).stdout
    finally:
        assert stop(sim) in (0, 130)
    assert "- r1" in listed, listed
    assert "[2.000000 0.000000" in pose, pose  # its pose, falling from 1 m


def test_create_with_a_keyframe_the_robot_lacks_is_refused_naming_the_nearest(sim_ws):
    sim_ws.write("bot.xml", MJCF_ROBOT.replace(
        "</worldbody>", '</worldbody><keyframe><key name="bent" qpos="0.5"/></keyframe>'))
    sim = sim_ws.start("sim", "-r", "-v", "3", output="sim.out")
    try:
        sim_ws.wait_for_output("world 'empty'", 60, "sim.out")
        refused = sim_ws.run("run", "ros_gz_sim", "create", "-file", "bot.xml", "-name", "r1",
                             "-keyframe", "bnet", timeout=60)
        done = sim_ws.run("run", "ros_gz_sim", "create", "-file", "bot.xml", "-name", "r1",
                          "-keyframe", "bent", timeout=60)
    finally:
        assert stop(sim) in (0, 130)
    assert refused.returncode == 1 and "Traceback" not in refused.stderr
    assert "no keyframe 'bnet' in the description (did you mean 'bent'?)" in refused.stderr, \
        refused.stderr
    assert done.returncode == 0, done.stderr


def test_an_unknown_keyframe_is_one_clean_error_naming_the_nearest(sim_ws):
    sim_ws.write("keyed.xml", '<mujoco model="keyed"><worldbody><body name="ball" pos="0 0 1">'
                 '<freejoint/><geom size="0.1"/></body></worldbody><keyframe>'
                 '<key name="high" qpos="0 0 3 1 0 0 0"/></keyframe></mujoco>')
    done = sim_ws.run("sim", "keyed.xml", "--keyframe", "hihg")
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert "keyed.xml: no keyframe 'hihg' in the world (did you mean 'high'?)" in done.stderr, \
        done.stderr
