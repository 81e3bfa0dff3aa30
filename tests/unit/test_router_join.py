"""`launcher router --join ENDPOINT` (bus/bridge.py) as it reads its arguments, the host
tokens sessions declare, and `node list`'s host column; no router is started here."""

from __future__ import annotations

import threading

import pytest

from launcher.bus import bridge, keys, router
from launcher.cli.node.list import lines
from launcher.errors import UsageError


@pytest.mark.parametrize("endpoint", ["tcp/10.0.0.1:7447", "tcp/[fd00::2]:7447",
                                      "tcp/robot1.local:7447", "quic/10.0.0.1:7447"])
def test_join_takes_another_hosts_endpoint(endpoint):
    assert bridge.check(endpoint) == endpoint


@pytest.mark.parametrize("endpoint", ["tcp/10.0.0.1", "10.0.0.1:7447", "tcp/host:0",
                                      "robot1"])
def test_join_with_a_malformed_endpoint_says_what_one_looks_like(endpoint):
    with pytest.raises(UsageError, match=f"--join: '{endpoint}' is not an endpoint: expected "
                                         r"PROTOCOL/HOST:PORT \(e.g. tcp/192.168.1.5:7447"):
        bridge.check(endpoint)


def test_join_refuses_a_unix_socket_which_is_this_hosts_own():
    with pytest.raises(UsageError, match="a Unix socket is this host's own; --join connects "
                                         "to another host's router"):
        bridge.check("unixsock-stream//tmp/launcher/domain-0.sock")


def test_join_and_listen_together_are_refused_before_anything_starts():
    with pytest.raises(UsageError, match=r"--join tcp/10.0.0.1:7447 and --listen "
                                         r"tcp/0.0.0.0:7447: --listen lets other hosts join"):
        router.run(["tcp/0.0.0.0:7447"], "tcp/10.0.0.1:7447", threading.Event())


def test_a_malformed_join_endpoint_is_said_by_the_standing_router():
    with pytest.raises(UsageError, match="--join: 'tcp/robot1' is not an endpoint"):
        router.run([], "tcp/robot1", threading.Event())


# --- which host a session runs on ------------------------------------------------------------
def test_a_host_token_is_launchers_own_and_reads_back():
    key = keys.host_key(3, "aa11", "robot2")
    assert key == "@launcher_lv/3/aa11/host/robot2"
    assert not key.startswith(keys.LIVELINESS)  # (off the ROS graph: no ROS tool lists it)
    assert keys.parse_host_key(key) == ("aa11", "robot2")


def test_a_host_name_is_made_a_chunk_of_a_key():
    assert keys.parse_host_key(keys.host_key(0, "aa11", "we*ird/name#1")) == \
        ("aa11", "we_ird_name_1")


@pytest.mark.parametrize("key", ["@ros2_lv/0/aa11/0/0/NN/%/%/talker",
                                 "@launcher_lv/0/aa11/other/robot2", "@launcher_lv/0/aa11"])
def test_other_tokens_are_no_host_tokens(key):
    assert keys.parse_host_key(key) is None


# --- node list's hosts --------------------------------------------------------------------------
def node(zid: str, name: str, namespace: str = "") -> keys.Entity:
    return keys.Entity(zid, 0, 0, keys.NODE, namespace, name)


def test_nodes_of_one_host_are_listed_plain():
    listed = lines([node("a", "talker"), node("b", "listener")], {"a": "vm", "b": "vm"})
    assert listed == ["/listener", "/talker"]


def test_nodes_of_several_hosts_say_where_each_runs():
    listed = lines([node("a", "talker"), node("b", "relay", "/robot"), node("c", "listener")],
                   {"a": "robot2", "b": "robot2", "c": "base"})
    assert listed == ["/listener     [base]", "/robot/relay  [robot2]", "/talker       [robot2]"]


def test_hosts_shows_the_column_for_one_host_too():
    assert lines([node("a", "talker")], {"a": "vm"}, hosts=True) == ["/talker  [vm]"]


def test_a_node_whose_program_does_not_say_its_host_is_shown_with_a_question_mark():
    listed = lines([node("a", "talker"), node("b", "rmw_node"), node("c", "listener")],
                   {"a": "robot2", "c": "base"})
    assert "/rmw_node  [?]" in listed


def test_a_node_of_unknown_host_beside_one_host_keeps_the_plain_list():
    assert lines([node("a", "talker"), node("b", "rmw_node")], {"a": "vm"}) == \
        ["/rmw_node", "/talker"]


def test_one_name_on_two_hosts_is_two_lines():
    listed = lines([node("a", "talker"), node("b", "talker")], {"a": "robot2", "b": "robot3"})
    assert listed == ["/talker  [robot2]", "/talker  [robot3]"]
