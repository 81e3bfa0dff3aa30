"""The base of every controller: a node of its own (named as the controller, in the manager's
namespace, parameters from the manager's files and its `params_file`), ros2_control's
lifecycle (unconfigured → inactive → active: the transitions of launcher/lifecycle.py), the
interfaces it asks for, and `update()`.

A controller that refuses (a missing or wrong parameter) raises ControllerError; the manager
answers the request with `ok: false` and logs the reason, as controller_manager does.
"""

from __future__ import annotations

import math
from typing import Any

from launcher.bus.declarations import Param
from launcher.bus.types import registry
from launcher.bus.wire import split_time
from launcher.control.resources import Handle
from launcher.control.yaml_places import Places
from launcher.errors import LaunchError, ParameterError
from launcher.lifecycle import ACTIVE, CONFIGURE, INACTIVE, TRANSITIONS, UNCONFIGURED, reached

CONTROLLER_BASE = "controller_interface::ControllerInterface"
_CLASSES: dict[str, type] = {}


class ControllerError(LaunchError):
    pass


class Controller:
    """`type_name` is its type as the manager's parameters name it
    (`joint_trajectory_controller/JointTrajectoryController`), `places` where its settings
    are written (its messages point there)."""

    base_class = CONTROLLER_BASE
    # what it reads, declared (bus/declarations.py): controller_interface's own, then each
    # controller's (`PARAMETERS = (*Controller.PARAMETERS, …)`)
    PARAMETERS: tuple[Param, ...] = (
        Param("update_rate", "int", 0, "updates a second (Hz); 0: at the manager's "
              "update_rate", minimum=0),
    )

    def __init__(self, name: str, node: Any, type_name: str, places: Places) -> None:
        self.name, self.node, self.type_name, self.places = name, node, type_name, places
        self.state = UNCONFIGURED
        self.update_rate = 0  # Hz; 0: the manager's
        self.commands: list[Handle] = []  # claimed, in command_interfaces() order
        self.states: dict[str, Handle] = {}
        self.last_update: float | None = None

    def take(self, transition: int) -> None:
        """Make a lifecycle transition (launcher/lifecycle.py's id): its callback's work, then
        the state it reaches; InvalidTransition if it is not allowed from the state, and a
        ControllerError from the work leaves it as it was. Its update_rate is read as it is
        configured, before on_configure, as controller_interface reads it."""
        goal, rate = reached(self.state, transition), self.update_rate
        if transition == CONFIGURE:
            rate = self.read_parameters("update_rate")["update_rate"]
        getattr(self, TRANSITIONS[transition].callback)()
        self.state, self.update_rate = goal, rate

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

    def on_shutdown(self) -> None:
        pass

    def update(self, time: float, period: float) -> None:
        pass

    # --- parameters --------------------------------------------------------------------------
    def read_parameters(self, *only: str) -> dict[str, Any]:
        """The declared parameters (those named, else all) from the controller's node, checked,
        with their defaults; a bad one is refused at its line in the parameter file."""
        try:
            return self.node.params.declare(self.PARAMETERS, only)
        except ParameterError as exc:  # (it names the controller's node)
            place = self.places.key(exc.name) if exc.name in self.node.parameters else ""
            raise ControllerError(self._at(str(exc), place)) from None

    def _at(self, message: str, place: str = "") -> str:
        place = place or self.places.block
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
