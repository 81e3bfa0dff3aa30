"""parameter_bridge: sim-native topics and services ⇄ ROS-typed ones, as ros_gz_bridge does.

  parameter_bridge [TOPIC@ROS_TYPE@GZ_TYPE …] [--ros-args -p config_file:=bridge.yaml]
See bridge_config.py for the YAML and the command-line forms and conversions.py for the type
pairs. Namespaces and remaps apply to the ROS side only: sim names are used as written
(relative ones from `/`), so one bridge per robot (in its namespace) and one bridge for all
robots (absolute per-robot entries) both work. A bad entry is reported and skipped; the
bridge runs with the rest. The sim's side is its own (keys.SIM), as gz-transport is apart from
ROS: the bridge is what puts a sim topic on the ROS graph.
"""

from __future__ import annotations

import sys
from typing import Any

from launcher.bus import keys
from launcher.bus.declarations import Param
from launcher.bus.lockstep import Relay
from launcher.bus.node import Node
from launcher.bus.qos import QoS
from launcher.errors import LaunchError
from launcher.nodes import bridge_config, conversions, running
from launcher.nodes.bridge_config import Entry


class Bridge:
    def __init__(self, node: Node) -> None:
        self.node = node
        self.log = node.get_logger()
        self.count = 0

    def add(self, entry: Entry) -> None:
        """Bridge one entry; a problem with it is reported and the entry skipped."""
        try:
            if entry.service:
                self._add_service(entry)
            else:
                self._add_topic(entry)
            self.count += 1
        except LaunchError as exc:
            self.log.error(f"{entry.where}: {exc}; skipped")

    def _add_topic(self, entry: Entry) -> None:
        conversion = conversions.find(entry.ros_type, entry.sim_type)
        sim_name = entry.sim_name if entry.sim_name.startswith("/") else f"/{entry.sim_name}"
        ros_name = self.node.resolve(entry.ros_name)
        ways = []
        if entry.direction in ("BIDIRECTIONAL", "GZ_TO_ROS"):
            ways.append(((entry.sim_type, sim_name, keys.SIM),
                         (entry.ros_type, ros_name, keys.ROS), conversion.to_ros, "GZ_TO_ROS"))
        if entry.direction in ("BIDIRECTIONAL", "ROS_TO_GZ"):
            ways.append(((entry.ros_type, ros_name, keys.ROS),
                         (entry.sim_type, sim_name, keys.SIM), conversion.to_sim, "ROS_TO_GZ"))
        for *_, convert, way in ways:
            if convert is None:
                raise LaunchError(f"{entry.ros_type} ⇄ gz.msgs.{entry.sim_type.rsplit('/')[-1]}"
                                  f" can only go one way; {way} is not supported")
        for source, target, convert, _ in ways:
            self._one_way(entry, source, target, convert)
        arrow = {"BIDIRECTIONAL": "<->", "GZ_TO_ROS": "->", "ROS_TO_GZ": "<-"}[entry.direction]
        self.log.info(f"bridging {sim_name} ({entry.sim_type}) {arrow} {ros_name} "
                      f"({entry.ros_type}){' lazily' if entry.lazy else ''}")

    def _add_service(self, entry: Entry) -> None:
        """A ROS-typed service that forwards each call to the sim's service."""
        from launcher.bus.messages import build

        conversion = conversions.find_service(entry.ros_type, entry.sim_type)
        sim_name = entry.sim_name if entry.sim_name.startswith("/") else f"/{entry.sim_name}"
        client = self.node.create_client(entry.sim_type, sim_name, space=keys.SIM)
        request_type = f"{entry.sim_type}_Request"

        def forward(request: Any, response: Any) -> Any:
            answer = client.call(build(request_type, conversion.request(request)), timeout=30)
            for key, value in conversion.response(answer).items():
                setattr(response, key, value)
            if not answer.success:
                self.log.warning(f"{sim_name}: {answer.message}")
            return response

        server = self.node.create_service(entry.ros_type, entry.ros_name, forward)
        self.log.info(f"bridging service {sim_name} ({entry.sim_type}) <- {server.name} "
                      f"({entry.ros_type})")

    def _one_way(self, entry: Entry, source: tuple[str, str, keys.Space],
                 target: tuple[str, str, keys.Space], convert: Any) -> None:
        """Forward (type, name, space) `source` to `target`, converting each payload."""
        publisher = self.node.create_publisher(target[0], target[1],
                                               QoS(depth=entry.publisher_queue),
                                               space=target[2])

        def forward(payload: bytes) -> None:
            publisher.publish_raw(convert(payload))

        def subscribe() -> Any:
            return self.node.create_subscription(
                source[0], source[1], forward, QoS(depth=entry.subscriber_queue), raw=True,
                inline=True, remote_only=True, space=source[2])

        if not entry.lazy:
            subscribe()
            return
        state: dict[str, Any] = {"subscription": None}

        def on_subscribers(matching: bool) -> None:
            if matching and state["subscription"] is None:
                state["subscription"] = subscribe()
            elif not matching and state["subscription"] is not None:
                state["subscription"].destroy()
                state["subscription"] = None

        self.node.watch_subscribers(publisher, on_subscribers)


# ros_gz_bridge's parameter (the config file is a template of all the node's parameters)
PARAMETERS = (
    Param("config_file", "string", "", "the bridge's YAML (a Jinja template of the node's "
                                       "parameters)"),
)


def setup(node: Node) -> Bridge:
    config = node.params.declare(PARAMETERS)["config_file"]
    bridge = Bridge(node)
    types = bridge_config.Types(conversions.sim_type, conversions.known_ros_type)
    entries = [bridge_config.parse_argument(arg, types) for arg in node.args]
    total = len(entries)
    if config:
        loaded, given = bridge_config.load_file(str(config), node.parameters, types,
                                                node.get_logger().error)
        entries, total = entries + loaded, total + given
    if not entries and not config and not node.args:
        raise LaunchError("nothing to bridge: give TOPIC@ROS_TYPE@GZ_TYPE arguments or "
                          "--ros-args -p config_file:=bridge.yaml")
    for entry in entries:
        bridge.add(entry)
    node.host.adopt(Relay(node.host))  # (a part of a sim's lockstep, while there is one)
    if not bridge.count:  # every entry was refused (each said why, with its place)
        raise LaunchError("nothing to bridge: every entry was left out (see above)")
    node.get_logger().info(f"bridging {bridge.count} of {total} entries")
    return bridge


component = running.component("parameter_bridge", setup)


def main() -> int:
    return running.run_node("parameter_bridge", setup)


if __name__ == "__main__":
    sys.exit(main())
