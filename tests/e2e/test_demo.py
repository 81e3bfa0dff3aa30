"""The demo stack end to end: launch_files/robot.launch.yaml (the seed project's launch file,
unchanged, and a driver) with real sim, bridge, robot_state_publisher, xacro, create and
driver processes on a real Zenoh router; the worlds are SDF, found through the hooks."""

from __future__ import annotations

import collections
import queue
import random
import re
import shutil
import signal
import subprocess
import threading
import time

import psutil
import pytest

from tests.support.environment import REPO, shared
from tests.support.processes import launcher_argv, tagged_processes

LAUNCH = str(REPO / "launch_files" / "robot.launch.yaml")


@pytest.fixture
def demo(ws):
    ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(REPO / "packages")
    return ws


def positions(text: str) -> list[tuple[float, float]]:
    return [(float(x), float(y)) for x, y in re.findall(r"X: (-?[\d.]+), Y: (-?[\d.]+)", text)]


def wait_for_driving(ws, timeout: float = 90) -> None:
    """Until the driver prints a position past 0.15 m from the start: it drives and odometry
    flows. (It prints twice a second, so a fixed text such as "X: 0.2" may be stepped over.)"""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if any(max(abs(x), abs(y)) > 0.15 for x, y in positions(ws.output("demo.out"))):
            return
        time.sleep(0.05)
    raise AssertionError(f"the robot did not drive:\n{ws.output('demo.out')}")


def first_line_with(ws, args: list[str], needle: str, timeout: float = 60) -> str:
    """Run `launcher ARGS` until a line holds `needle`; that line. None within `timeout`
    seconds fails the test, saying what the command printed (its errors too) and whether it
    had ended."""
    proc = subprocess.Popen([*launcher_argv(), *args], cwd=ws.root, env=ws.env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    lines: queue.Queue[str] = queue.Queue()
    seen: collections.deque[str] = collections.deque(maxlen=12)
    count = 0

    def read() -> None:  # (ends with the output)
        for line in proc.stdout:
            lines.put(line)

    threading.Thread(target=read, daemon=True).start()
    deadline = time.monotonic() + timeout
    try:
        while time.monotonic() < deadline:
            try:
                line = lines.get(timeout=max(0.0, deadline - time.monotonic()))
            except queue.Empty:
                break
            if needle in line:
                return line
            seen.append(line)
            count += 1
        ended = proc.poll()
        raise AssertionError(
            f"no line with {needle!r} from `launcher {' '.join(args)}` in {timeout:g} s: "
            f"{count} other lines, the command {'running' if ended is None else f'ended ({ended})'};"
            f" its last lines:\n{''.join(seen)}{_diagnose(ws, lines)}")
    finally:
        proc.send_signal(signal.SIGINT)
        proc.wait(30)


def _diagnose(ws, lines: queue.Queue) -> str:
    """What the graph says when a topic stays silent: who publishes it, and whether the sim
    sends what the bridges and robot_state_publisher turn into /tf (a chain woken only by a
    subscriber: which link is asleep). Then whether the silent echo has heard anything since."""
    said = []
    for command in (["topic", "info", "/tf", "-v"],
                    ["topic", "echo", "/robot_2/joint_states", "--once", "--timeout", "5"],
                    ["topic", "echo", "--sim", "/model/robot_2/tf", "--once", "--timeout", "5"]):
        done = ws.run(*command, timeout=30)
        said.append(f"$ launcher {' '.join(command)} (exit {done.returncode})\n"
                    f"{done.stdout[-1500:]}{done.stderr[-800:]}")
    time.sleep(3)
    said.append(f"lines from the silent echo since: {lines.qsize()}")
    return "\n" + "\n".join(said)


def sim_seconds(ws) -> float:
    out = ws.run("topic", "echo", "/clock", "--once").stdout
    sec = int(re.search(r"sec: (\d+)", out).group(1))
    nanosec = int(re.search(r"nanosec: (\d+)", out).group(1))
    return sec + nanosec * 1e-9


def test_the_demo_drives_publishes_tf_and_clock_and_stops_cleanly(demo):
    proc = demo.start("launch", LAUNCH, output="demo.out")
    try:
        demo.wait_for_output("spawned 'my_robot' into world 'robot'", 90, "demo.out")
        text = demo.wait_for_output("X: 1.", 90, "demo.out")  # past a metre
        xs = [x for x, _ in positions(text)]
        assert xs[-1] > xs[0] + 0.9
        assert "CrateDropper: spawned 'crate'" in text  # the world plugin, through the hooks
        wheel = first_line_with(demo, ["topic", "echo", "/tf"], "child_frame_id: left_wheel")
        assert wheel  # robot_state_publisher's wheel transforms
        odom = first_line_with(demo, ["topic", "echo", "/tf"], "child_frame_id: base_link")
        assert odom  # the diff drive's odom -> base_link, through the bridge
        before = sim_seconds(demo)
        demo.wait_for_output("X: 1.5", 60, "demo.out")
        assert sim_seconds(demo) > before
        names = demo.run("topic", "echo", "--sim", "/world/robot/model_states", "--once", "--field",
                         "name").stdout
        assert "my_robot" in names and "crate" in names
    finally:
        proc.send_signal(signal.SIGINT)
        code = proc.wait(60)
    assert code == 130  # documented: Ctrl-C ends with 130, everything stopped
    out = demo.output("demo.out")
    for name in ("gz", "robot_state_publisher", "parameter_bridge", "driver"):
        assert re.search(rf"\[{name}-\d+\]: process (stopped|has finished)", out), name


def test_overrides_pick_the_arena_and_leave_the_driver_out(demo):
    proc = demo.start("launch", LAUNCH, "world_name:=arena.xml.j2", "drive:=false",
                      output="demo.out")
    try:
        demo.wait_for_output("spawned 'my_robot' into world 'arena'", 90, "demo.out")
        names = demo.run("topic", "echo", "--sim", "/world/arena/model_states", "--once", "--field",
                         "name").stdout
        assert "my_robot" in names
        assert "[driver" not in demo.output("demo.out")
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(60) == 130


def test_a_bad_world_name_names_the_places_searched(demo):
    done = demo.run("launch", LAUNCH, "world_name:=nowhere.world", "drive:=false",
                    "--duration", "10", timeout=120)
    text = done.stdout + done.stderr
    assert "world 'nowhere.world' not found; searched:" in text
    assert "robot_gazebo/worlds (GZ_SIM_RESOURCE_PATH)" in text
    assert done.returncode == 1  # the seed's file has no on_exit: the sim's exit 1 counts


@pytest.mark.parametrize("container", ["all", "per_robot", "none"])
def test_three_robots_from_one_launch_file_move_independently(demo, container):
    """Each robot's nodes in one component container for all (the default), one per robot,
    or a process per node: the same robots, the same motion."""
    launch = str(REPO / "launch_files" / "multi_robot.launch.yaml")
    proc = demo.start("launch", launch, "count:=3", f"container:={container}",
                      output="multi.out")
    try:
        for i in range(3):
            demo.wait_for_output(f"spawned 'robot_{i}' into world 'robot'", 90, "multi.out")
        names = demo.run("topic", "echo", "--sim", "/world/robot/model_states", "--once", "--field",
                         "name").stdout
        assert all(f"robot_{i}" in names for i in range(3))
        demo.wait_for_output("X: 1.", 90, "multi.out")  # the fastest is past a metre
        xs = []
        for i in range(3):  # speeds 0.2, 0.3, 0.4 m/s: each its own odometry
            out = demo.run("topic", "echo", f"/robot_{i}/odom", "nav_msgs/msg/Odometry",
                           "--once", "--field", "pose.pose.position.x").stdout
            xs.append(float(out.split()[0]))
        assert xs[0] < xs[1] < xs[2] and xs[0] > 0.1, xs
        frames = first_line_with(demo, ["topic", "echo", "/tf"], "child_frame_id: robot_2/")
        assert frames  # tf frames carry each robot's prefix
        containers = {"all": 1, "per_robot": 3, "none": 0}[container]
        assert len([p for p in psutil.Process(proc.pid).children(recursive=True)
                    if "component_container" in " ".join(p.cmdline())]) == containers
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(60) == 130


def test_the_same_stack_from_the_xml_launch_file(demo):
    proc = demo.start("launch", "robot_bringup", "robot.launch.xml", output="xml.out")
    try:
        demo.wait_for_output("spawned 'my_robot' into world 'robot'", 90, "xml.out")
        xs = [x for x, _ in positions(demo.wait_for_output("X: 1.", 90, "xml.out"))]
        assert xs[-1] > xs[0] + 0.9
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(60) == 130


def test_the_same_stack_from_the_python_launch_file_with_an_override(demo):
    launch = str(REPO / "launch_files" / "robot.launch.py")
    proc = demo.start("launch", launch, "world_name:=arena.xml.j2", output="py.out")
    try:  # the override reaches ros_gz_sim's gz_sim.launch.py through two includes
        demo.wait_for_output("spawned 'my_robot' into world 'arena'", 90, "py.out")
        xs = [x for x, _ in positions(demo.wait_for_output("X: 1.", 90, "py.out"))]
        assert xs[-1] > xs[0] + 0.9
        wheel = first_line_with(demo, ["topic", "echo", "/tf"], "child_frame_id: right_wheel")
        assert wheel
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(60) == 130


def test_the_hooks_put_the_worlds_on_the_sim_path(demo):
    """`launcher gz sim robot.world` finds the world only through robot_gazebo's hooks (the
    seed's GZ_SIM_RESOURCE_PATH hook), its model and world plugin through the others."""
    workspace = demo.root / "ws"
    shutil.copytree(REPO / "packages" / "robot_gazebo", workspace / "robot_gazebo")
    demo.env["LAUNCHER_PACKAGE_PATH"] = str(workspace)
    hooks = workspace / "robot_gazebo" / "hooks"

    def sim():
        return demo.run("gz", "sim", "-v", "4", "-r", "--iterations", "200", "robot.world",
                        timeout=120)

    done = sim()
    assert done.returncode == 0, done.stdout + done.stderr
    assert f"from {hooks.parent}/worlds/robot.world" in done.stdout
    assert "CrateDropper: spawned" in done.stdout  # the plugin path came from them too
    shutil.move(hooks, demo.root / "hooks.bak")
    done = sim()
    text = done.stdout + done.stderr
    assert done.returncode == 1
    assert "world 'robot.world' not found; searched:" in text and "Traceback" not in text
    assert "GZ_SIM_RESOURCE_PATH is not set" in text
    shutil.move(demo.root / "hooks.bak", hooks)
    assert sim().returncode == 0


def test_a_bag_of_odom_recorded_during_the_run_opens_with_mcap(demo):
    from mcap.reader import make_reader

    proc = demo.start("launch", LAUNCH, output="demo.out")
    try:
        wait_for_driving(demo)
        done = demo.run("bag", "record", "/odom", "-o", "run1", "--duration", "6",
                        timeout=60)
        assert done.returncode == 0, done.stdout + done.stderr
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(60) == 130
    (bag,) = (demo.root / "run1").glob("*.mcap")
    with open(bag, "rb") as handle:
        messages = list(make_reader(handle).iter_messages(topics=["/odom"]))
    expected = 50 * 6  # the diff drive's odom_publish_frequency, at real-time pace
    assert abs(len(messages) - expected) <= expected * 0.1, len(messages)
    _, channel, _ = messages[0]
    assert channel.topic == "/odom"


def launched(proc, name: str):
    """The child of launcher process `proc` whose command line holds `name`."""
    for child in psutil.Process(proc.pid).children(recursive=True):
        if name in " ".join(child.cmdline()):
            return child
    raise AssertionError(f"no child process '{name}'")


def test_kill_9_of_the_sim_ends_the_launch_and_leaves_nothing(demo):
    # the Python file runs the sim as the seed's gazebo.launch.py does: on_exit_shutdown
    proc = demo.start("launch", str(REPO / "launch_files" / "robot.launch.py"),
                      output="demo.out")
    wait_for_driving(demo)
    launched(proc, "launcher gz sim").kill()  # SIGKILL: the sim cannot clean up
    code = proc.wait(60)  # on_exit_shutdown in the launch file; the fixture checks orphans
    out = demo.output("demo.out")
    assert code == 1, out  # a process died of a cause the launcher did not give it
    assert re.search(r"\[sim-\d+\]: process was killed by SIGKILL", out), out
    for name in ("robot_state_publisher", "parameter_bridge", "driver"):
        assert re.search(rf"\[{name}-\d+\]: process stopped", out), name


def test_sigterm_to_the_launcher_stops_everything(demo):
    proc = demo.start("launch", LAUNCH, output="demo.out")
    wait_for_driving(demo)
    children = psutil.Process(proc.pid).children(recursive=True)
    proc.send_signal(signal.SIGTERM)
    assert proc.wait(60) == 143
    _, alive = psutil.wait_procs(children, timeout=10)
    assert not alive, alive


def test_the_square_node_drives_a_square_and_reports_its_closing_error(demo):
    demo.write("square.launch.yaml", """
    launch:
      - include:
          file: "$(find-pkg-share robot_bringup)/launch/robot.launch.yaml"
          arg: [{name: drive, value: "false"}]
      - node:
          pkg: robot_application
          exec: square
          output: screen
          on_exit: shutdown
          param: [{name: side, value: 1.0}]
    """)
    done = demo.run("launch", "square.launch.yaml", timeout=240)
    out = done.stdout
    assert "leg 4 done" in out, out
    error = float(re.search(r"closing error: ([\d.]+) m after a 1 m square", out).group(1))
    assert error < 0.25, out  # odometry closes the square; a runaway would not
    assert re.search(r"\[square-\d+\]: process has finished cleanly", out)
    assert done.returncode == 0, out + done.stderr


def test_ten_robots_all_spawn_and_publish_odometry(demo):
    """Forty-one nodes start at once. Their peer links to the sim, which starts last, come late
    or not at all; `create` asks the router who is on the bus, so all ten find the sim (a
    peer's own liveliness query once left most of them waiting forever)."""
    launch = str(REPO / "launch_files" / "multi_robot.launch.yaml")
    proc = demo.start("launch", launch, "count:=10", output="ten.out")
    try:
        for i in range(10):
            demo.wait_for_output(f"spawned 'robot_{i}' into world 'robot'", 180, "ten.out")
        for i in range(10):
            out = demo.run("topic", "echo", f"/robot_{i}/odom", "nav_msgs/msg/Odometry",
                           "--once", "--field", "child_frame_id", timeout=60).stdout
            assert f"robot_{i}/base_link" in out, (i, out)
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(90) == 130


SEED = ("seeds", "001_ea06ae6f7572c47f.txt")  # the seed project, in ../shared


def test_the_demo_files_are_the_seed_projects_own_unchanged():
    seed = shared(*SEED).read_text()
    launch = seed[seed.index("launch:\n  - arg:"):seed.index("bridge.yaml\n")]
    assert (REPO / "launch_files" / "robot.launch.yaml").read_text().startswith(launch)
    python = seed[seed.index("import os\nfrom ament_index_python"):]
    bringup = REPO / "packages" / "robot_bringup" / "launch" / "gazebo.launch.py"
    assert bringup.read_text().rstrip("\n") == python.rstrip("\n")
    hook = REPO / "packages" / "robot_gazebo" / "hooks" / "robot_gazebo.dsv.in"
    assert hook.read_text().strip() == ("prepend-non-duplicate;GZ_SIM_RESOURCE_PATH;share;"
                                        "@CMAKE_INSTALL_PREFIX@/share/robot_gazebo/worlds")


def test_the_seeds_gazebo_launch_py_runs_its_sdf_world_through_the_hooks(demo):
    proc = demo.start("launch", "robot_bringup", "gazebo.launch.py", output="gazebo.out")
    try:
        listed = ""
        for _ in range(60):  # the sim is up once it answers
            listed = demo.run("gz", "model", "--list", "--timeout", "2").stdout
            if "box_model" in listed:
                break
        assert "Requesting state for world [world]" in listed, demo.output("gazebo.out")
        for model in ("ground_plane", "box_model", "second_box"):
            assert f"    - {model}" in listed, listed
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(60) == 130


def test_the_demo_hit_by_a_signal_at_a_random_moment_leaves_nothing(demo):
    """SIGINT, SIGTERM or SIGKILL to the launcher anywhere from its start-up to the robot
    driving: every process of the demo goes (the router, shared by the graph, goes by itself
    once idle). The sim exits on SIGINT or SIGTERM by itself: never SIGKILLed."""
    rng = random.Random(11)
    for run, sig in enumerate([signal.SIGKILL, signal.SIGINT, signal.SIGTERM, signal.SIGKILL,
                               signal.SIGINT]):
        name = f"demo{run}.out"
        proc = demo.start("launch", LAUNCH, output=name)
        time.sleep(rng.uniform(0.3, 4.0))
        proc.send_signal(sig)
        code = proc.wait(60)
        assert code in (-9, 130, 143), (run, code)
        deadline = time.monotonic() + 20
        def left() -> list[psutil.Process]:
            found = []
            for proc in tagged_processes(demo.tag):
                try:
                    if "launcher.bus.router" not in " ".join(proc.cmdline()):
                        found.append(proc)
                except psutil.Error:  # gone since it was listed
                    continue
            return found

        while left() and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not left(), (run, sig, [p.pid for p in left()])
        text = demo.output(name)
        assert "sending SIGKILL" not in text, text


def test_on_the_running_demo_ps_lists_the_stack_and_a_restarted_node_publishes_again(demo):
    """The user's hand on the demo: `launcher ps` lists its processes, `launcher restart
    robot_state_publisher` gives a new process, whose wheel transforms reach /tf again."""
    proc = demo.start("launch", LAUNCH, output="demo.out")
    try:
        demo.wait_for_output("spawned 'my_robot' into world 'robot'", 90, "demo.out")
        listed = demo.run("ps")
        table = listed.stdout
        for name in ("gz", "parameter_bridge", "robot_state_publisher", "driver"):
            assert re.search(rf"^  {name}-\d+ +\d+ .* running ", table, re.M), \
                table + listed.stderr
        label = re.search(r"^  (robot_state_publisher-\d+) +(\d+) ", table, re.M)
        result = demo.run("restart", "robot_state_publisher")
        assert result.returncode == 0 and f"restarting {label.group(1)}" in result.stdout
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            row = re.search(rf"^  {label.group(1)} +(\d+) .* running +1 ", demo.run("ps").stdout,
                            re.M)
            if row:
                break
            time.sleep(0.2)
        assert row and row.group(1) != label.group(2)
        assert first_line_with(demo, ["topic", "echo", "/tf"], "child_frame_id: left_wheel")
    finally:
        proc.send_signal(signal.SIGINT)
        code = proc.wait(60)
    assert code == 130
