"""What every mujoco_ros2_control ROS plugin is in the sim (ros_plugins.py makes them): its
instance name, its parameters declared as data (bus/declarations.py) and read under its prefix
(`mujoco_plugins.<name>.`), its topics in its sub-namespace, and its update each control
cycle. A plugin with a rate works on the grid of sim/schedule.py: the base decides when its
work is due, as gz-sensors' Sensor::Update does, and the plugin only does it (`publish`)."""

from __future__ import annotations

import itertools
from typing import Any

from launcher.bus.declarations import PLACEHOLDER, Param
from launcher.control.yaml_places import key_place
from launcher.errors import LaunchError, ParameterError
from launcher.records import dataclass
from launcher.sim import schedule

ROOT = "mujoco_plugins."
NODE = "mujoco_ros2_control_node"


@dataclass
class Context:
    """What every plugin of the node is made with."""

    node: Any
    world: Any
    where: str  # the hardware's place: for a message with no better one
    files: list[str]  # the node's parameter files: where a setting is written


class RosPlugin:
    """One plugin: `values` holds its declared parameters by their names under its prefix."""

    PARAMETERS: tuple[Param, ...] = ()  # under its prefix; `{camera}`: one for each camera
    SCOPE = ""  # the prefix its code reads whatever its instance is called (else ROOT<name>.)
    RATE = ""  # the parameter of its rate (Hz of sim time, declared above 0), when it has one
    next_update = 0.0  # (schedule.tick's)

    def __init__(self, context: Context, name: str, defaults: dict[str, Any] | None = None,
                 **items: list[str]) -> None:
        """`items`: the names a placeholder stands for; `defaults`: this instance's own
        defaults, by name under the prefix."""
        self.context, self.name = context, name
        self.node, self.world, self.where = context.node, context.world, context.where
        self.log = self.node.get_logger()
        self.prefix = self.scope(name)
        self.values = self._declare(scoped(self.PARAMETERS, self.prefix, items, defaults or {}))
        self.rate = self.values[self.RATE] if self.RATE else 0.0  # (0: every control cycle)

    @classmethod
    def scope(cls, name: str) -> str:
        """The prefix of the parameters of the instance `name`."""
        return cls.SCOPE or f"{ROOT}{name}."

    def _declare(self, mine: tuple[Param, ...]) -> dict[str, Any]:
        """`mine` read through the node's params.declare (which adds them to the node's
        declarations: `ros2 param describe` tells every plugin's); a bad value refused at its
        line."""
        if not mine:
            return {}
        try:
            found = self.node.params.declare(mine)
        except ParameterError as exc:  # (it names the node)
            raise LaunchError(f"{self.place(exc.name)}: {exc}") from None
        return {name.removeprefix(self.prefix): value for name, value in found.items()}

    def place(self, name: str) -> str:
        """`file:line` of the setting `name`, else of the plugin's block, else the hardware's."""
        for dotted in (name, f"{ROOT}{self.name}.type"):
            for node in ("/**", NODE):
                found = key_place(self.context.files, node, dotted)
                if found:
                    return found
        return self.where

    def topic(self, name: str) -> str:
        """A relative topic in the plugin's sub-namespace; an absolute one as it is."""
        return name if name.startswith("/") else f"/{self.name}/{name}"

    def update(self, model: Any, data: Any, now: float) -> None:
        """Each control cycle: its work, when it has someone to work for and is due."""
        if self.wanted() and schedule.tick(self, now, self.rate):
            self.publish(model, data, now)

    def wanted(self) -> bool:
        """Whether its work has someone to work for (a lazy publisher's subscribers)."""
        return True

    def publish(self, model: Any, data: Any, now: float) -> None:
        """Its periodic work, once due."""

    def close(self) -> None:
        pass


def scoped(declared: tuple[Param, ...], prefix: str, items: dict[str, list[str]],
           defaults: dict[str, Any]) -> tuple[Param, ...]:
    """`declared`, named under `prefix`: a name with a placeholder (`{camera}.policy`, as
    bus/declarations.py writes them) once for each of `items["camera"]`, the placeholder in its
    text default filled alike; `defaults`: defaults of the instance, by name under `prefix`."""
    found = []
    for param in declared:
        keys = PLACEHOLDER.findall(param.name)
        for chosen in itertools.product(*(items.get(key, ()) for key in keys)):
            fill = dict(zip(keys, chosen, strict=True))
            name = param.name.format_map(fill)
            default = param.default.format_map(fill) if isinstance(param.default, str) \
                else param.default
            found.append(param._replace(name=prefix + name, default=defaults.get(name, default)))
    return tuple(found)
