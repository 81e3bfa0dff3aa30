"""A node's parameter values and what may change them: the node's own code, a request from
outside (`param set`/`delete`, ros2 param, the ROS 1 parameter server's mirror) that `gate`
may refuse, and parameters declared as data (bus/declarations.py) that `describe` tells."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.bus import declarations
from launcher.bus.declarations import Param
from launcher.errors import LaunchError

_MISSING = object()


class NodeParameters:
    def __init__(self, values: dict[str, Any], owner: str) -> None:
        """`values`: what the command line and parameter files gave the node `owner`."""
        self._values, self.owner = values, owner
        self._listeners: list[Callable[[str, Any], None]] = []
        self._declared: tuple[Param, ...] = ()
        # a client library's node (rclpy's, with its declared types, read-only flags and set
        # callbacks) may refuse a request from outside with a reason, and describe its own
        self.gate: Callable[[str, Any], str | None] | None = None
        self.describer: Callable[[str], dict[str, Any]] | None = None

    @property
    def values(self) -> dict[str, Any]:
        """A copy of every value, by name."""
        return dict(self._values)

    def has(self, name: str) -> bool:
        return name in self._values

    def get(self, name: str) -> Any:
        if name not in self._values:
            raise LaunchError(f"parameter '{name}' is not declared on {self.owner}")
        return self._values[name]

    def default(self, name: str, value: Any) -> Any:
        """The parameter's value, `value` when it has none yet."""
        return self._values.setdefault(name, value)

    def set(self, name: str, value: Any) -> None:
        """Set one parameter and tell the listeners."""
        self._values[name] = value
        for listener in self._listeners:
            listener(name, value)

    def on_set(self, listener: Callable[[str, Any], None]) -> None:
        """`listener(name, value)` hears of every set."""
        self._listeners.append(listener)

    def request(self, name: str, value: Any) -> str | None:
        """Set (or, with None, delete) a parameter as asked from outside; the reason it was
        refused, or None."""
        if self.gate is not None:
            refused = self.gate(name, value)
            if refused:
                return refused
        param = self._declaration(name)
        if param is not None and param.read_only:
            return f"parameter '{name}' cannot be set because it is read-only"
        if param is not None and value is not None:
            refused = declarations.refusal(name, param, value)
            if refused:
                return refused
        if value is None:
            if name not in self._values:
                return f"parameter '{name}' is not set"
            del self._values[name]
            return None
        self.set(name, value)
        return None

    def declare(self, declared: tuple[Param, ...], only: tuple[str, ...] = ()) -> dict[str, Any]:
        """Parameters declared as data (those named in `only`, else all): checked against
        their declarations, their defaults kept as values (listed, as a ROS node lists what it
        declares) and described by `describe`. Declarations add up, as a ROS node's do (a
        name declared again takes its new declaration). A ParameterError, naming the node, for
        the first bad one."""
        names = {param.name for param in declared}
        self._declared = (*(p for p in self._declared if p.name not in names), *declared)
        found = declarations.read(declared, self._values, only, self.owner)
        for name, value in found.items():
            self._values.setdefault(name, value)
        return found

    def describe(self, name: str) -> dict[str, Any]:
        """rcl_interfaces/ParameterDescriptor's fields for a parameter."""
        if self.describer is not None:
            return self.describer(name)
        param = self._declaration(name)
        if param is not None:
            return declarations.descriptor(name, param)
        from launcher.bus.parameters import type_of

        return {"name": name, "type": type_of(self._values.get(name))}

    def _declaration(self, name: str) -> Param | None:
        return next((param for full, param in declarations.expand(self._declared, self._values)
                     if full == name), None)

    def keep(self, name: str, value: Any) -> None:
        """Hold a value without telling the listeners: a client library (rclpy's node) that
        has checked and announced the change itself."""
        self._values[name] = value

    def drop(self, name: str) -> bool:
        """Forget one parameter (undeclared, deleted); False if it was not set."""
        return self._values.pop(name, _MISSING) is not _MISSING

    def drop_all(self) -> None:
        """Forget them all: a client library that lists only what its node declares."""
        self._values.clear()
