"""The bus's pure parts: names, --ros-args, params files, keys, messages and types, and the
action server over a faked node."""

from __future__ import annotations

import subprocess
import sys
from types import SimpleNamespace

import numpy as np
import pytest

from launcher.bus import keys, names, ros_args
from launcher.bus.messages import MessageError, build, to_data
from launcher.bus.qos import QoS
from launcher.bus.types import UnknownType, registry
from launcher.errors import LaunchError
from tests.support.environment import REPO


@pytest.mark.parametrize("name, expected", [
    ("chatter", "/ns/chatter"), ("/abs", "/abs"), ("~", "/ns/node"),
    ("~/private", "/ns/node/private"), ("a/b", "/ns/a/b"),
])
def test_expand(name, expected):
    assert names.expand(name, "node", "/ns") == expected


@pytest.mark.parametrize("name, rule", [
    ("", "it is empty"), ("a//b", "empty part"), ("1abc", "starts with a digit"),
    ("a-b", "other than letters"), ("x/", "ends with '/'"), ("~x", "'~' must be alone"),
])
def test_invalid_names_say_which_rule(name, rule):
    with pytest.raises(names.InvalidName, match=rule):
        names.expand(name, "node", "/ns")


def test_node_and_namespace_rules():
    with pytest.raises(names.InvalidName, match="invalid node name 'my-node'"):
        names.check_node_name("my-node")
    assert names.check_namespace("robot1/") == "/robot1"


def test_remap():
    rules = [("cmd_vel", "/r1/cmd"), ("~/x", "y")]
    assert names.remap("/ns/cmd_vel", rules, "n", "/ns") == "/r1/cmd"
    assert names.remap("/ns/n/x", rules, "n", "/ns") == "/ns/y"
    assert names.remap("/other", rules, "n", "/ns") == "/other"


def test_ros_args_as_the_node_action_writes_them(tmp_path):
    params = tmp_path / "p.yaml"
    params.write_text("/**:\n  ros__parameters:\n    rate: 5\n    limits: {max: 1.5}\n"
                      "/r1/driver:\n  ros__parameters:\n    only_me: true\n"
                      "other:\n  ros__parameters:\n    not_me: 1\n")
    parsed = ros_args.parse(["--speed", "3", "--ros-args", "--log-level", "debug", "-r",
                             "__node:=driver", "-r", "__ns:=/r1", "--params-file", str(params),
                             "-p", "gain:=0.5", "-p", "name:=bob", "-r", "odom:=odometry"])
    assert parsed.user_args == ["--speed", "3"]
    assert (parsed.node_name, parsed.namespace, parsed.log_level) == ("driver", "/r1", "DEBUG")
    assert parsed.remaps == [("odom", "odometry")]
    assert parsed.parameters == {"gain": 0.5, "name": "bob"}
    loaded = ros_args.load_params_file(str(params), "driver", "/r1")
    assert loaded == {"rate": 5, "limits.max": 1.5, "only_me": True}
    # -p and params files in command-line order, later ones winning (as rcl applies them);
    # a value of several lines (a robot description) is text with its lines
    urdf = "<robot name='r'>\n  <link name='a'/>\n</robot>\n"
    ordered = ros_args.parse(["--ros-args", "-p", "rate:=1", "--params-file", str(params),
                              "-p", f"robot_description:={urdf}", "-r", "__node:=driver",
                              "-r", "__ns:=/r1"])
    values = ros_args.node_parameters(ordered, "driver", "/r1")
    assert values["rate"] == 5 and values["robot_description"] == urdf


def test_bad_ros_args_and_params_file(tmp_path):
    with pytest.raises(LaunchError, match="'-p gain' : expected NAME:=VALUE".replace(" :", ":")):
        ros_args.parse(["--ros-args", "-p", "gain"])
    bad = tmp_path / "bad.yaml"
    bad.write_text("a: [1,\n")
    with pytest.raises(LaunchError) as info:
        ros_args.load_params_file(str(bad), "n", "")
    assert str(info.value).startswith(f"{bad}:2:1: params file is not valid YAML")


def test_keys_follow_rmw_zenoh():
    h = registry().type_hash("geometry_msgs/msg/Twist")
    key = keys.topic_key(0, "/r1/cmd_vel", "geometry_msgs/msg/Twist", h)
    assert key == f"0/r1/cmd_vel/geometry_msgs::msg::dds_::Twist_/{h}"
    assert keys.split_topic_key(key) == ("/r1/cmd_vel", "geometry_msgs/msg/Twist", h)
    entity = keys.Entity("zid", 1, 2, keys.PUBLISHER, "/r1", "driver", "/r1/cmd_vel",
                         "geometry_msgs/msg/Twist", h, QoS().key())
    token = keys.liveliness_key(0, entity)
    assert token == (f"@ros2_lv/0/zid/1/2/MP/%/%r1/driver/%r1%cmd_vel/"
                     f"geometry_msgs::msg::dds_::Twist_/{h}/::,10:,:,:,,")
    assert keys.parse_liveliness(token) == entity
    data = keys.attachment(7, 123, b"g" * 16)
    assert len(data) == 33 and keys.parse_attachment(data) == (7, 123, b"g" * 16)


def test_type_hash_matches_the_published_one():
    # From rosbags' own Jazzy typestore, as ROS 2 Jazzy publishes it
    assert registry().type_hash("std_msgs/msg/String") == (
        "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18")


def test_messages_round_trip_and_errors():
    types = registry()
    message = build("sensor_msgs/msg/JointState", {"name": ["l", "r"], "position": [1.0, 2.0],
                                                   "header": {"frame_id": "base"}})
    back = types.deserialize(types.serialize(message, "sensor_msgs/msg/JointState"),
                             "sensor_msgs/msg/JointState")
    assert isinstance(back.position, np.ndarray)
    assert to_data(back)["position"] == [1.0, 2.0] and back.header.frame_id == "base"
    with pytest.raises(MessageError, match=r"linear\.x: expected float64, got 'fast'"):
        build("geometry_msgs/msg/Twist", {"linear": {"x": "fast"}})
    with pytest.raises(MessageError, match="no field 'angualr' \\(did you mean 'angular'"):
        build("geometry_msgs/msg/Twist", {"angualr": {}})
    with pytest.raises(MessageError, match="300 is out of range for uint8"):
        build("std_msgs/msg/UInt8", {"data": 300})
    with pytest.raises(UnknownType, match="unknown message type 'geometry_msgs/msg/Twits' "
                                          "\\(did you mean 'geometry_msgs/msg/Twist'"):
        registry().ensure("geometry_msgs/Twits")


def test_service_hash_matches_ros2():
    """std_srvs/srv/Trigger as ROS 2 Jazzy publishes it (char in the event hashed as uint8)."""
    assert registry().service_hash("std_srvs/srv/Trigger") == (
        "RIHS01_eeff2cd6fa5ad9d27cdf4dec64818317839b62f212a91e6b5304b634b2062c5f")
    assert registry().service("std_srvs/srv/SetBool") == ("std_srvs/srv/SetBool_Request",
                                                          "std_srvs/srv/SetBool_Response")


def test_the_parameter_services_known_hashes_are_those_of_their_srv_files():
    """A node offers them under these hashes before reading their definitions."""
    from launcher.bus import parameters

    assert {name: registry().service_hash(name) for name in parameters.HASHES} == \
        parameters.HASHES


def test_package_interfaces(tmp_path, monkeypatch):
    pkg = tmp_path / "ws" / "my_interfaces"
    (pkg / "msg").mkdir(parents=True)
    (pkg / "srv").mkdir()
    (pkg / "package.xml").write_text("<package format='3'><name>my_interfaces</name></package>")
    (pkg / "msg" / "Beacon.msg").write_text("string name\nfloat64[3] position\n")
    (pkg / "srv" / "Spawn.srv").write_text("string name\nfloat64 x\n---\nbool ok\n")
    (pkg / "srv" / "Broken.srv").write_text("string name\n")
    monkeypatch.setenv("LAUNCHER_PACKAGE_PATH", str(tmp_path / "ws"))
    monkeypatch.setenv("LAUNCHER_CACHE_DIR", str(tmp_path / "cache"))
    from launcher.bus.types import TypeRegistry

    types = TypeRegistry()
    beacon = build("my_interfaces/msg/Beacon", {"name": "b", "position": [1, 2, 3]})
    back = types.deserialize(types.serialize(beacon, "my_interfaces/msg/Beacon"),
                             "my_interfaces/msg/Beacon")
    assert back.name == "b" and list(back.position) == [1.0, 2.0, 3.0]
    assert types.service("my_interfaces/srv/Spawn")[0] == "my_interfaces/srv/Spawn_Request"
    assert types.service_hash("my_interfaces/srv/Spawn").startswith("RIHS01_")
    with pytest.raises(LaunchError, match="Broken.srv: a .srv file needs exactly one '---'"):
        types.service("my_interfaces/srv/Broken")


@pytest.mark.parametrize("qos, text", [
    (QoS(), "::,10:,:,:,,"),  # rmw_zenoh's default profile, depth 10
    (QoS(depth=1, transient_local=True), ":1:,1:,:,:,,"),  # latched
    (QoS(depth=5, reliable=False), "2::,5:,:,:,,"),  # sensor data
])
def test_liveliness_qos_has_rmw_zenohs_six_parts_and_reads_back(qos, text):
    assert qos.key() == text and len(text.split(":")) == 6
    assert QoS.from_key(text) == qos


def test_the_older_three_part_qos_is_still_read_and_junk_is_not():
    assert QoS.from_key("1:2:1,10") == QoS()
    assert QoS.from_key("2:1:1,3") == QoS(depth=3, reliable=False, transient_local=True)
    for junk in ("", "1:2", "1:2:1", "9:2:1,10", "1:2:1,x", "::,10:,:,:"):
        assert QoS.from_key(junk) is None, junk


SIGNAL_DURING_WAIT = """
import signal, time
from launcher.bus.host import Host
from launcher.bus.logging import Logger

def slow_handler(*_):  # outlasts what is left of the wait
    end = time.monotonic() + 0.05
    while time.monotonic() < end:
        pass

signal.signal(signal.SIGALRM, slow_handler)
host = Host(None, "", "waiter", Logger("waiter"))
for _ in range(10):
    signal.setitimer(signal.ITIMER_REAL, 0.005)
    assert host.next_work(0.02) is None
host.enqueue(print, "every wait ended")
callback, args = host.next_work(None)
callback(*args)
"""


def test_a_signal_handler_longer_than_the_executors_wait_does_not_make_it_wait_forever():
    # The sim's loop waits for work in slices of a millisecond; a Ctrl-C handled inside one
    # must not turn it into a wait for ever (the sim then ignored SIGINT and SIGTERM).
    done = subprocess.run([sys.executable, "-c", SIGNAL_DURING_WAIT], capture_output=True,
                          text=True, timeout=120, cwd=REPO)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "every wait ended\n"


def test_node_api_message_classes_are_shaped_as_rosbags_makes_them_without_rosbags():
    import subprocess
    import sys

    code = """
import sys
from rosbags.typesys import get_typestore, Stores
from launcher.bus.types import registry
ours = registry().message_class('geometry_msgs/msg/Vector3')
theirs = get_typestore(Stores.ROS2_JAZZY).types['geometry_msgs/msg/Vector3']
a, b = ours(1.0, 2.0, 3.0), theirs(1.0, 2.0, 3.0)
assert repr(a) == repr(b), (repr(a), repr(b))
assert ours(x=1.0, y=2.0, z=3.0) == a and a != ours(1.0, 2.0, 4.0)
assert ours.__msgtype__ == theirs.__msgtype__ == 'geometry_msgs/msg/Vector3'
for bad, text in ((lambda: ours(1.0), "missing 2 required positional arguments: 'y' and 'z'"),
                  (lambda: ours(1.0, 2.0, 3.0, w=1), "unexpected keyword argument 'w'"),
                  (lambda: ours(1.0, 2.0, 3.0, 4.0), "positional arguments"),
                  (lambda: ours(1.0, x=2.0, y=1, z=1), "multiple values for argument 'x'")):
    try:
        bad()
    except TypeError as exc:
        assert text in str(exc), exc
        assert str(exc).startswith('geometry_msgs__msg__Vector3.__init__()'), exc
    else:
        raise AssertionError(text)
assert registry().message_class('geometry_msgs/msg/Vector3') is ours  # made once
from launcher.bus import message_class
odd = message_class.make('p/msg/T', ['x);import os;os._exit(3)#', 'y'])  # names never run
assert getattr(odd(1, 2), 'x);import os;os._exit(3)#') == 1
print('ok')
"""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.stdout.strip() == "ok", done.stderr
    lean = ("import sys; from launcher.bus.types import registry; "
            "registry().message_class('geometry_msgs/msg/Twist'); "
            "print(sorted(m for m in sys.modules if m.startswith(('rosbags', 'numpy'))))")
    done = subprocess.run([sys.executable, "-c", lean], capture_output=True, text=True)
    assert done.stdout.strip() == "[]", done.stdout + done.stderr


def test_the_qos_vocabulary_names_profiles_and_policies_once():
    from launcher.bus.qos import KEEP_ALL_DEPTH, PROFILES, QoS, QoSPolicyError

    sensor = PROFILES["sensor_data"]
    assert sensor == QoS(depth=5, reliable=False)
    assert sensor.with_policies(reliability="RELIABLE", durability="transient_local") == \
        QoS(depth=5, reliable=True, transient_local=True)
    assert sensor.with_policies("system_default", 3, "system_default", None) == \
        QoS(depth=3, reliable=False)
    assert QoS().with_policies(history="keep_all", depth=2).depth == KEEP_ALL_DEPTH
    assert (sensor.reliability_name, PROFILES["best_available"].durability_name) == \
        ("BEST_EFFORT", "TRANSIENT_LOCAL")
    with pytest.raises(QoSPolicyError, match="durability is system_default, volatile, "
                                             "transient_local; got 'sticky'"):
        QoS().with_policies(durability="sticky")



class _Attachment:
    def __init__(self, data: bytes) -> None:
        self.data = data

    def to_bytes(self) -> bytes:
        return self.data


def test_a_lockstep_answer_has_landed_once_what_it_sent_here_has_come():
    from launcher.bus.lockstep import Ledger

    ledger = Ledger()
    gid = bytes(range(16))
    ledger.subscribe("0/cmd_vel/T")
    sent = [["0/cmd_vel/T", gid.hex(), 3], ["0/rosout/T", bytes(16).hex(), 9]]
    ledger.note(_Attachment(keys.attachment(2, 0, gid)))
    assert not ledger.landed(sent)  # the third cmd_vel is still on its way
    ledger.note(_Attachment(keys.attachment(3, 0, gid)))
    assert ledger.landed(sent)  # (rosout: not subscribed here, not waited for)


def test_a_later_sample_counts_for_an_earlier_one_dropped_on_the_way():
    from launcher.bus.lockstep import Ledger

    ledger = Ledger()
    gid = b"g" * 16
    ledger.subscribe("k")
    ledger.note(_Attachment(keys.attachment(5, 0, gid)))
    ledger.note(_Attachment(keys.attachment(4, 0, gid)))  # (late: the highest stays)
    assert ledger.landed([["k", gid.hex(), 5]])
    ledger.unsubscribe("k")
    assert ledger.landed([["k", gid.hex(), 99]])  # no longer subscribed: not waited for


class _Endpoint:
    """A bus service or publisher of a faked node: what the action server uses of them."""

    def __init__(self, callback=None) -> None:
        self.callback, self.sent, self.listened = callback, [], False

    def new_response(self):
        return SimpleNamespace()

    def publish_raw(self, payload) -> None:
        self.sent.append(payload)

    def publish(self, message) -> None:
        self.sent.append(message)

    def get_subscription_count(self) -> int:
        return int(self.listened)


class _Reply:
    def __init__(self, said: list) -> None:
        self.said = said

    def new_response(self):
        return SimpleNamespace()

    def send(self, response) -> None:
        self.said.append(("answered", response))


def _faked_node() -> SimpleNamespace:
    endpoints: dict[str, _Endpoint] = {}

    def make(type_name, name, callback=None, qos=None):
        endpoints[name.rpartition("/")[2]] = endpoint = _Endpoint(callback)
        return endpoint
    return SimpleNamespace(create_service=make, create_publisher=make, endpoints=endpoints,
                           message=lambda type_name, **fields: SimpleNamespace(**fields))


def test_the_action_server_answers_first_and_cancels_only_what_can_be_canceled():
    """The controllers' way (every goal executes at once, every cancel is taken): the goal's
    request is answered before its owner hears of it, a second cancel of a canceling goal is
    refused, and its result waits for the owner to end it."""
    from launcher.bus import actions
    from launcher.bus.action_server import ActionServer

    said: list = []
    node = _faked_node()
    server = ActionServer(node, "control_msgs/action/GripperCommand", "~/gripper_cmd",
                          lambda goal: goal == "close", lambda goal: said.append("accepted"),
                          lambda goal: said.append("canceling"),
                          lambda: SimpleNamespace(sec=1, nanosec=0))
    goal_id = SimpleNamespace(uuid=bytes([1] * 16))
    send, cancel = node.endpoints["send_goal"].callback, node.endpoints["cancel_goal"].callback
    send(SimpleNamespace(goal_id=SimpleNamespace(uuid=bytes([2] * 16)), goal="open"),
         _Reply(said))
    send(SimpleNamespace(goal_id=goal_id, goal="close"), _Reply(said))
    assert [s if isinstance(s, str) else s[1].accepted for s in said] == [False, True, "accepted"]
    assert actions.statuses(node.endpoints["status"].sent[-1]) == [(bytes([1] * 16),
                                                                    actions.EXECUTING)]
    every_goal = SimpleNamespace(goal_info=SimpleNamespace(
        goal_id=SimpleNamespace(uuid=bytes(16)), stamp=SimpleNamespace(sec=0, nanosec=0)))
    first = cancel(every_goal, SimpleNamespace())
    assert first.return_code == actions.ERROR_NONE and said[-1] == "canceling"
    assert [g.goal_id for g in first.goals_canceling] == [goal_id]
    assert cancel(every_goal, SimpleNamespace()).return_code == actions.ERROR_REJECTED
    waiting: list = []
    node.endpoints["get_result"].callback(SimpleNamespace(goal_id=goal_id), _Reply(waiting))
    assert waiting == []
    goal = server.goals.goals()[0].handle
    goal.feedback("unheard")
    assert node.endpoints["feedback"].sent == []
    goal.canceled("let go")
    assert [(r.status, r.result) for _, r in waiting] == [(actions.CANCELED, "let go")]
