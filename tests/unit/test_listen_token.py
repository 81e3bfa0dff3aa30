"""The graph's token for TCP listeners (bus/listen_token.py) and the viewer's own-user gate
on Studio's internal port (sim/viewer_gate.py)."""

from __future__ import annotations

import os
import socket
import threading

from launcher.bus import listen_token
from launcher.sim import viewer_gate


def test_one_private_token_per_graph(tmp_path):
    env = {"LAUNCHER_RUN_DIR": str(tmp_path / "run"), "ROS_DOMAIN_ID": "3"}
    first = listen_token.load(env)
    assert len(first) >= 32 and listen_token.load(env) == first
    file = tmp_path / "run" / "domain-3.token"
    assert file.stat().st_mode & 0o777 == 0o600
    assert (tmp_path / "run").stat().st_mode & 0o777 == 0o700
    assert listen_token.load({**env, "ROS_DOMAIN_ID": "4"}) != first


def test_a_request_presents_the_token_in_its_url_cookie_or_header():
    token = "s3cret"
    assert listen_token.presented("/?token=s3cret", [], 8080) == ("s3cret", True)
    assert listen_token.presented("/model", [("Cookie", "a=b; launcher_token_8080=s3cret")],
                                  8080) == ("s3cret", False)
    assert listen_token.presented("/", [("Cookie", "launcher_token_9090=s3cret")], 8080) == \
        (None, False)  # another port's cookie
    assert listen_token.presented("/", {"Authorization": "Bearer s3cret"}, 1)[0] == token
    assert listen_token.presented("/", [("Cookie", "bad\x00;;")], 1) == (None, False)
    assert listen_token.matches("s3cret", token)
    assert not listen_token.matches(None, token) and not listen_token.matches("s3cre", token)
    assert listen_token.url("http://h:1/", token) == "http://h:1/?token=s3cret"
    assert listen_token.url("ws://h:1/?a=b", None) == "ws://h:1/?a=b"
    assert listen_token.off({"LAUNCHER_NO_TOKEN": "1"}) and not listen_token.off({})


def test_the_internal_port_knows_its_peers_user():
    listener = viewer_gate.own_user_listener()
    port = listener.getsockname()[1]
    accepted = []
    thread = threading.Thread(target=lambda: accepted.append(listener.accept()))
    thread.start()
    with socket.create_connection(("127.0.0.1", port), timeout=5) as client:
        thread.join(5)
        connection, _ = accepted[0]
        assert viewer_gate.peer_uid(connection) == os.getuid()
        assert viewer_gate.peer_uid(client) == os.getuid()
        connection.close()
    listener.close()
