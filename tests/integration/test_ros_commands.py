"""The commands users type, by their own names: `ros2 …` and ROS 1's `rostopic`, `rosservice`,
`rosnode`, `rosmsg`, `rossrv`, `rospack`, `roscore`, `roslaunch`, `rosrun`, `roscd`, `rosls`,
from a bash that sourced launcher's setup file; a real tool earlier on PATH (a stand-in the
test writes) always wins. Real processes on a real router; a rospy node of the test's."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.support.environment import REPO

SETUP = REPO / "hooks" / "setup.bash"

NODE = '''#!/usr/bin/env python3
import rospy
from std_msgs.msg import String
from std_srvs.srv import SetBool, SetBoolResponse


def answer(request):
    return SetBoolResponse(success=request.data, message="set" if request.data else "unset")


rospy.init_node("talker")
rospy.Service("switch", SetBool, answer)
pub = rospy.Publisher("chatter", String, queue_size=10)
rate = rospy.Rate(10)
while not rospy.is_shutdown():
    pub.publish(String(data="hello"))
    rate.sleep()
'''
MANIFEST = """<?xml version="1.0"?>
<package format="2"><name>{name}</name><version>0.0.1</version>
<description>t</description><maintainer email="a@b.c">a</maintainer>
<license>MIT</license></package>
"""


def shell(ws, script: str, timeout: float = 60, path: str | None = None
          ) -> subprocess.CompletedProcess:
    """`script` in a bash that sourced hooks/setup.bash."""
    env = dict(ws.env, PATH=path or ws.env["PATH"])
    return subprocess.run(["bash", "-c", f". {SETUP} && {script}"], cwd=ws.root, env=env,
                          capture_output=True, text=True, timeout=timeout)


@pytest.fixture
def graph(ws):
    """A rospy talker with a service, in a package of the test's workspace."""
    ws.own_bus()
    ws.write("src/chat/package.xml", MANIFEST.format(name="chat"))
    ws.write("src/chat/launch/chat.launch", '<launch><node pkg="chat" type="talker.py" '
                                            'name="talker" output="screen"/></launch>\n')
    ws.write("src/chat/scripts/talker.py", NODE).chmod(0o755)
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "src")
    proc = ws.start("launch", "chat", "chat.launch", output="talker.out")
    deadline = time.monotonic() + 60
    while "/chatter" not in ws.run("topic", "list").stdout:
        assert time.monotonic() < deadline, ws.output("talker.out")
        time.sleep(0.3)
    yield ws
    proc.send_signal(signal.SIGINT)
    proc.wait(30)


def test_a_real_tool_on_path_wins_and_launchers_come_last(ws):
    real = ws.root / "real-ros"
    real.mkdir()
    for name in ("ros2", "rostopic", "colcon"):
        (real / name).write_text(f"#!/bin/sh\necho REAL-{name} \"$@\"\n")
        (real / name).chmod(0o755)
    path = f"{real}{os.pathsep}{ws.env['PATH']}"
    done = shell(ws, "ros2 daemon status; rostopic list; colcon build; command -v roslaunch; "
                     "echo \"PATH=$PATH\"; launcher doctor", path=path, timeout=120)
    assert "REAL-ros2 daemon status" in done.stdout, done.stdout + done.stderr
    assert "REAL-rostopic list" in done.stdout and "REAL-colcon build" in done.stdout
    ours = REPO / "launcher" / "compat" / "bin"
    assert f"{ours}/roslaunch" in done.stdout
    folders = re.search(r"PATH=(.*)", done.stdout).group(1).split(os.pathsep)
    assert folders[-1] == str(ours) and folders.index(str(real)) < folders.index(str(ours))
    doctor = re.search(r"commands +(.*)", done.stdout).group(1)
    assert f"ros2 → {real}/ros2" in doctor and f"rostopic → {real}/rostopic" in doctor
    assert re.search(r"launcher's: [^;]*\broslaunch\b", doctor), doctor


def test_the_names_are_not_console_scripts_of_the_python_environment():
    scripts = Path(sys.executable).parent
    names = os.listdir(REPO / "launcher" / "compat" / "bin")
    assert {"ros2", "roslaunch", "rostopic", "roscore", "rosrun", "colcon"} <= set(names)
    assert not [n for n in names if (scripts / n).exists()]


def test_ros2_verbs_daemon_and_the_ones_launcher_lacks(ws):
    for verb, said in (("start", "The daemon has been started"),
                       ("stop", "The daemon has been stopped"),
                       ("status", "The daemon is running")):
        done = shell(ws, f"ros2 daemon {verb}")
        assert (done.returncode, done.stdout.strip()) == (0, said), done.stderr
    listing = shell(ws, "ros2 --help")
    assert "Commands:" in listing.stdout and "  topic " in listing.stdout
    wrong = shell(ws, "ros2 topc list")
    assert wrong.returncode == 2
    assert "'topc' is not a ros2 command (did you mean 'topic'?)" in wrong.stderr
    assert "action, bag, component" in wrong.stderr and "Traceback" not in wrong.stderr
    lacking = shell(ws, "ros2 component list")
    assert lacking.returncode == 1 and "ros2 component:" in lacking.stderr
    assert "not in launcher yet" in lacking.stderr and "node_container" in lacking.stderr
    doctor = shell(ws, "ros2 wtf --help")
    assert doctor.returncode == 0 and "usage: ros2 doctor" in doctor.stdout
    packages = shell(ws, "ros2 pkg prefix robot_state_publisher")
    assert packages.returncode == 0 and packages.stdout.strip(), packages.stderr


def test_topic_lists_take_the_fast_path_and_say_what_the_full_command_says(graph):
    """`ros2 topic list` and `rostopic list` are answered without the full command line
    (cli/quick.py); LAUNCHER_ROUTER naming the same router sends them the full way, which
    must print the same: ros2 hides hidden names, rostopic lists them."""
    hidden = graph.start("rostopic", "pub", "/_secret/state", "std_msgs/String", "x",
                         output="hidden.out")
    try:
        lists = "ros2 topic list; echo ===; rostopic list; echo ===; launcher topic list"
        deadline = time.monotonic() + 30
        while "/_secret/state" not in shell(graph, "rostopic list").stdout:
            assert time.monotonic() < deadline, graph.output("hidden.out")
            time.sleep(0.2)
        fast = shell(graph, lists)
        socket = Path(graph.env["LAUNCHER_RUN_DIR"]) / "domain-0.sock"
        full = shell(graph, f"export LAUNCHER_ROUTER=unixsock-stream/{socket}; {lists}")
        assert fast.returncode == full.returncode == 0, fast.stderr + full.stderr
        assert fast.stdout == full.stdout, (fast.stdout, full.stdout)
        ros2, ros1, ours = fast.stdout.split("===\n")
        assert "/chatter" in ros2.split() and "/_secret/state" not in ros2.split()
        assert {"/chatter", "/_secret/state"} <= set(ros1.split()) and ours == ros2
        imports = shell(graph, f"{sys.executable} -X importtime -P -c 'import sys; "
                               "from launcher.cli.entry import main; sys.exit(main())' "
                               "ros2 topic list")
        assert imports.returncode == 0 and "/chatter" in imports.stdout.split()
        assert " argparse\n" not in imports.stderr and "zenoh" in imports.stderr
    finally:
        hidden.send_signal(signal.SIGINT)
        hidden.wait(30)


def test_the_commands_run_launchers_interpreter_and_fall_back_to_launcher(ws):
    """compat/bin's scripts run the interpreter named on `launcher`'s first line, without
    the current folder on the module path (a zenoh.py there is not imported); where
    `launcher` is not a Python script, they run `launcher` itself."""
    (ws.root / "zenoh.py").write_text("raise SystemExit('the folder was on the module path')\n")
    done = shell(ws, "ros2 daemon status")
    assert (done.returncode, done.stdout.strip()) == (0, "The daemon is running"), done.stderr
    other = ws.root / "other"
    other.mkdir()
    (other / "launcher").write_text('#!/bin/sh\necho "STAND-IN $*"\n')
    (other / "launcher").chmod(0o755)
    ours = REPO / "launcher" / "compat" / "bin"
    done = subprocess.run([str(ours / "ros2"), "topic", "list"], capture_output=True,
                          text=True, env=dict(ws.env, PATH=f"{other}:/usr/bin:/bin"),
                          timeout=30)
    assert done.stdout == "STAND-IN ros2 topic list\n", done.stderr


def test_ros1_topic_service_and_node_tools_on_a_running_graph(graph):
    done = shell(graph, "rostopic list; echo ===; rostopic type /chatter; echo ===; "
                        "rostopic info /chatter; echo ===; rostopic echo -n 2 /chatter; "
                        "echo ===; ros2 topic list")
    assert done.returncode == 0, done.stderr
    listing, kind, info, echoed, ros2_listing = done.stdout.split("===\n")
    assert "/chatter" in listing.split() and "/chatter" in ros2_listing.split()
    assert kind.strip() == "std_msgs/String"
    assert info.startswith("Type: std_msgs/String\n\nPublishers: \n * /talker\n"), info
    assert echoed.count("data: hello\n---") == 2, echoed
    field = shell(graph, "rostopic echo -n 1 /chatter/data")
    assert field.stdout.startswith("hello\n---"), field.stdout + field.stderr
    services = shell(graph, "rosservice list; echo ===; rosservice type /switch; echo ===; "
                            "rosservice info /switch; echo ===; rosservice call /switch true; "
                            "echo ===; rosservice call /switch '{data: false}'")
    assert services.returncode == 0, services.stderr
    listing, kind, info, called, mapped = services.stdout.split("===\n")
    assert "/switch" in listing.split()
    assert kind.strip() == "std_srvs/SetBool"
    assert "Node: /talker\n" in info and "Args: data" in info
    assert called == "success: true\nmessage: set\n"
    assert mapped == "success: false\nmessage: unset\n"
    nodes = shell(graph, "rosnode list; echo ===; rosnode info /talker; echo ===; "
                         "rosnode ping -c 1 /talker")
    assert nodes.returncode == 0, nodes.stderr
    listing, info, ping = nodes.stdout.split("===\n")
    assert "/talker" in listing.split()
    assert "Node [/talker]" in info and " * /chatter [std_msgs/String]" in info
    assert " * /switch" in info
    assert "reply from /talker\ttime=" in ping
    # the launch set no parameter, yet the server holds roslaunch's own, as roscore's would
    params = shell(graph, "rosparam list; rosparam get /rosversion")
    assert {"/rosdistro", "/rosversion", "/run_id"} <= set(params.stdout.split()), params
    assert "1.16.0" in params.stdout
    unknown = shell(graph, "rosnode info /talkr")
    assert unknown.returncode == 1
    assert "Unknown node [/talkr] (did you mean '/talker'?)" in unknown.stderr


def test_rostopic_pub_latches_until_stopped_and_takes_fields_in_order(graph):
    pub = subprocess.Popen(["bash", "-c", f". {SETUP} && exec rostopic pub /note "
                                          "std_msgs/String 'a note'"],
                           cwd=graph.root, env=graph.env, stdout=subprocess.PIPE, text=True)
    try:
        assert pub.stdout.readline().startswith("publishing and latching message. Press "
                                                "ctrl-C to terminate")
        late = shell(graph, "rostopic echo -n 1 /note")  # latched: a late subscriber gets it
        assert late.stdout.startswith("data: a note\n---"), late.stdout + late.stderr
    finally:
        pub.send_signal(signal.SIGINT)
        assert pub.wait(20) == 0
    once = shell(graph, "rostopic pub -1 /other std_msgs/String '{data: x}'", timeout=60)
    assert once.returncode == 0
    assert "publishing and latching message for 3.0 seconds" in once.stdout
    bad = shell(graph, "rostopic pub -1 /other std_msgs/String '{data: [x'")
    assert bad.returncode == 2 and "is not valid YAML" in bad.stderr, bad.stderr


def test_ros1_package_and_type_tools(graph):
    done = shell(graph, "rospack find chat; echo ===; rospack list | grep '^chat '; "
                        "echo ===; rosmsg show geometry_msgs/Twist; echo ===; "
                        "rossrv show std_srvs/SetBool; echo ===; roscd chat/launch && pwd; "
                        "echo ===; rosls chat")
    assert done.returncode == 0, done.stderr
    found, listed, twist, setbool, here, files = done.stdout.split("===\n")
    assert found.strip() == str(graph.root / "src" / "chat")
    assert listed.strip() == f"chat {graph.root / 'src' / 'chat'}"
    assert twist.startswith("geometry_msgs/Vector3 linear\n  float64 x\n")
    assert setbool == "bool data\n---\nbool success\nstring message\n"
    assert here.strip() == str(graph.root / "src" / "chat" / "launch")
    assert set(files.split()) == {"launch", "package.xml", "scripts"}
    missing = shell(graph, "rospack find chatt")
    assert missing.returncode == 1
    assert "[rospack] Error: package 'chatt' not found" in missing.stderr


def test_roslaunch_and_rosrun_as_ros1_finds_files(graph):
    missing = shell(graph, "roslaunch chat nope.launch")
    assert missing.returncode == 1
    assert ("RLException: [nope.launch] is neither a launch file in package [chat] nor is "
            "[chat] a launch file name") in missing.stderr
    assert "chat.launch" in missing.stderr and "Traceback" not in missing.stderr
    path = shell(graph, "roslaunch no/such/file.launch")
    assert path.returncode == 1 and "[no/such/file.launch]" in path.stderr
    shown = shell(graph, "roslaunch --ros-args chat chat.launch")
    assert shown.returncode == 0, shown.stderr
    exe = shell(graph, "rosrun chat nope.py")
    assert exe.returncode == 1
    assert "[rosrun] Couldn't find executable named nope.py" in exe.stderr


def test_roscore_joins_the_graph_sets_roslaunchs_parameters_and_stops_on_ctrl_c(graph):
    core = subprocess.Popen(["bash", "-c", f". {SETUP} && exec roscore"], cwd=graph.root,
                            env=graph.env, stdout=subprocess.PIPE, text=True)
    try:
        lines = []
        while "started core service [/rosout]" not in "".join(lines):
            line = core.stdout.readline()
            assert line, "".join(lines)
            lines.append(line)
        assert "SUMMARY" in "".join(lines) and " * /rosdistro: noetic" in "".join(lines)
        values = shell(graph, "rosparam get /rosdistro; rosparam get /run_id")
        assert values.stdout.startswith("'noetic\n\n  '\n"), values.stdout
        assert re.search(r"[0-9a-f]{8}-[0-9a-f]{4}-", values.stdout)
    finally:
        core.send_signal(signal.SIGINT)
        assert core.wait(20) == 0


def test_rosbag_records_a_ros1_bag_that_rosbags_reads_and_plays_it_back(graph):
    from rosbags.rosbag1 import Reader
    from rosbags.typesys import Stores, get_typestore

    done = shell(graph, "rosbag record -O chat.bag /chatter --duration 2 && rosbag info "
                        "chat.bag", timeout=120)
    assert done.returncode == 0, done.stderr
    assert "[ INFO] Recording to 'chat.bag'." in done.stdout
    assert re.search(r"topics:\s+/chatter\s+\d+ msgs\s+: std_msgs/String", done.stdout)
    assert "std_msgs/String [992ce8a1687cec8c8bd883ec73ca41d1]" in done.stdout  # ROS 1's md5
    noetic = get_typestore(Stores.ROS1_NOETIC)  # an independent reader, ROS 1's types
    with Reader(graph.root / "chat.bag") as reader:
        texts = [noetic.deserialize_ros1(raw, "std_msgs/msg/String").data
                 for _c, _t, raw in reader.messages()]
    assert len(texts) >= 10 and set(texts) == {"hello"}
    converted = shell(graph, "launcher bag convert chat.bag chat2 && launcher bag info chat2")
    assert converted.returncode == 0 and "Topic: /chatter" in converted.stdout, converted.stderr
    note = subprocess.Popen(["bash", "-c", f". {SETUP} && exec rostopic pub -r 10 /note "
                                           "std_msgs/String 'from the bag'"],
                            cwd=graph.root, env=graph.env, stdout=subprocess.DEVNULL)
    try:
        recorded = shell(graph, "rosbag record -O note.bag /note --duration 2", timeout=120)
        assert "recorded" in recorded.stdout, recorded.stdout + recorded.stderr
    finally:
        note.send_signal(signal.SIGINT)
        note.wait(20)
    listener = subprocess.Popen(["bash", "-c", f". {SETUP} && exec rostopic echo -n 1 /note"],
                                cwd=graph.root, env=graph.env, stdout=subprocess.PIPE, text=True)
    try:
        time.sleep(1.0)
        played = shell(graph, "rosbag play note.bag", timeout=60)
        assert played.returncode == 0 and "Done." in played.stdout, played.stderr
        assert "data: from the bag" in listener.communicate(timeout=30)[0]
    finally:
        if listener.poll() is None:
            listener.send_signal(signal.SIGINT)
            listener.wait(20)


def test_rosbag_record_into_a_folder_that_is_not_writable(graph):
    """/proc/1 takes no new file from anyone, root included (who writes past permission bits)."""
    done = shell(graph, "rosbag record -O /proc/1/race.bag /chatter")
    assert done.returncode == 1
    assert "cannot write '/proc/1/race.bag': the folder '/proc/1' is not writable" in \
        done.stderr, done.stderr
    assert "Traceback" not in done.stderr
    missing = shell(graph, "rosbag record -O no/such/folder/race.bag /chatter")
    assert missing.returncode == 1 and "the folder 'no/such/folder' does not exist" in \
        missing.stderr


def test_rosnode_kill_ends_the_node_as_ros1s_does(graph):
    done = shell(graph, "rosnode kill /talker")
    assert (done.returncode, done.stdout) == (0, "killing /talker\nkilled\n"), done.stderr
    deadline = time.monotonic() + 20
    while "/talker" in shell(graph, "rosnode list").stdout.split():
        assert time.monotonic() < deadline, graph.output("talker.out")
        time.sleep(0.3)
    assert "ROSInterruptException" in graph.output("talker.out")  # rospy's shutdown, as ROS 1
    unknown = shell(graph, "rosnode kill /talker")
    assert unknown.returncode == 1 and "Unknown node [/talker]" in unknown.stderr


def test_rostopic_hz_and_catkin_tools_verbs(graph):
    hz = shell(graph, "timeout -s INT 3.5 rostopic hz /chatter; true")
    assert hz.stdout.startswith("subscribed to [/chatter]\n"), hz.stdout + hz.stderr
    assert "average rate: " in hz.stdout
    late = shell(graph, "timeout -s INT 1.5 rostopic echo /nobody; true")
    assert "WARNING: topic [/nobody] does not appear to be published yet" in late.stderr
    done = shell(graph, "catkin init && catkin build && test -f devel/setup.bash && "
                        "catkin clean && test ! -e devel")
    assert done.returncode == 0, done.stdout + done.stderr
    assert "Initialized new catkin workspace" in done.stdout and "- chat" in done.stdout
