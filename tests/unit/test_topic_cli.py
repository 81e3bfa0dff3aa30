"""The ros2 CLI habits of `launcher topic`: hz's figures, and messages printed as rclpy prints them."""

import argparse

import pytest

from launcher.cli import positive_count
from launcher.cli.topic.hz import rate_lines


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


def test_messages_print_as_rclpy_prints_them():
    from launcher.bus.messages import build, ros_repr

    assert ros_repr(build("std_msgs/msg/String", {"data": "hi"})) == \
        "std_msgs.msg.String(data='hi')"
    assert ros_repr(build("std_msgs/msg/Empty", {})) == "std_msgs.msg.Empty()"
    assert ros_repr(build("std_msgs/msg/Float64MultiArray", {"data": [1.0, 2.0]})) == \
        ("std_msgs.msg.Float64MultiArray(layout=std_msgs.msg.MultiArrayLayout(dim=[], "
         "data_offset=0), data=array('d', [1.0, 2.0]))")


def test_filter_expressions_read_a_message_and_nothing_else():
    from launcher.description.safe_expression import (
        ExpressionError,
        check_expression,
        evaluate,
        fields_of,
    )

    m = fields_of({"linear": {"x": 0.75}, "data": "hi", "items": [{"v": 2}]})
    assert evaluate("m.linear.x > 0.5 and m.data.upper() == 'HI'", {"m": m}) is True
    assert evaluate("m.items[0].v * 2", {"m": m}) == 4
    for bad in ("m.__class__", "m.linear.y", "m.data.format()", "open('f')"):
        with pytest.raises(ExpressionError):
            evaluate(bad, {"m": m})
    with pytest.raises(ExpressionError, match="unknown name 'os'"):
        check_expression("os.system('x')", ("m",))
    check_expression("m.data == 'x'", ("m",))


def test_bandwidth_lines_as_ros2_prints_them():
    from launcher.cli.topic.bw import bandwidth_lines

    samples = [(0.0, 100), (0.5, 300), (1.0, 200)]
    first, second = bandwidth_lines(samples, 2.0).split("\n")
    assert first == "300 B/s from 3 messages"
    assert second == "\tMessage size mean: 200 B min: 100 B max: 300 B"
    assert bandwidth_lines([(0.0, 5000), (1.0, 5000)], 1.0).startswith("10.00 KB/s")
    assert bandwidth_lines([], 1.0) == "no new messages"


def test_echo_data_of_nested_messages_and_arrays():
    from launcher.bus.messages import build, echo_data

    message = build("tf2_msgs/msg/TFMessage", {"transforms": [
        {"child_frame_id": "left_wheel", "transform": {"translation": {"x": 1.5}}}]})
    data = echo_data(message, "tf2_msgs/msg/TFMessage")
    assert data["transforms"][0]["child_frame_id"] == "left_wheel"
    assert data["transforms"][0]["transform"]["translation"]["x"] == 1.5
    short = echo_data(message, "tf2_msgs/msg/TFMessage", no_arr=True)
    assert short["transforms"] == "<sequence type: geometry_msgs/msg/TransformStamped, length: 1>"
    odometry = echo_data(build("nav_msgs/msg/Odometry", {}), "nav_msgs/msg/Odometry",
                         no_arr=True)
    assert odometry["pose"]["covariance"] == "<array type: double[36]>"
    cut = echo_data(build("std_msgs/msg/Float64MultiArray", {"data": [1.0, 2.0, 3.0]}),
                    "std_msgs/msg/Float64MultiArray", limit=2)
    assert cut["data"] == [1.0, 2.0, "..."]


def test_qos_options_start_from_a_profile_and_override_it():
    from launcher.bus.qos import KEEP_ALL_DEPTH, QoS
    from launcher.cli import qos_options

    parser = argparse.ArgumentParser()
    qos_options.add(parser, default="best_available")
    chosen = qos_options.chosen
    assert chosen(parser.parse_args([])) == QoS(depth=10, reliable=True, transient_local=True)
    assert chosen(parser.parse_args(["--qos-profile", "sensor_data"])) == \
        QoS(depth=5, reliable=False)
    assert chosen(parser.parse_args(["--qos-profile", "sensor_data", "--qos-reliability",
                                     "reliable", "--qos-depth", "3"])) == QoS(depth=3)
    assert chosen(parser.parse_args(["--qos-history", "keep_all", "--qos-depth", "3"])).depth \
        == KEEP_ALL_DEPTH  # depth is keep_last's alone, as in ROS 2
    assert not chosen(parser.parse_args(["--qos-durability", "volatile"])).transient_local
    with pytest.raises(SystemExit):
        parser.parse_args(["--qos-reliability", "sometimes"])


def test_a_topic_only_subscribed_to_is_not_its_own_suggestion(monkeypatch):
    from launcher.bus import graph
    from launcher.cli.topic import lookup
    from launcher.errors import LaunchError

    clock = graph.TopicInfo("/clock")
    clock.subscribers.append(object())
    chatter = graph.TopicInfo("/chatter")
    chatter.publishers.append(object())
    monkeypatch.setattr(graph, "topics", lambda session, space: {"/clock": clock,
                                                                 "/chatter": chatter})
    monkeypatch.setattr(lookup.time, "monotonic", iter(range(0, 100, 10)).__next__)
    with pytest.raises(LaunchError) as caught:
        lookup.type_of(None, "/clock", None)
    assert "nobody publishes '/clock' (it has 1 subscriber(s))" in str(caught.value)
    with pytest.raises(LaunchError) as caught:
        lookup.type_of(None, "/chattr", None)
    assert "did you mean '/chatter'" in str(caught.value)
