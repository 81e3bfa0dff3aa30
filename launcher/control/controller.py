"""The base of every controller: a node of its own (named as the controller, in the manager's
namespace, parameters from the manager's files and its `params_file`), ros2_control's
lifecycle (unconfigured → inactive → active), the interfaces it asks for, and `update()`.

A controller that refuses (a missing or wrong parameter) raises ControllerError; the manager
answers the request with `ok: false` and logs the reason, as controller_manager does.
"""

from __future__ import annotations

import math
from typing import Any

from launcher.bus.declarations import Param, ParameterError
from launcher.bus.types import registry
from launcher.bus.wire import split_time
from launcher.control.resources import ACTIVE, INACTIVE, UNCONFIGURED, Handle
from launcher.errors import LaunchError

CONTROLLER_BASE = "controller_interface::ControllerInterface"
_CLASSES: dict[str, type] = {}


class ControllerError(LaunchError):
    pass


class Controller:
    type_name = ""
    base_class = CONTROLLER_BASE
    PARAMETERS: tuple[Param, ...] = ()  # what it reads, declared (bus/declarations.py)

    def __init__(self, name: str, node: Any, where: str = "") -> None:
        self.name, self.node = name, node
        self.where = where  # file:line of its parameters, when known
        self.state = UNCONFIGURED
        self.update_rate = 0  # Hz; 0: the manager's
        self.commands: list[Handle] = []  # claimed, in command_interfaces() order
        self.states: dict[str, Handle] = {}
        self.last_update: float | None = None
        self.place_of: Any = lambda name: ""  # file:line:column of a parameter (the manager's)

    # --- what a controller declares --------------------------------------------------------
    def on_init(self) -> None:
        """Read parameters that exist from the start (joints, interfaces)."""

    def command_interfaces(self) -> list[str]:
        return []

    def state_interfaces(self) -> list[str] | None:
        """The state interfaces it reads; None: every one (a broadcaster)."""
        return []

    def on_configure(self) -> None:
        pass

    def on_activate(self) -> None:
        pass

    def on_deactivate(self) -> None:
        pass

    def on_cleanup(self) -> None:
        pass

    def update(self, time: float, period: float) -> None:
        pass

    # --- parameters --------------------------------------------------------------------------
    def read_parameters(self, *only: str) -> dict[str, Any]:
        """The declared parameters (those named, else all) from the controller's node, checked,
        with their defaults; a bad one is refused at its line in the parameter file."""
        try:
            return self.node.params.declare(self.PARAMETERS, only)
        except ParameterError as exc:
            name = exc.name
            place = self.place_of(name) if name in self.node.parameters else ""
            raise ControllerError(self._at(f"controller '{self.name}': {exc}", place)) from None

    def _at(self, message: str, place: str = "") -> str:
        place = place or self.where
        return f"{place}: {message}" if place else message

    # --- helpers ---------------------------------------------------------------------------
    @property
    def is_active(self) -> bool:
        return self.state == ACTIVE

    @property
    def is_inactive(self) -> bool:
        return self.state == INACTIVE

    def make(self, type_name: str, **fields: Any) -> Any:
        """A message, made by its class directly (a controller may publish at 1 kHz: the
        checking builder behind node.message costs more than the rest of its update)."""
        found = _CLASSES.get(type_name)
        if found is None:
            found = _CLASSES[type_name] = registry().message_class(type_name)
        try:
            return found(**fields)
        except TypeError:  # fields left out: the builder fills them with their defaults
            return self.node.message(type_name, **fields)

    def stamp(self, time: float) -> Any:
        sec, nanosec = split_time(time)
        return self.make("builtin_interfaces/msg/Time", sec=sec, nanosec=nanosec)

    def header(self, time: float, frame_id: str = "") -> Any:
        return self.make("std_msgs/msg/Header", stamp=self.stamp(time), frame_id=frame_id)

    def refuse_non_finite(self, values: list[float], what: str) -> bool:
        """True (and one warning) when a command holds NaN or an infinity: it is dropped."""
        if all(math.isfinite(v) for v in values):
            return False
        if not getattr(self, "_warned_nan", False):
            self._warned_nan = True
            self.node.get_logger().warning(
                f"{what} holds NaN or an infinite value ({values}): ignored, the joints hold "
                f"their last command (warned once)")
        return True
