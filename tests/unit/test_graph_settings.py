"""The graph's settings without a router: domain ids, endpoints, the run folder, credentials,
peer sockets of dead processes, and the key spaces."""

from __future__ import annotations

import os
import stat

import pytest

from launcher.bus import credentials, discovery, keys
from launcher.errors import ParseError, UsageError


@pytest.mark.parametrize("text, expected", [("", 0), ("0", 0), (" 7 ", 7), ("232", 232)])
def test_domain_ids_as_ros2_allows(text, expected):
    assert discovery.domain_id({"ROS_DOMAIN_ID": text}) == expected


@pytest.mark.parametrize("text", ["233", "-1", "x", "1.5"])
def test_bad_domain_ids_say_the_range(text):
    with pytest.raises(UsageError, match="expected a whole number from 0 to 232"):
        discovery.domain_id({"ROS_DOMAIN_ID": text})


@pytest.mark.parametrize("endpoint", ["tcp/10.0.0.1:7447", "tcp/[::1]:7447",
                                      "tcp/robot.local:7447", "unixsock-stream//tmp/x.sock",
                                      "quic/10.0.0.1:7447"])
def test_endpoints_that_are_fine(endpoint):
    assert discovery.check_endpoint(endpoint, "LAUNCHER_ROUTER") == endpoint


@pytest.mark.parametrize("endpoint", ["tcp/10.0.0.1", "10.0.0.1:7447", "tcp/host:0",
                                      "tcp/host:70000", "http/host:80", "unixsock-stream/x"])
def test_malformed_endpoints_name_the_variable(endpoint):
    with pytest.raises(UsageError, match=f"LAUNCHER_ROUTER: '{endpoint}' is not an endpoint"):
        discovery.check_endpoint(endpoint, "LAUNCHER_ROUTER")


def test_several_explicit_endpoints_and_which_are_local():
    env = {"LAUNCHER_ROUTER": "tcp/a:1, unixsock-stream//run/x.sock"}
    found = discovery.explicit_endpoints(env)
    assert found == ["tcp/a:1", "unixsock-stream//run/x.sock"]
    assert [discovery.is_local(e) for e in found] == [False, True]


def test_the_run_folder_and_the_socket_path(tmp_path):
    assert discovery.run_dir({"LAUNCHER_RUN_DIR": str(tmp_path)}) == tmp_path
    runtime = tmp_path / "xdg"
    runtime.mkdir()
    assert discovery.run_dir({"XDG_RUNTIME_DIR": str(runtime)}) == runtime / "launcher"
    env = {"LAUNCHER_RUN_DIR": str(tmp_path), "ROS_DOMAIN_ID": "5"}
    assert discovery.socket_path(env) == tmp_path / "domain-5.sock"
    with pytest.raises(UsageError, match="too long a path"):
        discovery.socket_path({"LAUNCHER_RUN_DIR": "/tmp/" + "x" * 120})


def test_a_run_folder_of_someone_else_is_a_clear_error(tmp_path_factory):
    blocked = tmp_path_factory.mktemp("rf") / "file"  # (a short path: its sockets would fit)
    blocked.write_text("")
    with pytest.raises(discovery.NoRouter, match="cannot use the run folder"), \
            discovery.router({"LAUNCHER_RUN_DIR": str(blocked / "run")}):
        pass


def test_dead_peers_sockets_are_swept_and_live_ones_kept(tmp_path):
    dead = tmp_path / "peer-999999-aa.sock"
    dead_lock = tmp_path / "peer-999999-aa.sock.lock"
    alive = tmp_path / f"peer-{os.getpid()}-bb.sock"
    other = tmp_path / "domain-0.sock"
    for path in (dead, dead_lock, alive, other):
        path.write_text("")
    discovery.sweep_peer_sockets(tmp_path)
    assert not dead.exists() and not dead_lock.exists() and alive.exists() and other.exists()
    assert discovery.peer_endpoint({"LAUNCHER_RUN_DIR": str(tmp_path)}).startswith(
        f"unixsock-stream/{tmp_path}/peer-{os.getpid()}-")


def test_credentials_are_made_private_once_and_read_back(tmp_path, monkeypatch):
    monkeypatch.setenv("HOME", str(tmp_path))
    first = credentials.load({})
    again = credentials.load({})
    assert first == again and first.user == "launcher" and len(first.password) >= 32
    assert stat.S_IMODE(first.file.stat().st_mode) == 0o600
    assert stat.S_IMODE(first.file.parent.stat().st_mode) == 0o700


@pytest.mark.parametrize("text, where", [("launcher secret\n", ":1:1"),
                                         ("# a comment\n\nuser:\n", ":3:1"),
                                         ("", "")])
def test_malformed_credentials_name_their_line(text, where):
    with pytest.raises(ParseError) as caught:
        credentials.parse(text, "creds")
    assert str(caught.value).startswith(f"creds{where}: ")


def test_a_named_credentials_file_that_is_missing_is_not_made(tmp_path):
    missing = tmp_path / "nope"
    with pytest.raises(ParseError, match="cannot read the bus credentials"):
        credentials.load({"LAUNCHER_CREDENTIALS": str(missing)})
    assert not missing.exists()


def test_the_sims_side_has_keys_and_tokens_of_its_own():
    ros = keys.topic_key(0, "/clock", "rosgraph_msgs/msg/Clock", "RIHS01_x")
    sim = keys.topic_key(0, "/clock", "rosgraph_msgs/msg/Clock", "RIHS01_x", keys.SIM)
    assert ros == "0/clock/rosgraph_msgs::msg::dds_::Clock_/RIHS01_x"
    assert sim == "@sim/0/clock/rosgraph_msgs::msg::dds_::Clock_/RIHS01_x"
    assert keys.split_topic_key(sim) == keys.split_topic_key(ros)
    entity = keys.Entity("z", 1, 2, keys.PUBLISHER, "/ns", "n", "/a/b", "std_msgs/msg/String",
                         "RIHS01_x", keys.qos_key(True, True, 1))
    token = keys.liveliness_key(0, entity, keys.SIM)
    assert token.startswith("@sim_lv/0/z/1/2/MP/%/%ns/n/%a%b/")
    assert keys.parse_liveliness(token) == entity


def test_a_run_folder_too_long_for_the_nodes_sockets_is_said_before_anything_starts():
    """The graph's own socket would fit, a node's would not (its name is longer): said at
    once, not as the socket library's error when the node opens its session."""
    folder = "/tmp/" + "x" * 85  # 90 characters: domain-0.sock fits, peer-…-….sock does not
    assert len(f"{folder}/domain-0.sock") <= 107
    with pytest.raises(UsageError, match=r"too long a path for the graph's sockets \(its "
                                         r"nodes' need up to 117 characters"):
        discovery.socket_path({"LAUNCHER_RUN_DIR": folder})
