"""gazebo_ros's spawn_model flags, as launcher's create takes them."""

import pytest

from launcher.errors import UsageError
from launcher.nodes.spawn_model import create_argv


def test_the_flags_map_onto_create():
    flags, unpause, joints = create_argv(
        ["-urdf", "-param", "robot_description", "-model", "bot", "-x", "6", "-Y", "1.57",
         "-J", "left_wheel_joint", "0.5", "-unpause", "-robot_namespace", "/r1"])
    assert flags == ["-param", "robot_description", "-name", "bot", "-x", "6", "-Y", "1.57"]
    assert unpause and joints == [("left_wheel_joint", 0.5)]
    assert create_argv(["-sdf", "-database", "ground_plane", "-model", "g"])[0] == \
        ["-file", "model://ground_plane", "-name", "g"]


@pytest.mark.parametrize("argv, message", [
    (["-param", "robot_description"], "-model NAME is needed"),
    (["-model", "bot", "-modle", "x"], "unknown option '-modle' (did you mean '-model'"),
    (["-model", "bot", "-x"], "-x needs a value"),
    (["-model", "bot", "-J", "joint"], "-J needs a joint name and a position"),
    (["-model", "bot", "-J", "joint", "half"], "-J joint half: the position must be a number"),
])
def test_bad_flags_say_what_is_wrong(argv, message):
    with pytest.raises(UsageError, match=None) as info:
        create_argv(argv)
    assert message in str(info.value)
