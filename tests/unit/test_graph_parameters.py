"""The graph's parameter server's pieces: ROS 1 names as the server's parameter names, values
as a ROS 2 parameter holds them, and what a ROS 1 launch hands the server (its parameters by
full name, once, after its files have been read). The server and its clients over the bus are
in tests/integration/test_roslaunch_xml.py."""

from __future__ import annotations

import json
import os
import stat
from pathlib import Path

import pytest

from launcher.bus import graph_parameters as graph
from launcher.cli.rosparam.server import resolve
from launcher.errors import UsageError
from launcher.frontend.loader import load_file
from tests.support.fake_service import run


def test_ros1_names_are_dotted_parameter_names_and_back():
    assert graph.key("/robot1/robot_description") == "robot1.robot_description"
    assert graph.key("/") == "" and graph.key("rate") == "rate"
    assert graph.ros1_name("robot1.robot_description") == "/robot1/robot_description"


def test_values_are_kept_as_a_ros2_parameter_holds_them():
    assert graph.leaves("/gains", {"p": 1.5, "limits": {"max": 2}}) == \
        {"gains.p": 1.5, "gains.limits.max": 2}
    assert graph.leaves("/mixed", [1, 2.5]) == {"mixed": [1.0, 2.5]}  # one array type
    assert graph.leaves("/names", ("a", "b")) == {"names": ["a", "b"]}


def test_a_list_of_mixed_types_is_kept_for_its_clients_to_read_as_the_list():
    """ROS 1's server is XML-RPC, whose arrays take any types: [1, two, 3.0] stays a list."""
    (kept,) = graph.leaves("/odd", [1, "two", 3.0]).values()
    assert isinstance(kept, str)  # (a ROS 2 parameter cannot hold it as it is)
    assert graph._read(kept) == [1, "two", 3.0]


def test_rosparam_resolves_names_as_ros1_does(monkeypatch):
    monkeypatch.delenv("ROS_NAMESPACE", raising=False)
    assert resolve("rate") == "/rate" and resolve("/a/b") == "/a/b"
    monkeypatch.setenv("ROS_NAMESPACE", "/robot1")
    assert resolve("rate") == "/robot1/rate"
    with pytest.raises(UsageError, match="a private name"):
        resolve("~rate")


ROS1 = """<launch>
  <param name="robot_description" value="urdf"/>
  <rosparam command="load" ns="gains">{p: 1.5, i: 0}</rosparam>
  <group ns="fleet">
    <param name="rate" value="50"/>
    <param name="/absolute" value="yes"/>
    <rosparam>spare: 1</rosparam>
    <rosparam command="delete" param="spare"/>
  </group>
  <param name="typed/flag" value="True"/>
  <param name="typed/listed" value="[1, 2]"/>
  <param name="typed/under" value="1_000"/>
  <param name="typed/real" value="3."/>
  <param name="typed/exponent" value="1e3"/>
  <param name="~for_later_nodes" value="5"/>
  <param name="typed/spaced" value=" true "/>
  <param name="typed/spaced_text" value="  two words  " type="str"/>
  <param name="typed/file" textfile="$(dirname)/count.txt"/>
  <param name="typed/file_bool" textfile="$(dirname)/flag.txt"/>
  <param name="typed/output" command="printf 2.5"/>
  <param name="typed/output_text" command="printf 2.5" type="str"/>
  <include file="$(dirname)/inner.launch"/>
</launch>
"""


def test_a_ros1_launch_hands_every_parameter_to_the_server_once_at_the_end(tmp_path):
    (tmp_path / "top.launch").write_text(ROS1)
    (tmp_path / "inner.launch").write_text('<launch><param name="inner" value="7"/></launch>')
    (tmp_path / "count.txt").write_text("42\n")
    (tmp_path / "flag.txt").write_text("true\n")
    context, service = run(load_file(tmp_path / "top.launch"), environment={
        "PATH": "/usr/bin:/bin", "HOME": str(tmp_path)})
    loads = [s for s in service.specs if "launcher.nodes.load_parameters" in s.argv]
    assert len(loads) == 1 and service.specs[-1] is loads[0]  # after everything else
    path = loads[0].argv[-1]
    written = json.loads(Path(path).read_text())
    # roslaunch runs `rosparam delete` before it uploads: what the server held goes, what
    # the launch sets (spare, here) stays
    assert written["before"] == [["delete", "/fleet/spare"]]
    assert "/for_later_nodes" not in written["set"]  # a ~name is the later nodes' alone
    assert written["set"] == {
        "/robot_description": "urdf", "/gains/p": 1.5, "/gains/i": 0, "/fleet/rate": 50,
        "/fleet/spare": 1,
        "/absolute": "yes", "/inner": 7,
        # roslaunch's own typing of an untyped value (roslaunch/loader.py convert_value, on
        # Python 3 as Debian's roslaunch runs): float() with a dot, else int() but not with
        # an underscore (so 1_000 and 1e3 are text), then true/false, else text;
        # param_value strips value=
        # (not a file's text or a command's output) and types all three the same way
        "/typed/flag": True, "/typed/listed": "[1, 2]", "/typed/under": "1_000",
        "/typed/real": 3.0, "/typed/exponent": "1e3", "/typed/spaced": True,
        "/typed/spaced_text": "two words", "/typed/file": 42, "/typed/file_bool": "true\n",
        "/typed/output": 2.5, "/typed/output_text": "2.5"}
    assert stat.S_IMODE(os.stat(path).st_mode) == 0o600  # it may hold a robot description
    assert context.graph_parameters == {}


def test_a_ros2_launch_has_no_parameter_server(tmp_path):
    (tmp_path / "top.launch.xml").write_text(
        '<launch><set_parameter name="rate" value="5"/></launch>')
    _, service = run(load_file(tmp_path / "top.launch.xml"))
    assert service.specs == []
