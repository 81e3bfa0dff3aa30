"""ROS 2's node name and namespace rules (launcher/description/ros_names.py)."""

import pytest

from launcher.description.ros_names import check_namespace, check_node_name
from launcher.errors import ExecutionError


@pytest.mark.parametrize("name", ["talker", "_hidden", "robot_0", "a" * 255, "Node2"])
def test_valid_node_names(name):
    check_node_name(name)


@pytest.mark.parametrize("name, said", [
    ("bad-name", "it holds '-'"),
    ("2robots", "it starts with a digit"),
    ("", "it is empty"),
    ("robot/driver", "it holds '/'"),
    ("a" * 256, "longer than 255 characters"),
    ("café", "it holds 'é'"),
])
def test_invalid_node_names_say_the_rule(name, said):
    with pytest.raises(ExecutionError) as caught:
        check_node_name(name)
    assert f"node name '{name}' is not valid in ROS 2: " in caught.value.message
    assert said in caught.value.message
    assert "expected letters, digits and '_', not starting with a digit" in caught.value.message


def test_an_invalid_node_name_gets_a_did_you_mean():
    with pytest.raises(ExecutionError) as caught:
        check_node_name("bad-name")
    assert caught.value.message.endswith("(did you mean 'bad_name'?)")


@pytest.mark.parametrize("space", ["", "/", "/robot_0", "/a/b_c/d2", "relative/ns"])
def test_valid_namespaces(space):
    check_namespace(space)


@pytest.mark.parametrize("space, said", [
    ("/robot-0", "the part 'robot-0': it holds '-'"),
    ("/a//b", "an empty part"),
    ("/1st", "the part '1st': it starts with a digit"),
])
def test_invalid_namespaces_say_the_rule(space, said):
    with pytest.raises(ExecutionError) as caught:
        check_namespace(space)
    assert f"namespace '{space}' is not valid in ROS 2: {said}" in caught.value.message
