"""The small tools launch files start: joint_state_publisher (and its _gui, with no desktop),
as ROS 2's, on real processes."""

from __future__ import annotations

import re
import signal

URDF = """<robot name="arm"><link name="base"/><link name="a"/><link name="b"/><link name="c"/>
<link name="d"/><link name="e"/>
<joint name="shoulder" type="revolute"><parent link="base"/><child link="a"/>
<axis xyz="0 0 1"/><limit lower="0.5" upper="1.5" effort="1" velocity="1"/></joint>
<joint name="wheel" type="continuous"><parent link="a"/><child link="b"/></joint>
<joint name="slide" type="prismatic"><parent link="b"/><child link="c"/>
<limit lower="-0.2" upper="0.2" effort="1" velocity="1"/></joint>
<joint name="finger" type="revolute"><parent link="c"/><child link="d"/>
<limit lower="-1" upper="1" effort="1" velocity="1"/><mimic joint="shoulder" multiplier="2"
offset="0.1"/></joint>
<joint name="bolt" type="fixed"><parent link="d"/><child link="e"/></joint>
</robot>"""


def positions(text: str) -> dict[str, float]:
    names = re.findall(r"^name:\n((?:- .*\n)+)", text, re.M)[0]
    values = re.findall(r"^position:\n((?:- .*\n)+)", text, re.M)[0]
    return dict(zip([n[2:] for n in names.splitlines()],
                    [float(v[2:]) for v in values.splitlines()], strict=True))


def test_joint_state_publisher_publishes_the_moving_joints_at_their_zeros(ws):
    ws.own_bus()
    publisher = ws.start("run", "joint_state_publisher", "joint_state_publisher", "--ros-args",
                         "-p", f"robot_description:={URDF}", "-p", "zeros.wheel:=0.25",
                         "-p", "rate:=20.0", output="jsp.txt")
    try:
        heard = ws.run("topic", "echo", "/joint_states", "sensor_msgs/msg/JointState",
                       "--once", "--timeout", "30")
        assert heard.returncode == 0, heard.stderr
        # 0 is outside the shoulder's limits: the middle; the mimic follows its master
        assert positions(heard.stdout) == {"shoulder": 1.0, "wheel": 0.25, "slide": 0.0,
                                           "finger": 2.1}, heard.stdout
    finally:
        publisher.send_signal(signal.SIGINT)
        assert publisher.wait(20) in (0, 130)


def test_joint_state_publisher_refuses_a_rate_of_zero_by_name(ws):
    ws.own_bus()
    done = ws.run("run", "joint_state_publisher", "joint_state_publisher", "--ros-args",
                  "-p", "rate:=0", timeout=60)
    assert done.returncode == 1, done.stderr
    assert "error: /joint_state_publisher: parameter 'rate': expected a number ≥ 0.001, got " \
        "0.0" in done.stderr, done.stderr
    assert "Traceback" not in done.stderr


def test_joint_state_publisher_gui_needs_no_desktop_and_says_how_to_move_joints(ws):
    ws.own_bus()
    description = ws.start("topic", "pub", "--latched",
                           "/robot_description", "std_msgs/msg/String", f"{{data: '{URDF}'}}",
                           output="description.txt")
    gui = ws.start("run", "joint_state_publisher_gui", "joint_state_publisher_gui",
                   "--ros-args", "-p", "source_list:=[/moved]", output="gui.txt")
    try:
        said = ws.wait_for_output("no desktop here for its sliders", 30, "gui.txt")
        assert "source_list" in said and "Traceback" not in said
        moved = ws.start("topic", "pub", "-r", "10", "/moved", "sensor_msgs/msg/JointState",
                         "{name: [slide], position: [0.15]}", output="moved.txt")
        try:
            for _ in range(20):
                heard = ws.run("topic", "echo", "/joint_states", "sensor_msgs/msg/JointState",
                               "--once", "--timeout", "30")
                if positions(heard.stdout).get("slide") == 0.15:
                    break
            assert positions(heard.stdout)["slide"] == 0.15, heard.stdout
        finally:
            moved.send_signal(signal.SIGINT)
            moved.wait(20)
    finally:
        for proc in (gui, description):
            proc.send_signal(signal.SIGINT)
            proc.wait(20)


def rate_of(ws, topic: str) -> str:
    """What `launcher topic hz` says of the topic over four seconds."""
    import time

    hz = ws.start("topic", "hz", topic, output=f"hz{topic.replace('/', '_')}.txt")
    time.sleep(4)
    hz.send_signal(signal.SIGINT)
    hz.wait(20)
    return ws.output(f"hz{topic.replace('/', '_')}.txt")


def test_topic_tools_relay_throttle_drop_and_mux(ws):
    ws.own_bus()
    source = ws.start("topic", "pub", "-r", "20", "/chatter", "std_msgs/msg/String",
                      "{data: hello}", output="source.txt")
    other = ws.start("topic", "pub", "-r", "20", "/other", "std_msgs/msg/String",
                     "{data: other}", output="other.txt")
    tools = [ws.start("run", "topic_tools", "relay", "/chatter", "/relayed", output="relay.txt"),
             ws.start("run", "topic_tools", "throttle", "messages", "/chatter", "2",
                      output="throttle.txt"),
             ws.start("run", "topic_tools", "drop", "/chatter", "1", "2", output="drop.txt"),
             ws.start("run", "topic_tools", "mux", "/muxed", "/chatter", "/other",
                      output="mux.txt")]
    try:
        relayed = ws.run("topic", "echo", "/relayed", "std_msgs/msg/String", "--once",
                         "--timeout", "30")
        assert "data: hello" in relayed.stdout, relayed
        hz = rate_of(ws, "/chatter_throttle")
        rates = [float(r) for r in re.findall(r"average rate: ([\d.]+)", hz)]
        assert rates and 1.0 < rates[-1] < 3.0, hz  # 2 a second of 20
        dropped = rate_of(ws, "/chatter_drop")
        rates = [float(r) for r in re.findall(r"average rate: ([\d.]+)", dropped)]
        assert rates and 6.0 < rates[-1] < 14.0, dropped  # half of 20
        assert "data: hello" in ws.run("topic", "echo", "/muxed", "std_msgs/msg/String",
                                       "--once", "--timeout", "30").stdout
        chosen = ws.run("service", "call", "/mux/select",
                        "topic_tools_interfaces/srv/MuxSelect", "{topic: /other}")
        assert "prev_topic: /chatter" in chosen.stdout and "success: true" in chosen.stdout
        heard = ""
        for _ in range(5):
            heard = ws.run("topic", "echo", "/muxed", "std_msgs/msg/String", "--once",
                           "--timeout", "30").stdout
            if "data: other" in heard:
                break
        assert "data: other" in heard, heard
        bad = ws.run("run", "topic_tools", "drop", "/chatter", "3", "2")
        assert bad.returncode != 0 and "X must be at least 0 and below Y" in bad.stderr
    finally:
        for proc in (*tools, source, other):
            proc.send_signal(signal.SIGINT)
            proc.wait(20)


def test_teleop_twist_keyboard_stamped_with_its_frame_id(ws):
    """`stamped:=true` publishes TwistStamped, with the `frame_id` parameter's frame."""
    import os
    import subprocess
    import time

    from tests.support.processes import launcher_argv

    ws.own_bus()
    master, slave = os.openpty()
    teleop = subprocess.Popen([*launcher_argv(), "run", "teleop_twist_keyboard",
                               "teleop_twist_keyboard", "--ros-args", "-p", "stamped:=true",
                               "-p", "frame_id:=base_link"], stdin=slave, stdout=slave,
                              stderr=slave, cwd=ws.root, env=ws.env)
    listener = None
    try:
        screen = b""
        deadline = time.monotonic() + 30
        while b"currently:" not in screen and time.monotonic() < deadline:
            screen += os.read(master, 4096)
        listener = ws.start("topic", "echo", "/cmd_vel", "geometry_msgs/msg/TwistStamped",
                            output="stamped.txt")
        said = ""
        for _ in range(20):  # a key each time until the listener (matched when it is) hears
            os.write(master, b"l")
            deadline = time.monotonic() + 1.0
            while "z: -1.0" not in said and time.monotonic() < deadline:
                time.sleep(0.05)
                said = ws.output("stamped.txt")
            if "z: -1.0" in said:
                break
        assert "z: -1.0" in said and "frame_id: base_link" in said, said
        os.write(master, b"\x03")
        assert teleop.wait(20) == 0
    finally:
        if teleop.poll() is None:
            teleop.kill()
            teleop.wait()
        if listener is not None:
            listener.send_signal(signal.SIGINT)
            listener.wait(20)
        os.close(master)
        os.close(slave)


def test_teleop_twist_keyboard_drives_from_keys_and_gives_the_terminal_back(ws):
    """In a pseudo-terminal, as a user's: keys become Twists on cmd_vel, q steps the speeds
    up 10%, Ctrl-C ends it with the terminal's settings as they were."""
    import os
    import select
    import subprocess
    import termios
    import time

    from tests.support.processes import launcher_argv

    ws.own_bus()
    master, slave = os.openpty()
    before = termios.tcgetattr(slave)
    teleop = subprocess.Popen([*launcher_argv(), "run", "teleop_twist_keyboard",
                               "teleop_twist_keyboard"], stdin=slave, stdout=slave,
                              stderr=slave, cwd=ws.root, env=ws.env)
    try:
        screen, speeds = b"", b"currently:\tspeed 0.5\tturn 1.0"
        deadline = time.monotonic() + 30
        while speeds not in screen and time.monotonic() < deadline:  # (a line may come in parts)
            if select.select([master], [], [], 0.5)[0]:
                screen += os.read(master, 4096)
        assert b"Moving around:" in screen and speeds in screen
        listener = ws.start("topic", "echo", "/cmd_vel", "geometry_msgs/msg/Twist",
                            output="cmd_vel.txt")
        time.sleep(1.5)
        os.write(master, b"i")
        said = ws.wait_for_output("x: 0.5", 20, "cmd_vel.txt")
        os.write(master, b"q")
        time.sleep(0.3)
        os.write(master, b"j")
        said = ws.wait_for_output("z: 1.1", 20, "cmd_vel.txt")
        assert "x: 0.5" in said
        os.write(master, b"\x03")
        assert teleop.wait(20) == 0
        assert termios.tcgetattr(slave) == before  # raw mode undone
        listener.send_signal(signal.SIGINT)
        listener.wait(20)
    finally:
        if teleop.poll() is None:
            teleop.kill()
            teleop.wait()
        os.close(master)
        os.close(slave)
    no_terminal = ws.run("run", "teleop_twist_keyboard", "teleop_twist_keyboard",
                         stdin=subprocess.DEVNULL)
    assert no_terminal.returncode == 1 and "Traceback" not in no_terminal.stderr
    assert "its stdin is not one: run it in a terminal of its own" in no_terminal.stderr


def test_launcher_graph_and_plot_draw_the_graph_and_fields_over_time(ws):
    """(graphviz's dot and matplotlib come with the set-up)"""
    import time

    ws.own_bus()
    talker = ws.start("topic", "pub", "-r", "20", "/level", "std_msgs/msg/Float64",
                      "{data: 2.5}", output="talker.txt")
    listener = ws.start("topic", "echo", "/level", "std_msgs/msg/Float64", output="heard.txt")
    try:
        ws.wait_for_output("data: 2.5", 30, "heard.txt")
        drawn = ws.run("graph", "--all", "-o", "graph.gv")
        assert drawn.returncode == 0, drawn.stderr
        text = (ws.root / "graph.gv").read_text()
        assert 'shape=box' in text and '"t:/level"' in text and "_launcher" in text, text
        assert ws.run("graph", "-o", "tools.gv").returncode == 0
        assert "_launcher" not in (ws.root / "tools.gv").read_text()  # (as rqt_graph hides
        # ros2cli's nodes by default, launcher's own tools are left out without --all)
        assert ws.run("graph", "-o", "graph.png").returncode == 0
        assert (ws.root / "graph.png").read_bytes().startswith(b"\x89PNG")
        plotted = ws.run("plot", "/level/data", "-o", "level.png", "--duration", "2",
                         timeout=60)
        assert plotted.returncode == 0, plotted.stderr
        assert re.search(r"wrote level.png \(/level/data: \d+\)", plotted.stdout), plotted
        assert (ws.root / "level.png").read_bytes().startswith(b"\x89PNG")
        recorder = ws.start("bag", "record", "/level", "-o", "levels", output="bag.txt")
        time.sleep(2.5)
        recorder.send_signal(signal.SIGINT)
        recorder.wait(30)
        recorded = ws.run("plot", "/level/data", "--bag", "levels", "-o", "recorded.svg",
                          timeout=60)
        assert recorded.returncode == 0, recorded.stderr
        assert (ws.root / "recorded.svg").read_text().lstrip().startswith("<?xml")
        wrong = ws.run("plot", "/level/dta", "-o", "x.png", "--duration", "1", timeout=60)
        assert wrong.returncode == 1 and "no 'dta' there" in wrong.stderr, wrong.stderr
        unknown = ws.run("plot", "/lvl/data", "-o", "x.png", "--duration", "1", timeout=60)
        assert unknown.returncode == 2 and "no topic for the field '/lvl/data'" in \
            unknown.stderr, unknown.stderr
    finally:
        for proc in (listener, talker):
            proc.send_signal(signal.SIGINT)
            proc.wait(20)
