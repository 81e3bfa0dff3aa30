"""The base of every controller: a node of its own (named as the controller, in the manager's
namespace, parameters from the manager's files and its `params_file`), ros2_control's
lifecycle (unconfigured → inactive → active), the interfaces it asks for, and `update()`.

A controller that refuses (a missing or wrong parameter) raises ControllerError; the manager
answers the request with `ok: false` and logs the reason, as controller_manager does.
"""

from __future__ import annotations

import math
from typing import Any

from launcher.bus.types import registry
from launcher.bus.wire import split_time
from launcher.control.resources import ACTIVE, INACTIVE, UNCONFIGURED, Handle
from launcher.errors import LaunchError

CONTROLLER_BASE = "controller_interface::ControllerInterface"
_MISSING = object()
_CLASSES: dict[str, type] = {}


class ControllerError(LaunchError):
    pass


class Controller:
    type_name = ""
    base_class = CONTROLLER_BASE

    def __init__(self, name: str, node: Any, where: str = "") -> None:
        self.name, self.node = name, node
        self.where = where  # file:line of its parameters, when known
        self.state = UNCONFIGURED
        self.update_rate = 0  # Hz; 0: the manager's
        self.commands: list[Handle] = []  # claimed, in command_interfaces() order
        self.states: dict[str, Handle] = {}
        self.last_update: float | None = None

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
    def param(self, name: str, default: Any = _MISSING, kind: type | tuple[type, ...] | None = None,
              required: bool = False) -> Any:
        """A parameter of the controller's node (from its YAML), checked against `kind`."""
        values = self.node.parameters
        if name not in values or values[name] is None:
            if required or default is _MISSING:
                raise ControllerError(self._at(f"controller '{self.name}': parameter '{name}' "
                                               f"is required and not set"))
            return default
        value = values[name]
        want = kind if kind is not None else (type(default) if default is not _MISSING and
                                              default is not None else None)
        if want is float and isinstance(value, int) and not isinstance(value, bool):
            return float(value)
        if want is list and isinstance(value, list | tuple):
            return list(value)
        if want is not None and not isinstance(value, want):
            expected = " or ".join(t.__name__ for t in (want if isinstance(want, tuple)
                                                       else (want,)))
            raise ControllerError(self._at(f"controller '{self.name}': parameter '{name}' is "
                                           f"{value!r}; expected {expected}"))
        return value

    def names(self, name: str, required: bool = True) -> list[str]:
        """A list-of-strings parameter (joints, interfaces)."""
        value = self.param(name, [] if not required else _MISSING, list, required=required)
        if not all(isinstance(v, str) for v in value):
            raise ControllerError(self._at(f"controller '{self.name}': parameter '{name}' "
                                           f"must be a list of names, got {value!r}"))
        if required and not value:
            raise ControllerError(self._at(f"controller '{self.name}': parameter '{name}' "
                                           f"is empty"))
        return list(value)

    def _at(self, message: str) -> str:
        return f"{self.where}: {message}" if self.where else message

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
