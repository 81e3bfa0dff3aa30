"""The listing fast path (cli/quick.py) answers only what it can answer as the full command
would, and leaves everything else to it; the session settings' JSON is JSON."""

from __future__ import annotations

import json

import pytest

from launcher.bus.zenoh_settings import json5, settings
from launcher.cli import quick


@pytest.fixture
def environ(tmp_path, monkeypatch):
    for name in ("LAUNCHER_ROUTER", "ROS_DOMAIN_ID"):
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("LAUNCHER_RUN_DIR", str(tmp_path))
    return tmp_path


@pytest.mark.parametrize("argv", [["topic", "list", "-t"], ["ros2", "topic", "list", "-v"],
                                  ["rostopic", "list", "/ns"], ["node", "list"], []])
def test_other_words_and_options_take_the_full_way(environ, argv):
    assert quick.answer(argv) is None


def test_an_explicit_router_a_bad_domain_or_no_router_take_the_full_way(environ,
                                                                           monkeypatch):
    assert quick.answer(["topic", "list"]) is None  # no router's socket in the run folder
    (environ / "domain-0.lock").write_text("")
    (environ / "domain-0.sock").write_text("")  # a dead router's file: nothing answers
    assert quick.answer(["rostopic", "list"]) is None
    monkeypatch.setenv("ROS_DOMAIN_ID", "999")
    assert quick.answer(["topic", "list"]) is None
    monkeypatch.setenv("ROS_DOMAIN_ID", "0")
    monkeypatch.setenv("LAUNCHER_ROUTER", "tcp/127.0.0.1:7447")
    assert quick.answer(["ros2", "topic", "list"]) is None


def test_the_settings_json_is_json(tmp_path):
    values = settings("peer", ['unixsock-stream//a b/"q\\x\n\u0001é'], ["unixsock-stream//s"],
                      2.5)
    values["extra"] = {"none": None, "list": [1, 2.5, True, "x"]}
    assert json.loads(json5(values)) == values
    with pytest.raises(TypeError):
        json5(object())
