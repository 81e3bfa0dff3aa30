"""A gazebo_ros plugin's ROS node, as `gazebo_ros::Node::Get(sdf)` makes it: named after the
plugin, in `<ros><namespace>` (ROS 1: `<robotNamespace>`), with the `<ros><remapping>` rules
applied to its topics as ROS 2 applies remappings (both sides expanded in the node's
namespace: `~/out:=scan` turns `/ns/plugin/out` into `/ns/scan`). An entity spawned in a
namespace (simulation_interfaces' `entity_namespace`) has a relative one put under it (an
absolute one stays)."""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from launcher.bus.names import expand, remap


@dataclass(frozen=True)
class RosNode:
    """A gazebo_ros plugin's node: its name, namespace and remapping rules."""
    name: str
    namespace: str = "/"
    rules: tuple[tuple[str, str], ...] = ()

    def topic(self, name: str) -> str:
        return remap(expand(name, self.name, self.namespace), list(self.rules), self.name,
                     self.namespace)


def ros_node(plugin: Any, entity_namespace: str = "") -> RosNode:
    ros = plugin.find("ros")
    namespace = under(entity_namespace, (ros.findtext("namespace") if ros is not None else None)
                      or plugin.findtext("robotNamespace") or "")
    rules = []
    for remapping in (ros.iterfind("remapping") if ros is not None else ()):
        source, _, target = (remapping.text or "").strip().partition(":=")
        if source.strip() and target.strip():
            rules.append((source.strip(), target.strip()))
    name = re.sub(r"\W", "_", plugin.get("name", "") or "gazebo_ros") or "gazebo_ros"
    return RosNode(name, "/" + namespace.strip().strip("/"), tuple(rules))


def under(entity_namespace: str, written: str) -> str:
    """A plugin's namespace as written, below its entity's (`entity_namespace`, "" for
    none); an absolute one stays as it is."""
    written = written.strip()
    if written.startswith("/"):
        return written
    parts = (entity_namespace.strip("/"), written.strip("/"))
    return "/" + "/".join(part for part in parts if part)
