"""Machines: where each process of a launch runs, from roslaunch's `<machine>` (its rules read
from ros_comm's roslaunch: xmlloader._machine_tag, _recurse_load, _include_tag; config.add_machine,
assign_machines, _select_machine) and from launcher's extension of ROS 2 files, in XML, YAML and
Python. The processes are made, not started: a fake service records their specs."""

from __future__ import annotations

import getpass
import socket
from pathlib import Path

import pytest

from launcher.errors import LaunchError, ParseError
from launcher.frontend.loader import load_file
from launcher.runtime.context import LaunchContext
from launcher.runtime.machine import Machine, RemoteStart
from tests.support.fake_service import FakeService, visit
from tests.support.packages import index_for, make_tree, manifest

ROBOT2 = Machine("robot2", "10.0.0.2", "pi", 2222, "/home/pi/env.sh", 5.0)
NO_OPT_IN = "is launcher's extension, which ROS 2's launch lacks: say so once with"


@pytest.fixture
def index(tmp_path):
    """A workspace with the package `demo` (talker, listener) on this host."""
    ws = make_tree(tmp_path / "ws", {
        "demo/package.xml": manifest("demo"), "demo/lib/demo/talker": "#!/bin/sh\n",
        "demo/lib/demo/listener": "#!/bin/sh\n"},
        executable=("demo/lib/demo/talker", "demo/lib/demo/listener"))
    return index_for(ws, tmp=tmp_path)


def launched(tmp_path: Path, index, name: str, text: str, **files: str) -> list:
    """The specs of the processes the launch file would start, once its files are read."""
    for other, body in files.items():
        (tmp_path / other).write_text(body)
    path = tmp_path / name
    path.write_text(text)
    service = FakeService()
    context = LaunchContext({"PATH": "/usr/bin:/bin", "ROS_HOME": str(tmp_path / "ros_home")},
                            {}, service=service, load_description=load_file, packages=index,
                            log_dir=tmp_path / "log")
    service.context = context
    visit([load_file(path)], context)
    for check in context.loaded_checks:  # (what the launch service runs once they are read)
        check()
    return service.specs


def machines(specs: list) -> dict[str, str | None]:
    return {spec.label: spec.machine and spec.machine.name for spec in specs}


ROS1_ROBOT2 = ('<machine name="robot2" address="10.0.0.2" user="pi" ssh-port="2222" '
               'env-loader="/home/pi/env.sh" timeout="5"/>')


# --- the record -----------------------------------------------------------------------------
@pytest.mark.parametrize("address", ["localhost", "127.0.0.1", "127.0.1.1", "::1",
                                     socket.gethostname()])
def test_a_machine_named_as_this_host_is_local(address):
    assert Machine("here", address).local
    assert Machine("here", address, user=getpass.getuser()).local


@pytest.mark.parametrize("machine", [Machine("far", "10.0.0.2"), Machine("far", "robot2"),
                                     Machine("other", "localhost", user="someone-else")],
                         ids=["address", "name", "user"])
def test_another_host_or_user_is_not_local(machine):
    assert not machine.local


def test_machines_with_one_key_are_one_host_whatever_their_names():
    assert Machine("a", "10.0.0.2", "pi").key() == Machine("b", "10.0.0.2", "pi").key()
    assert Machine("a", "10.0.0.2", "pi").key() != Machine("a", "10.0.0.2", "root").key()


# --- roslaunch's <machine> ------------------------------------------------------------------
def test_a_ros1_node_on_another_host_is_neither_found_nor_prepared_here(tmp_path):
    """Its package need not exist here, and its folder (ROS_HOME) is not made here."""
    empty = index_for(make_tree(tmp_path / "empty", {"x/package.xml": manifest("x")}),
                      tmp=tmp_path)
    (spec,) = launched(tmp_path, empty, "a.launch", f'<launch>{ROS1_ROBOT2}\n'
                       '<node name="talker" pkg="demo" type="talker" machine="robot2" '
                       'args="-v"><param name="rate" value="2"/></node></launch>')
    assert spec.machine == ROBOT2 and spec.machine.where.endswith("a.launch:1:9")
    assert spec.remote == RemoteStart("demo", "talker", 0, (str(tmp_path / "log" / "params" /
                                                               "talker.yaml"),))
    assert spec.argv[:2] == ["-v", "__name:=talker"]
    assert spec.cwd is None and not (tmp_path / "ros_home").exists()


def test_a_ros1_node_on_this_host_runs_here_as_before(tmp_path, index):
    (spec,) = launched(tmp_path, index, "a.launch", '<launch><machine name="here" '
                       'address="localhost"/><node name="t" pkg="demo" type="talker" '
                       'machine="here"/></launch>')
    assert spec.machine == Machine("here", "localhost") and spec.remote is None
    assert spec.argv[0].endswith("demo/lib/demo/talker")
    assert spec.cwd == str(tmp_path / "ros_home")


def test_the_default_machine_takes_later_nodes_across_groups_and_includes(tmp_path, index):
    """xmlloader._recurse_load returns the default from a group and _include_tag from an
    included file: it holds for what follows in document order, whatever the scope."""
    specs = launched(
        tmp_path, index, "a.launch",
        '<launch>\n<node name="before" pkg="demo" type="talker"/>\n'
        '<include file="$(dirname)/m.launch"/>\n'
        '<node name="after_include" pkg="demo" type="talker"/>\n'
        '<group ns="g"><machine name="robot3" address="10.0.0.3" default="true"/></group>\n'
        '<node name="after_group" pkg="demo" type="talker"/>\n'
        '<node name="own" pkg="demo" type="talker" machine="robot2"/>\n</launch>',
        **{"m.launch": "<launch>" + ROS1_ROBOT2.replace("/>", ' default="true"/>') +
           "</launch>"})
    assert machines(specs) == {"before-1": None, "after_include-2": "robot2",
                               "after_group-3": "robot3", "own-4": "robot2"}


@pytest.mark.parametrize("default", ["false", "never", "FALSE"])
def test_a_machine_not_default_takes_no_node(tmp_path, index, default):
    specs = launched(tmp_path, index, "a.launch", f'<launch><machine name="m" address="10.0.0.3" '
                     f'default="{default}"/><node name="n" pkg="demo" type="talker"/></launch>')
    assert machines(specs) == {"n-1": None}


def test_a_machine_under_a_false_condition_is_not_declared(tmp_path, index):
    with pytest.raises(LaunchError, match="unknown machine 'm'"):
        launched(tmp_path, index, "a.launch", '<launch><machine if="false" name="m" '
                 'address="10.0.0.3" default="true"/><node name="n" pkg="demo" type="talker" '
                 'machine="m"/></launch>')


def test_a_test_tag_takes_its_machine(tmp_path, index):
    from launcher.description.actions.rostest import RosTest

    path = tmp_path / "a.test"
    path.write_text(f'<launch>{ROS1_ROBOT2}<test test-name="t" pkg="demo" type="talker" '
                    'machine="robot2"/></launch>')
    (rostest,) = load_file(path).actions[1:]
    assert isinstance(rostest, RosTest) and rostest.actions[0].machine is not None


@pytest.mark.parametrize("address, remote", [("10.0.0.3", True), ("localhost", False)])
def test_a_machine_declared_after_its_node_places_it_once_the_files_are_read(
        tmp_path, index, address, remote):
    """config.assign_machines runs once the launch is loaded: a node may name a machine
    declared after it, on another host (not found here) or on this one (found here)."""
    (spec,) = launched(tmp_path, index, "a.launch", '<launch><node name="n" pkg="demo" '
                       f'type="talker" machine="m"/><machine name="m" address="{address}"/>'
                       '</launch>')
    assert spec.machine.name == "m" and (spec.remote is not None) is remote
    assert spec.argv[0].endswith("demo/lib/demo/talker") is not remote


def test_an_unknown_machine_is_said_at_its_node_with_did_you_mean(tmp_path, index):
    with pytest.raises(LaunchError, match=r"unknown machine 'robot3' \(did you mean "
                                          r"'robot2'\?\): declare it") as caught:
        launched(tmp_path, index, "a.launch", f'<launch>{ROS1_ROBOT2}\n<node name="n" '
                 'pkg="demo" type="talker" machine="robot3"/></launch>')
    assert caught.value.location.line == 2


def test_a_name_declared_twice_with_other_settings_names_both(tmp_path, index):
    with pytest.raises(LaunchError, match=r"machine 'robot2' is declared twice with different "
                                          r"settings: address 10.0.0.3 here, 10.0.0.2 at "
                                          r".*b.launch:1:9; user unset here, pi at") as caught:
        launched(tmp_path, index, "a.launch", '<launch><include file="$(dirname)/b.launch"/>\n'
                 '<machine name="robot2" address="10.0.0.3" ssh-port="2222" '
                 'env-loader="/home/pi/env.sh" timeout="5"/></launch>',
                 **{"b.launch": f"<launch>{ROS1_ROBOT2}</launch>"})
    assert caught.value.location.line == 2


def test_a_name_declared_twice_alike_is_one_machine(tmp_path, index):
    specs = launched(tmp_path, index, "a.launch", f'<launch>{ROS1_ROBOT2}{ROS1_ROBOT2}<node '
                     'name="n" pkg="demo" type="talker" machine="robot2"/></launch>')
    assert specs[0].machine == ROBOT2


def test_a_password_is_refused_at_it_naming_key_based_login(tmp_path, index):
    with pytest.raises(ParseError, match=r"launcher logs in with OpenSSH, which takes no "
                                         r"password from a program; use key-based login "
                                         r"\(ssh-keygen; ssh-copy-id pi@10.0.0.2\) and an "
                                         r"ssh-agent") as caught:
        launched(tmp_path, index, "a.launch", '<launch>\n<machine name="m" address="10.0.0.2" '
                 'user="pi" password="secret"/></launch>')
    assert caught.value.location.line == 2


@pytest.mark.parametrize("attribute, expected", [
    ('default="yes"', "<machine default='yes'>: expected true, false or never"),
    ('timeout="0"', "<machine timeout='0'>: expected a number of seconds > 0"),
    ('timeout="soon"', "<machine timeout='soon'>: expected a number of seconds > 0"),
    ('ssh-port="70000"', "<machine ssh-port='70000'>: expected a port number, 1 to 65535"),
    ('ssh-port="ssh"', "<machine ssh-port='ssh'>: expected a port number, 1 to 65535"),
    ('ros-root="/opt/ros"', "<machine>: ros-* attributes are not supported since ROS Fuerte"),
], ids=["default", "timeout-zero", "timeout-word", "port-range", "port-word", "ros-root"])
def test_a_bad_machine_value_is_said_at_it(tmp_path, index, attribute, expected):
    with pytest.raises(ParseError, match=expected.replace("(", r"\(").replace("*", r"\*")) \
            as caught:
        launched(tmp_path, index, "a.launch", f'<launch>\n<machine name="m" address="h" '
                 f'{attribute}/></launch>')
    assert caught.value.location.line == 2


def test_a_bad_value_made_by_a_substitution_is_said_when_declared(tmp_path, index):
    with pytest.raises(LaunchError, match="timeout: expected a number > 0, got -1") as caught:
        launched(tmp_path, index, "a.launch", '<launch><arg name="t" default="-1"/>\n'
                 '<machine name="m" address="h" timeout="$(arg t)"/></launch>')
    assert caught.value.location.line == 2


def test_env_in_a_machine_is_refused(tmp_path, index):
    with pytest.raises(ParseError, match="<machine> takes no <env>"):
        launched(tmp_path, index, "a.launch", '<launch><machine name="m" address="localhost">'
                 '<env name="X" value="1"/></machine></launch>')


# --- launcher's extension of ROS 2 files: the same launch in every syntax --------------------
ROS1 = f"""<launch>
  {ROS1_ROBOT2}
  <machine name="robot3" address="10.0.0.3"/>
  <node name="talker" pkg="demo" type="talker" machine="robot2"/>
  <node name="listener" pkg="demo" type="listener" machine="robot3"/>
  <node name="local" pkg="demo" type="listener"/>
</launch>"""
XML = """<launch extensions="launcher">
  <machine name="robot2" address="10.0.0.2" user="pi" ssh-port="2222"
           env-loader="/home/pi/env.sh" timeout="5"/>
  <machine name="robot3" address="10.0.0.3"/>
  <node pkg="demo" exec="talker" name="talker" machine="robot2"/>
  <group machine="robot3"><node pkg="demo" exec="listener" name="listener"/></group>
  <node pkg="demo" exec="listener" name="local"/>
</launch>"""
YAML = """extensions: [launcher]
launch:
  - machine: {name: robot2, address: 10.0.0.2, user: pi, ssh-port: 2222,
              env-loader: /home/pi/env.sh, timeout: 5}
  - machine: {name: robot3, address: 10.0.0.3}
  - node: {pkg: demo, exec: talker, name: talker, machine: robot2}
  - group: {machine: robot3, children: [{node: {pkg: demo, exec: listener, name: listener}}]}
  - node: {pkg: demo, exec: listener, name: local}
"""
PYTHON = """from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node
from launcher.api.extensions import Machine, PushMachine

def generate_launch_description():
    return LaunchDescription([
        Machine(name="robot2", address="10.0.0.2", user="pi", ssh_port=2222,
                env_loader="/home/pi/env.sh", timeout=5),
        Machine(name="robot3", address="10.0.0.3"),
        GroupAction([PushMachine("robot2"), Node(package="demo", executable="talker",
                                                 name="talker")]),
        GroupAction([PushMachine("robot3"), Node(package="demo", executable="listener",
                                                 name="listener")]),
        Node(package="demo", executable="listener", name="local"),
    ])
"""


@pytest.mark.parametrize("name, text", [("a.launch", ROS1), ("a.launch.xml", XML),
                                        ("a.launch.yaml", YAML), ("a.launch.py", PYTHON)],
                         ids=["ros1", "xml", "yaml", "python"])
def test_every_syntax_puts_each_node_on_the_same_machine(tmp_path, index, name, text):
    specs = launched(tmp_path, index, name, text)
    assert [spec.machine for spec in specs] == [ROBOT2, Machine("robot3", "10.0.0.3"), None]
    assert [spec.remote and spec.remote.executable for spec in specs] == \
        ["talker", "listener", None]


def test_a_remote_executable_runs_its_command_there_as_is(tmp_path, index):
    (spec,) = launched(tmp_path, index, "a.launch.xml", '<launch extensions="launcher">'
                       '<machine name="r" address="10.0.0.2"/><executable cmd="no-such-tool -v" '
                       'machine="r"/></launch>')
    assert spec.argv == ["no-such-tool", "-v"] and spec.remote == RemoteStart(None, None)


def test_a_process_names_its_own_machine_over_its_groups(tmp_path, index):
    specs = launched(tmp_path, index, "a.launch.yaml", """extensions: [launcher]
launch:
  - machine: {name: a, address: 10.0.0.2}
  - machine: {name: b, address: 10.0.0.3}
  - group: {machine: a, children: [{node: {pkg: demo, exec: talker, machine: b}},
                                   {node: {pkg: demo, exec: listener}}]}
  - node: {pkg: demo, exec: talker}
""")
    assert machines(specs) == {"talker-1": "b", "listener-2": "a", "talker-3": None}


def test_a_ros2_file_declares_a_machine_before_naming_it(tmp_path, index):
    with pytest.raises(LaunchError, match=r"unknown machine 'robot2'") as caught:
        launched(tmp_path, index, "a.launch.xml", '<launch extensions="launcher">\n<node '
                 'pkg="demo" exec="talker" machine="robot2"/>\n<machine name="robot2" '
                 'address="10.0.0.2"/></launch>')
    assert caught.value.location.line == 2


@pytest.mark.parametrize("name, text, what, line", [
    ("a.launch.xml", '<launch>\n<machine name="r" address="h"/>\n<node pkg="demo" '
     'exec="talker"/></launch>', "<machine>", 2),
    ("a.launch.xml", '<launch>\n<node pkg="demo" exec="talker" machine="r"/></launch>',
     "node's machine=", 2),
    ("a.launch.xml", '<launch>\n<group machine="r"/></launch>', "group's machine=", 2),
    ("a.launch.yaml", "launch:\n  - executable: {cmd: ls, machine: r}\n",
     "executable's machine=", 2),
    ("a.launch.yaml", "launch:\n  - machine: {name: r, address: h}\n", "<machine>", 2),
], ids=["xml-machine", "xml-node", "xml-group", "yaml-executable", "yaml-machine"])
def test_an_extension_without_the_opt_in_is_said_at_it(tmp_path, index, name, text, what, line):
    with pytest.raises(ParseError, match=NO_OPT_IN) as caught:
        launched(tmp_path, index, name, text)
    assert str(caught.value.message).startswith(what)
    assert caught.value.location.line == line
    opt_in = "extensions: [launcher]" if name.endswith("yaml") else 'extensions="launcher"'
    assert opt_in in caught.value.message


def test_only_launcher_s_extensions_can_be_opted_in(tmp_path, index):
    with pytest.raises(ParseError, match=r"extensions: expected launcher \(launcher's own\), "
                                         r"got 'launchr' \(did you mean 'launcher'\?\)"):
        launched(tmp_path, index, "a.launch.xml", '<launch extensions="launchr"/>')


def test_a_ros2_machine_checks_its_values_at_them(tmp_path, index):
    with pytest.raises(ParseError, match=r"machine.timeout: expected a number > 0, got 0") \
            as caught:
        launched(tmp_path, index, "a.launch.yaml", "extensions: [launcher]\nlaunch:\n"
                 "  - machine: {name: r, address: h,\n      timeout: 0}\n")
    assert (caught.value.location.line, caught.value.location.column) == (4, 16)


@pytest.mark.parametrize("name, text", [
    ("a.launch.yaml", "extensions: [launcher]\nlaunch:\n"
                      "  - machine: {name: r, address: h, user: pi, password: x}\n"),
    ("a.launch.py", "from launch import LaunchDescription\n"
                    "from launcher.api.extensions import Machine\n"
                    "def generate_launch_description():\n"
                    "    return LaunchDescription([Machine(name='r', address='h', user='pi',\n"
                    "                                      password='x')])\n"),
], ids=["yaml", "python"])
def test_a_ros2_password_is_refused(tmp_path, index, name, text):
    with pytest.raises(LaunchError, match=r"ssh-copy-id pi@h\) and an ssh-agent"):
        launched(tmp_path, index, name, text)


def test_the_fidelity_page_lists_every_extension_the_registry_marks():
    from launcher.description.registry import EXTENSION, Registry
    from launcher.schema import declared_fields, frontend_name
    from tests.fidelity.extensions import EXTENSIONS

    registry = Registry()
    registry.load_all()
    tags = {tag for tag, cls in registry.actions.items() if getattr(cls, "extension", False)}
    attributes = {(tag, frontend_name(f, s)) for tag, cls in registry.actions.items()
                  for f, s in declared_fields(cls) if f.metadata.get(EXTENSION)}
    assert tags == {tag for e in EXTENSIONS for tag in e.tags}
    assert attributes == {pair for e in EXTENSIONS for pair in e.attributes}


@pytest.mark.parametrize("make", [
    lambda api: api.Node(package="demo", executable="talker", machine="robot2"),
    lambda api: api.GroupAction([], machine="robot2"),
])
def test_launch_ros_own_classes_take_no_machine_as_ros_2s_do(make):
    import launcher.api as api

    with pytest.raises(TypeError, match="unexpected keyword argument 'machine'.*PushMachine"):
        make(api)
