"""What every mujoco_ros2_control ROS plugin is in the sim (ros_plugins.py makes them): its
instance name, its parameters (`mujoco_plugins.<name>.…`), its topics in its sub-namespace,
and its update each control cycle."""

from __future__ import annotations

from typing import Any


class RosPlugin:
    """One plugin: its instance name, its parameters (`mujoco_plugins.<name>.…`)."""

    def __init__(self, node: Any, world: Any, name: str, where: str) -> None:
        self.node, self.world, self.name, self.where = node, world, name, where
        prefix = f"mujoco_plugins.{name}."
        self.params = {k[len(prefix):]: v for k, v in node.parameters.items()
                       if k.startswith(prefix)}
        self.log = node.get_logger()

    def param(self, name: str, default: Any) -> Any:
        return self.params.get(name, default)

    def topic(self, name: str) -> str:
        """A relative topic in the plugin's sub-namespace; an absolute one as it is."""
        return name if name.startswith("/") else f"/{self.name}/{name}"

    def update(self, model: Any, data: Any, now: float) -> None:
        pass

    def close(self) -> None:
        pass
