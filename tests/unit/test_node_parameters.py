"""A node's parameter values and who may change them (bus/node_parameters.py)."""

from __future__ import annotations

import pytest

from launcher.bus.declarations import Param
from launcher.bus.node_parameters import NodeParameters
from launcher.errors import LaunchError


def test_a_set_is_heard_by_the_listeners_and_a_kept_value_is_not():
    params, heard = NodeParameters({}, "/n"), []
    params.on_set(lambda name, value: heard.append((name, value)))
    params.set("gain", 2.0)
    params.keep("quiet", 1)
    assert heard == [("gain", 2.0)] and params.values == {"gain": 2.0, "quiet": 1}


def test_a_request_from_outside_may_be_refused_by_the_gate():
    params = NodeParameters({"gain": 1.0}, "/n")
    params.gate = lambda name, value: "read-only" if name == "gain" else None
    assert params.request("gain", 3.0) == "read-only" and params.get("gain") == 1.0
    assert params.request("other", 3.0) is None and params.get("other") == 3.0


def test_deleting_a_parameter_that_is_not_set_says_so():
    params = NodeParameters({}, "/n")
    assert params.request("missing", None) == "parameter 'missing' is not set"


def test_an_unknown_parameter_is_refused_naming_the_node():
    with pytest.raises(LaunchError, match="parameter 'x' is not declared on /robot/driver"):
        NodeParameters({}, "/robot/driver").get("x")


def test_a_read_only_declared_parameter_is_refused_from_outside_and_described_so():
    params = NodeParameters({"joints": ["a"]}, "/n")
    params.declare((Param("joints", "string_array", [], "the joints", read_only=True),
                    Param("rate", "double", 1.0, "a rate")))
    assert params.request("joints", ["b"]) == \
        "parameter 'joints' cannot be set because it is read-only"
    assert params.get("joints") == ["a"] and params.describe("joints")["read_only"]
    assert params.request("rate", 2.0) is None and params.get("rate") == 2.0


def test_declarations_add_up_as_a_ros_nodes_do():
    """A node whose parts declare their own (the controller manager, then each mujoco plugin)
    describes every part's parameters, and a name declared again takes its new declaration."""
    params = NodeParameters({}, "/n")
    params.declare((Param("update_rate", "int", 100, "Hz"), Param("a", "double", 1.0, "old")))
    params.declare((Param("plugin.rate", "double", 30.0, "Hz"), Param("a", "double", 1.0, "new")))
    assert params.describe("update_rate")["description"] == "Hz"  # (the first part's)
    assert params.describe("plugin.rate")["type"] == 3  # (PARAMETER_DOUBLE)
    assert params.describe("a")["description"] == "new"
