"""An SDF `<sensor>` read into what the sim needs to run it: a plugin config (so a sensor is
made, loaded, re-bound, reset and removed as an entity's plugins are), with the sensor's kind,
its link, the site that carries its pose, and the settings every sensor shares."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from launcher.errors import did_you_mean
from launcher.sim.mjcf import PluginConfig
from launcher.sim.sensors import KINDS, NOT_SIMULATED


@dataclass
class SensorConfig(PluginConfig):
    kind: str = ""  # what launcher simulates it as (sensors.KINDS)
    link: str = ""  # the link, scoped within its model (`inner::link`)
    topic: str | None = None
    update_rate: float = 0.0  # Hz; 0: every step
    always_on: bool = False
    frame_id: str | None = None
    named_link: str = ""  # the link Gazebo names it under, where not `link`: a URDF's fixed
    # links are lumped into their parent, and their sensors with them
    joint: str = ""  # a joint's sensor (force_torque): the joint; `link` is its child

    @property
    def scope_link(self) -> str:
        return self.named_link or self.link

    @property
    def site(self) -> str:
        """The site at the sensor's pose, below the entity's prefix."""
        if self.joint:
            return f"{self.link}/joint/{self.joint}/sensor/{self.name}"
        return f"{self.link}/sensor/{self.name}"


def sensor_config(element: Any, link: str, warn: Any, joint: str = "") -> SensorConfig | None:
    """The sensor an SDF `<sensor>` element declares; one launcher does not simulate is a
    warning at its line (None); a value no sensor can take is an error at its line."""
    name, written = element.get("name", ""), element.get("type", "")
    if not name:
        raise element.error("<sensor> needs a name")
    if written in NOT_SIMULATED:
        warn(element, f"sensor '{name}' (type {written}) is not simulated: "
                      f"{NOT_SIMULATED[written]}; it publishes nothing")
        return None
    if written not in KINDS:
        warn(element, f"sensor '{name}': unknown type '{written}'"
                      f"{did_you_mean(written, [*KINDS, *NOT_SIMULATED])}; it is left out")
        return None
    rate = _number(element, "update_rate", 0.0)  # (the sensor says when it is not one)
    frame = element.value("gz_frame_id") or element.value("ignition_frame_id")
    location = element.location
    return SensorConfig(f"sensor:{KINDS[written]}", name, element,
                        f"{location.file}:{location.line}", kind=KINDS[written], link=link,
                        topic=element.value("topic") or None, update_rate=rate,
                        always_on=_flag(element, "always_on"), frame_id=frame or None,
                        joint=joint)


def _number(element: Any, tag: str, default: float) -> float:
    text = element.value(tag)
    if text is None or text == "":
        return default
    try:
        return float(text)
    except ValueError:
        return math.nan


def _flag(element: Any, tag: str) -> bool:
    return (element.value(tag, "false") or "").strip().lower() in ("true", "1")
