"""`launcher topic hz`'s figures, as `ros2 topic hz` prints them (launcher/cli/topic_command.py)."""

import argparse

import pytest

from launcher.cli import positive_count
from launcher.cli.topic_command import rate_lines


def test_the_rate_over_the_kept_messages_with_the_shortest_and_longest_gap():
    stamps = [0.0, 0.1, 0.2, 0.35, 0.45]  # gaps 0.1, 0.1, 0.15, 0.1
    first, second = rate_lines(stamps).split("\n")
    assert first == "average rate: 8.889"
    assert second.startswith("\tmin: 0.100s max: 0.150s std dev: 0.02165s")
    assert second.endswith("window: 5")  # messages, as ROS 2 counts its window


@pytest.mark.parametrize("text", ["0", "-3", "2.5", "ten"])
def test_a_window_is_a_whole_number_of_messages(text):
    with pytest.raises(argparse.ArgumentTypeError):
        positive_count(text)
