"""Python launch files built from launcher.api."""

import pytest

from launcher.errors import ParseError
from launcher.frontend.loader import load_file
from tests.support.fake_service import run

LAUNCH_PY = '''
import os
from launcher.api import *


def generate_launch_description():
    child = os.path.join(os.path.dirname(__file__), "child.launch.yaml")
    return LaunchDescription([
        DeclareLaunchArgument("robot", default_value="r1", description="the robot"),
        SetLaunchConfiguration("double", PythonExpression(["'", LaunchConfiguration("robot"),
                                                           "' * 2"])),
        LogInfo(msg=["robot=", LaunchConfiguration("robot"), " double=",
                     LaunchConfiguration("double")]),
        IncludeLaunchDescription(PythonLaunchDescriptionSource([child]),
                                 launch_arguments={"name": "from_py"}.items()),
        GroupAction([LogInfo(msg="in group")], condition=IfCondition("true")),
        ExecuteProcess(cmd=["/bin/echo", PathJoinSubstitution(["a", LaunchConfiguration("robot")])],
                       output="screen", additional_env={"X": "1"}),
        OpaqueFunction(function=lambda context: [LogInfo(msg="opaque " +
                       LaunchConfiguration("robot").perform(context))]),
        ForLoop(2, function=lambda i: [LogInfo(msg=f"i={i}")]),
    ])
'''


def test_python_launch_file(tmp_path):
    (tmp_path / "child.launch.yaml").write_text(
        "launch:\n  - arg: {name: name}\n  - log: {message: 'child $(var name)'}\n")
    path = tmp_path / "main.launch.py"
    path.write_text(LAUNCH_PY)
    _, service = run(load_file(path), {"robot": "bb"})
    assert [m for _, m in service.logs] == [
        "robot=bb double=bbbb", "child from_py", "in group", "opaque bb", "i=0", "i=1"]
    (spec,) = service.specs
    assert spec.argv == ["/bin/echo", "a/bb"] and spec.env["X"] == "1"


def test_python_file_that_raises_is_trimmed_to_the_users_frames(tmp_path):
    path = tmp_path / "bad.launch.py"
    path.write_text("def helper():\n    return 1 / 0\n\n"
                    "def generate_launch_description():\n    return helper()\n")
    with pytest.raises(ParseError) as info:
        load_file(path)
    text = str(info.value)
    assert text.startswith(f"{path}:2: the launch file raised ZeroDivisionError")
    assert "line 5, in generate_launch_description" in text
    assert "python_loader" not in text


def test_python_file_without_generate_function(tmp_path):
    path = tmp_path / "empty.launch.py"
    path.write_text("x = 1\n")
    with pytest.raises(ParseError, match="must define generate_launch_description"):
        load_file(path)


def test_on_exit_takes_one_action_as_ros_2_does():
    from launcher.api import ExecuteProcess, LogInfo, Shutdown

    process = ExecuteProcess(cmd=["true"], on_exit=Shutdown(reason="bye"),
                             on_start=LogInfo(msg="up"))
    (shutdown,) = process.on_exit  # was silently dropped when not given as a list
    (log,) = process.on_start
    assert isinstance(shutdown, type(Shutdown())) and list(process.sub_actions()) == [log,
                                                                                      shutdown]


def test_loading_a_python_launch_file_leaves_no_bytecode_beside_it(tmp_path, monkeypatch):
    """ROS 2's launch leaves __pycache__ in the package's launch folder; launcher does not."""
    monkeypatch.setattr("sys.dont_write_bytecode", False)  # as a user's Python has it
    (tmp_path / "child.launch.yaml").write_text(
        "launch:\n  - arg: {name: name}\n  - log: {message: 'child $(var name)'}\n")
    path = tmp_path / "main.launch.py"
    path.write_text(LAUNCH_PY)
    run(load_file(path), {"robot": "bb"})
    assert not (tmp_path / "__pycache__").exists()
    import sys

    assert sys.dont_write_bytecode is False  # put back


def test_get_launch_arguments_finds_the_declared_arguments_inside_groups_too():
    from launcher.api import DeclareLaunchArgument, GroupAction, LaunchDescription, LogInfo

    description = LaunchDescription([DeclareLaunchArgument("a"), GroupAction(
        [DeclareLaunchArgument("b"), LogInfo(msg="x")])])
    assert [argument.name for argument in description.get_launch_arguments()] == ["a", "b"]
