"""Hardware components that need no simulator: mock_components/GenericSystem, whose states
follow its commands (as ros2_control's mock hardware does, for testing controllers without
physics). The sim's GazeboSimSystem is in launcher/sim/plugins/ros2_control.py."""

from __future__ import annotations

import math
from typing import Any

from launcher.control.description import Hardware
from launcher.control.resources import Component


class GenericSystem(Component):
    """A position command sets the position state; a velocity command integrates into the
    position and sets the velocity state; an effort command sets the effort state. Mimic
    joints follow. `position_state_following_offset` (a hardware param) adds to positions."""

    def __init__(self, info: Hardware) -> None:
        super().__init__(info)
        self.offset = float(info.params.get("position_state_following_offset", "0") or 0)
        self.pairs: list[tuple[Any, Any, str]] = []  # (command, state of the same joint, kind)
        for name, command in self.commands.items():
            joint, _, kind = name.rpartition("/")
            state = self.states.get(name)
            if kind == "velocity":
                state = self.states.get(f"{joint}/position")
                velocity = self.states.get(name)
                if velocity is not None:
                    self.pairs.append((command, velocity, "copy"))
                if state is not None:
                    self.pairs.append((command, state, "integrate"))
                continue
            if state is not None:
                self.pairs.append((command, state, "copy"))
        self.mimics = [(self.states.get(f"{j.name}/position"), self.states.get(
            f"{j.mimic[0]}/position"), j.mimic[1], j.mimic[2]) for j in info.joints if j.mimic]

    def read(self, time: float, period: float) -> None:
        for command, state, how in self.pairs:
            value = command.value
            if not math.isfinite(value):
                continue
            if how == "copy":
                state.value = value + (self.offset if state.interface == "position" else 0.0)
            else:
                state.value += value * period
        for mimic, leader, multiplier, offset in self.mimics:
            if mimic is not None and leader is not None:
                mimic.value = leader.value * multiplier + offset


def make(info: Hardware) -> Component:
    """The component for a block that needs no simulator (mock_components)."""
    return GenericSystem(info)
