"""The resource manager: every hardware component's state and command interfaces as handles
that hardware and controllers share, and which controller claims each command interface.

A handle is one float (`value`) named `<joint>/<interface>`; hardware writes state handles in
`read()` and reads command handles in `write()`, controllers the other way round, so a cycle
moves numbers without looking anything up. A command interface is claimed by one controller
at a time, as ros2_control's resource manager allows.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

from launcher.control.description import Hardware
from launcher.errors import LaunchError
from launcher.lifecycle import ACTIVE, INACTIVE


class Handle:
    __slots__ = ("name", "prefix", "interface", "value", "low", "high")

    def __init__(self, name: str, value: float = 0.0, low: float = -math.inf,
                 high: float = math.inf) -> None:
        self.name = name
        self.prefix, _, self.interface = name.rpartition("/")
        self.value, self.low, self.high = value, low, high


class Component:
    """What every hardware component offers the manager (see hardware.py); `state` is its
    lifecycle state (launcher/lifecycle.py)."""

    def __init__(self, info: Hardware) -> None:
        self.info = info
        self.state = ACTIVE
        self.states: dict[str, Handle] = {}
        self.commands: dict[str, Handle] = {}
        for component in info.components:
            for interface in component.state_interfaces:
                name = f"{component.name}/{interface.name}"
                self.states[name] = Handle(name, interface.initial_value or 0.0)
            for interface in component.command_interfaces:
                name = f"{component.name}/{interface.name}"
                initial = interface.initial_value
                if initial is None:  # a command starts at its state (a position holds)
                    found = self.states.get(name)
                    initial = found.value if found is not None else 0.0
                self.commands[name] = Handle(name, initial, interface.min, interface.max)

    def read(self, time: float, period: float) -> None:
        pass

    def write(self, time: float, period: float) -> None:
        pass

    def switch_modes(self, start: list[str], stop: list[str]) -> None:
        """Command interfaces claimed (`start`) and released (`stop`) by a switch."""


class Resources:
    def __init__(self, components: Iterable[Component]) -> None:
        self.components = list(components)
        self.states: dict[str, Handle] = {}
        self.commands: dict[str, Handle] = {}
        self.owner: dict[str, Component] = {}
        for component in self.components:
            for name, handle in component.states.items():
                self._add(self.states, name, handle, component)
            for name, handle in component.commands.items():
                self._add(self.commands, name, handle, component)
        self.claimed: dict[str, str] = {}  # command interface -> the controller holding it

    def _add(self, into: dict[str, Handle], name: str, handle: Handle,
             component: Component) -> None:
        if name in into:
            raise LaunchError(f"{component.info.where}: interface '{name}' is exported by two "
                              f"hardware components ('{self.owner[name].info.name}' and "
                              f"'{component.info.name}')")
        into[name] = handle
        self.owner[name] = component

    def available(self, name: str, command: bool) -> bool:
        found = (self.commands if command else self.states).get(name)
        if found is None:
            return False
        state = self.owner[name].state
        return state == ACTIVE if command else state in (INACTIVE, ACTIVE)

    def read(self, time: float, period: float) -> None:
        for component in self.components:
            if component.state in (INACTIVE, ACTIVE):
                component.read(time, period)

    def write(self, time: float, period: float) -> None:
        for component in self.components:
            if component.state == ACTIVE:
                component.write(time, period)

    def claim(self, controller: str, names: list[str]) -> list[Handle]:
        for name in names:
            self.claimed[name] = controller
        by_owner: dict[int, tuple[Component, list[str]]] = {}
        for name in names:
            owner = self.owner[name]
            by_owner.setdefault(id(owner), (owner, []))[1].append(name)
        for owner, started in by_owner.values():
            owner.switch_modes(started, [])
        return [self.commands[name] for name in names]

    def release(self, controller: str) -> list[str]:
        names = [n for n, c in self.claimed.items() if c == controller]
        for name in names:
            del self.claimed[name]
        by_owner: dict[int, tuple[Component, list[str]]] = {}
        for name in names:
            owner = self.owner[name]
            by_owner.setdefault(id(owner), (owner, []))[1].append(name)
        for owner, stopped in by_owner.values():
            owner.switch_modes([], stopped)
        return names

    def describe(self) -> Any:
        """(command names, state names), in the order ros2_control lists them."""
        return sorted(self.commands), sorted(self.states)
