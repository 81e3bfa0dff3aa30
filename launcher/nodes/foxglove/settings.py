"""foxglove_bridge's parameters, declared (bus/declarations.py) and read as a ROS user sets
them, and the whitelists they give."""

from __future__ import annotations

import re
from typing import Any

from launcher.bus.declarations import Param
from launcher.bus.node import Node
from launcher.errors import LaunchError

CAPABILITIES = ("clientPublish", "parameters", "parametersSubscribe", "services",
                "connectionGraph", "assets")


def parameters() -> tuple[Param, ...]:
    """foxglove_bridge's parameters, declared."""
    from launcher.nodes.foxglove.assets import DEFAULT_ALLOWLIST

    return (
        Param("port", "int", 8765, "the WebSocket port (behind launcher's front)",
              minimum=1, maximum=65535),
        Param("address", "string", "127.0.0.1", "the address it listens on"),
        Param("topic_whitelist", "string_array", [".*"],
              "regular expressions of the topics served"),
        Param("service_whitelist", "string_array", [".*"],
              "regular expressions of the services served"),
        Param("param_whitelist", "string_array", [".*"],
              "regular expressions of the parameters served"),
        Param("client_topic_whitelist", "string_array", [".*"],
              "regular expressions of the topics clients may publish"),
        Param("send_buffer_limit", "int", 10_000_000,
              "bytes queued for a client before it loses frames"),
        Param("use_sim_time", "bool", False, "the clients' time from /clock"),
        Param("capabilities", "string_array", list(CAPABILITIES),
              "what clients may do: " + ", ".join(CAPABILITIES), choices=CAPABILITIES),
        Param("include_hidden", "bool", False, "serve hidden topics and services too"),
        Param("max_qos_depth", "int", 25, "the deepest history a channel subscribes with",
              minimum=1),
        Param("asset_uri_allowlist", "string_array", list(DEFAULT_ALLOWLIST),
              "regular expressions of the asset URIs clients may fetch"),
        Param("token", "bool", True, "clients must bring the graph's token"),
    )


class Settings:
    """foxglove_bridge's parameters, as a ROS user sets them."""

    def __init__(self, node: Node) -> None:
        value = node.params.declare(parameters())
        self.port, self.address = value["port"], value["address"]
        self.topics = patterns(value["topic_whitelist"], "topic_whitelist")
        self.services = patterns(value["service_whitelist"], "service_whitelist")
        self.params = patterns(value["param_whitelist"], "param_whitelist")
        self.client_topics = patterns(value["client_topic_whitelist"],
                                      "client_topic_whitelist")
        self.send_buffer_limit = value["send_buffer_limit"]
        self.use_sim_time = value["use_sim_time"]
        self.capabilities = value["capabilities"]
        self.include_hidden, self.max_qos_depth = value["include_hidden"], value["max_qos_depth"]
        self.asset_allowlist = value["asset_uri_allowlist"]
        self.token = value["token"]

    @property
    def backlog(self) -> int:
        """The SDK bounds each client's queue in messages, not bytes: send_buffer_limit read
        as that many 512 KiB messages (10 MB: 19, about 10 MB of camera images), from 8 to
        1024."""
        return max(8, min(1024, self.send_buffer_limit // (512 * 1024)))


def patterns(values: Any, name: str) -> list[re.Pattern[str]]:
    """The regular expressions of a whitelist parameter, or LaunchError naming the bad one."""
    items = [values] if isinstance(values, str) else list(values)
    try:
        return [re.compile(str(item)) for item in items]
    except re.error as exc:
        raise LaunchError(f"foxglove_bridge: {name}: '{exc.pattern}' is not a regular "
                          f"expression: {exc}") from None


def allowed(name: str, patterns: list[re.Pattern[str]]) -> bool:
    """Whether a whitelist lets `name` through (one of its expressions matches it whole)."""
    return any(p.fullmatch(name) for p in patterns)
