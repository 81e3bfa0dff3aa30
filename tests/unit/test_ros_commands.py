"""`ros2`'s verbs onto launcher's commands, and ROS 1's rostopic word rules (`/topic/field`,
a message from YAML or its fields in order), as ros2cli and rostopic have them."""

from __future__ import annotations

import pytest

from launcher.bus.interfaces import ros1_spelling
from launcher.cli.ros1.rostopic.lookup import split_field
from launcher.cli.ros1.values import message_values
from launcher.cli.ros2_command import translate
from launcher.errors import LaunchError, UsageError


def test_ros2_verbs_are_launchers_commands_and_wtf_is_doctor():
    assert translate(["topic", "echo", "/x"]) == ["topic", "echo", "/x"]
    assert translate(["launch", "pkg", "f.launch.py", "a:=1"]) == \
        ["launch", "pkg", "f.launch.py", "a:=1"]
    assert translate(["wtf"]) == ["doctor"]
    assert translate(["pkg", "list"]) == ["pkg", "list", "--names"]  # names alone, as ros2
    # ros2cli's daemon and hidden-name options ask for what launcher's graph does anyway
    assert translate(["topic", "list", "--no-daemon", "--spin-time", "2", "-t"]) == \
        ["topic", "list", "-t"]
    assert translate(["doctor", "--report"]) == ["doctor"]
    assert translate(["--use-python-default-buffering", "node", "list"]) == ["node", "list"]


def test_ros2_daemon_prints_as_ros2_and_help_lists_the_verbs(capsys):
    assert translate(["daemon", "stop"]) is None
    assert capsys.readouterr().out == "The daemon has been stopped\n"
    assert translate([]) is None
    assert "  multicast  Various multicast related sub-commands" in capsys.readouterr().out


def test_ros2_unknown_and_missing_verbs():
    with pytest.raises(UsageError, match=r"'lanch' is not a ros2 command \(did you mean "
                                         r"'launch'\?\)"):
        translate(["lanch"])
    with pytest.raises(UsageError, match="'restart' is not a daemon command"):
        translate(["daemon", "restart"])
    with pytest.raises(LaunchError, match="ros2 multicast: launcher's graph never uses "
                                          "multicast"):
        translate(["multicast", "receive"])


def test_rostopic_echo_reads_a_field_path_after_the_topic():
    topics = {"/odom": 1, "/a/b": 1}
    assert split_field("/odom/pose/pose", topics) == ("/odom", "pose.pose")
    assert split_field("/a/b", topics) == ("/a/b", None)
    assert split_field("/a/b/c", topics) == ("/a/b", "c")
    assert split_field("/nothing/here", topics) == ("/nothing/here", None)


def test_rostopic_pub_values_from_yaml_or_the_fields_in_order():
    assert message_values("std_msgs/msg/String", ["hello"]) == {"data": "hello"}
    assert message_values("std_msgs/msg/String", ["{data: hi}"]) == {"data": "hi"}
    assert message_values("geometry_msgs/msg/Vector3", ["1", "2", "3"]) == \
        {"x": 1, "y": 2, "z": 3}
    assert message_values("std_msgs/msg/Empty", []) == {}
    with pytest.raises(UsageError, match="too many arguments"):
        message_values("std_msgs/msg/String", ["a", "b"])
    with pytest.raises(UsageError, match="is not valid YAML"):
        message_values("std_msgs/msg/String", ["{data: [x"])


def test_hidden_names_are_ros2s():
    from launcher.bus.names import hidden

    assert hidden("/fibonacci/_action/feedback") and hidden("/_private")
    assert not hidden("/cmd_vel") and not hidden("/robot_1/odom")


def test_ros1_spelling_of_type_names():
    assert ros1_spelling("std_msgs/msg/String") == "std_msgs/String"
    assert ros1_spelling("std_msgs/String") == "std_msgs/String"


def test_launchers_own_nodes_read_a_roslaunch_command_line_in_ros2s_layout():
    from launcher.packages.ros1_args import ros2_layout

    assert ros2_layout(["-urdf", "in:=/out", "__name:=spawner", "__ns:=/r1", "_rate:=5",
                        "__log:=/tmp/x.log"]) == \
        ["-urdf", "--ros-args", "-r", "in:=/out", "-r", "__node:=spawner", "-r",
         "__ns:=/r1", "-p", "rate:=5"]
    assert ros2_layout(["-x", "1"]) == ["-x", "1"]


def test_ros_args_read_roslaunchs_words_and_the_launchs_parameters(monkeypatch):
    import json

    from launcher.bus import ros_args
    from launcher.lineage import NODE_PARAMETERS

    monkeypatch.setattr(ros_args, "_inherited", None)
    monkeypatch.setenv(NODE_PARAMETERS, json.dumps(["-p", "gain:=2.5"]))
    parsed = ros_args.parse(["mine", "in:=/out", "__name:=driver", "__ns:=fleet",
                             "_rate:=5", "__log:=/tmp/x.log"])
    assert (parsed.node_name, parsed.namespace) == ("driver", "/fleet")
    assert parsed.remaps == [("in", "/out")] and parsed.user_args == ["mine"]
    assert parsed.parameters == {"rate": 5, "gain": 2.5}
    import os
    assert NODE_PARAMETERS not in os.environ  # taken: no child of the node inherits them
