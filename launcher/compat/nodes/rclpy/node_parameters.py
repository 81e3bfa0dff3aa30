"""rclpy's Node's parameters, a part of their own that Node mixes in (as LifecycleNodeMixin
is lifecycle's): declared before use unless `allow_undeclared_parameters`; overrides from
`--ros-args -p`, params files and `parameter_overrides` win over defaults; the set callbacks
(`add_on_set_parameters_callback`, the pre-set and post-set ones) may change or refuse a
change; a change after start goes out on /parameter_events (parameter_events.py).

They live in the bus node's parameter store (`_bus.params`: what `launcher param` and ros2
param list, get and set), which asks the node's gate whether a set from outside is allowed and
its describer what a parameter's descriptor is. The node calls `_init_parameters` as it starts
(its bus node made), and `_start_announcing` once it has started.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from rclpy.exceptions import (
    InvalidParameterException,
    InvalidParameterTypeException,
    ParameterAlreadyDeclaredException,
    ParameterNotDeclaredException,
)
from rclpy.parameter import Parameter

EMPTY_AFTER_PRE_SET = ("parameter list cannot be empty, this might be due to "
                       "pre_set_parameters_callback modifying the original parameters list.")


class ParametersMixin:
    """The parameter methods of rclpy's Node (Node is one of these)."""

    _bus: Any  # the node's bus node (rclpy.node.Node makes it)

    def _init_parameters(self, parameter_overrides: list[Parameter] | None,
                         allow_undeclared: bool, declare_overrides: bool) -> None:
        """The node's parameters at its start: use_sim_time declared (and every override,
        when `declare_overrides`), the bus node's store told to ask this node."""
        self._allow_undeclared = allow_undeclared
        self._overrides: dict[str, Any] = self._bus.parameters
        for parameter in parameter_overrides or []:
            self._overrides[parameter.name] = parameter.value
        self._declared: dict[str, Parameter] = {}
        self._descriptors: dict[str, Any] = {}
        self._set_callbacks: list[Callable[[list[Parameter]], Any]] = []
        self._pre_set_callbacks: list[Callable[[list[Parameter]], Any]] = []
        self._post_set_callbacks: list[Callable[[list[Parameter]], None]] = []
        self._pending_post: list[Parameter] | None = None
        self._events: Any = None  # ParameterEvents, made at the first change after start
        self._announcing = False
        self._bus.params.drop_all()  # what is declared, as rclpy lists it
        self._declare_now("use_sim_time", self._overrides.get("use_sim_time", False))
        if declare_overrides:
            for name, value in self._overrides.items():
                if name not in self._declared:
                    self._declare_now(name, value)
        self._bus.add_on_set_parameters_callback(self._on_bus_set)
        self._bus.params.gate, self._bus.params.describer = self._gate, self._describe_for_bus

    def _start_announcing(self) -> None:
        """The node has started: its changes go out on /parameter_events from now on."""
        self._announcing = True

    def _declare_now(self, name: str, value: Any) -> Parameter:
        parameter = Parameter(name, value=_plain(value))
        self._declared[name] = parameter
        self._bus.params.keep(name, parameter.value)
        return parameter

    def declare_parameter(self, name: str, value: Any = None, descriptor: Any = None,
                          ignore_override: bool = False) -> Parameter:
        """Declare a parameter: an override from the command line or a params file wins
        over `value`.

        :param name: the parameter's name.
        :param value: its default (or a Parameter.Type, for a parameter with no default).
        :param descriptor: a ParameterDescriptor (its type, read_only, ranges, description).
        :param ignore_override: take `value` even when an override was given.
        :return: the declared Parameter.
        """
        if isinstance(value, Parameter.Type):  # declare_parameter(name, Parameter.Type.X)
            value = None
        if name in self._declared:
            raise ParameterAlreadyDeclaredException([name])
        if not name:
            raise InvalidParameterException(name)
        chosen = value if ignore_override or name not in self._overrides else \
            self._overrides[name]
        if value is not None and chosen is not None and not ignore_override and \
                name in self._overrides and _kind(value) != _kind(chosen) and \
                not (descriptor is not None and getattr(descriptor, "dynamic_typing", False)):
            raise InvalidParameterTypeException(Parameter(name, value=_plain(chosen)),
                                                Parameter(name, value=_plain(value)).type_.name)
        if descriptor is not None:
            self._descriptors[name] = descriptor
        declared = self._declare_now(name, chosen)
        self._announce(new=[declared])
        return declared

    def declare_parameters(self, namespace: str, parameters: Sequence[Any],
                           ignore_override: bool = False) -> list[Parameter]:
        """Declare several parameters under `namespace` (each (name, value[, descriptor])).

        :return: the declared Parameters, in order.
        """
        declared = []
        for entry in parameters:
            name, *rest = entry if isinstance(entry, tuple) else (entry,)
            full = f"{namespace}.{name}" if namespace else name
            declared.append(self.declare_parameter(full, *rest[:2],
                                                   ignore_override=ignore_override))
        return declared

    def undeclare_parameter(self, name: str) -> None:
        """Undeclare a parameter (ParameterNotDeclaredException if it was not declared)."""
        if name not in self._declared:
            raise ParameterNotDeclaredException(name)
        self._announce(deleted=[self._declared.pop(name)])
        self._bus.params.drop(name)

    def has_parameter(self, name: str) -> bool:
        """Whether the parameter is declared."""
        return name in self._declared

    def get_parameter(self, name: str) -> Parameter:
        """The declared parameter (ParameterNotDeclaredException if it is not, unless the
        node allows undeclared parameters).
        """
        if name in self._declared:
            return self._declared[name]
        if self._allow_undeclared:
            return Parameter(name, Parameter.Type.NOT_SET, None)
        raise ParameterNotDeclaredException(name)

    def get_parameter_or(self, name: str, alternative_value: Parameter | None = None
                         ) -> Parameter:
        """The parameter, or `alternative_value` when it is not declared."""
        if alternative_value is None:
            alternative_value = Parameter(name, Parameter.Type.NOT_SET)
        return self._declared.get(name, alternative_value)

    def get_parameters(self, names: list[str]) -> list[Parameter]:
        """The parameters of `names`, in order (see get_parameter)."""
        return [self.get_parameter(name) for name in names]

    def get_parameters_by_prefix(self, prefix: str) -> dict[str, Parameter]:
        """The parameters under `prefix.`, by their names after it."""
        start = f"{prefix}." if prefix else ""
        return {name[len(start):]: p for name, p in self._declared.items()
                if name.startswith(start)}

    @property
    def parameters(self) -> dict[str, Parameter]:
        """The declared parameters by name."""
        return dict(self._declared)

    def describe_parameter(self, name: str) -> Any:
        """The parameter's ParameterDescriptor (its declared one, else its name and type)."""
        from rcl_interfaces.msg import ParameterDescriptor

        if name not in self._declared:
            raise ParameterNotDeclaredException(name)
        return self._descriptors.get(name) or ParameterDescriptor(
            name=name, type=self._declared[name].type_.value)

    def add_on_set_parameters_callback(self, callback: Callable[[list[Parameter]], Any]
                                       ) -> Callable[[list[Parameter]], Any]:
        """Add a callback asked before parameters are set: it returns a
        SetParametersResult, and `successful=False` refuses the change.

        :return: the callback (to remove it later).
        """
        self._set_callbacks.insert(0, callback)
        return callback

    def remove_on_set_parameters_callback(self, callback: Any) -> None:
        """Remove a callback added by add_on_set_parameters_callback."""
        self._set_callbacks.remove(callback)

    def set_parameters(self, parameter_list: list[Parameter]) -> list[Any]:
        """Set parameters one at a time: a SetParametersResult for each."""
        return [self.set_parameters_atomically([p]) for p in parameter_list]

    def set_parameters_atomically(self, parameter_list: list[Parameter]) -> Any:
        """Set parameters all together or none: one SetParametersResult."""
        from rcl_interfaces.msg import SetParametersResult

        parameter_list = self._pre_set(list(parameter_list))
        if not parameter_list:
            return SetParametersResult(successful=False, reason=EMPTY_AFTER_PRE_SET)
        for parameter in parameter_list:
            if parameter.name not in self._declared and not self._allow_undeclared:
                raise ParameterNotDeclaredException(parameter.name)
        for callback in self._set_callbacks:
            result = callback(list(parameter_list))
            if result is not None and not result.successful:
                return result
        known = set(self._declared)
        for parameter in parameter_list:
            self._declared[parameter.name] = parameter
            self._bus.params.keep(parameter.name, parameter.value)
        self._announce(new=[p for p in parameter_list if p.name not in known],
                       changed=[p for p in parameter_list if p.name in known])
        self._post_set(parameter_list)
        return SetParametersResult(successful=True)

    # --- rclpy's pre-set (may change the list) and post-set (told what was set) callbacks ---
    def add_pre_set_parameters_callback(self, callback: Callable[[list[Parameter]], Any]
                                        ) -> Callable[[list[Parameter]], Any]:
        """Add a callback that may change the list of parameters about to
        be set (it returns the list to set).

        :return: the callback.
        """
        self._pre_set_callbacks.insert(0, callback)
        return callback

    def remove_pre_set_parameters_callback(self, callback: Any) -> None:
        """Remove a callback added by add_pre_set_parameters_callback."""
        self._pre_set_callbacks.remove(callback)

    def add_post_set_parameters_callback(self, callback: Callable[[list[Parameter]], None]
                                         ) -> Callable[[list[Parameter]], None]:
        """Add a callback told of the parameters once they are set.

        :return: the callback.
        """
        self._post_set_callbacks.insert(0, callback)
        return callback

    def remove_post_set_parameters_callback(self, callback: Any) -> None:
        """Remove a callback added by add_post_set_parameters_callback."""
        self._post_set_callbacks.remove(callback)

    def _pre_set(self, parameters: list[Parameter]) -> list[Parameter]:
        for callback in self._pre_set_callbacks:
            parameters = list(callback(list(parameters)) or [])
        return parameters

    def _post_set(self, parameters: list[Parameter]) -> None:
        for callback in self._post_set_callbacks:
            callback(list(parameters))

    def _gate(self, name: str, value: Any) -> str | None:
        """A set or delete asked from outside, checked as rclcpp/rclpy check it (the declared
        type, read_only, the set callbacks); the reason it is refused, or None."""
        descriptor = self._descriptors.get(name)
        if name not in self._declared and not self._allow_undeclared:
            return f"parameter '{name}' cannot be set because it was not declared"
        if descriptor is not None and descriptor.read_only:
            return f"parameter '{name}' cannot be set because it is read-only"
        dynamic = descriptor is not None and descriptor.dynamic_typing
        if value is None:
            if name in self._declared and not dynamic and not self._allow_undeclared:
                return "cannot undeclare a statically typed parameter"
            gone = self._declared.pop(name, None)
            self._announce(deleted=[gone] if gone is not None else [])
            return None
        parameters = self._pre_set([Parameter(name, value=_plain(value))])
        if not parameters:
            return EMPTY_AFTER_PRE_SET
        for parameter in parameters:
            old = self._declared.get(parameter.name)
            described = self._descriptors.get(parameter.name)
            loose = described is not None and described.dynamic_typing
            if parameter.name not in self._declared and not self._allow_undeclared:
                return (f"parameter '{parameter.name}' cannot be set because it was not "
                        "declared")
            if old is not None and old.type_ != Parameter.Type.NOT_SET and not loose and \
                    old.type_ != parameter.type_:
                return (f"Wrong parameter type, parameter {{{parameter.name}}} is of type "
                        f"{{{old.type_.name.lower()}}}, setting it to "
                        f"{{{parameter.type_.name.lower()}}} is not allowed.")
        for callback in self._set_callbacks:
            result = callback(list(parameters))
            if result is not None and not result.successful:
                return result.reason or "refused by the node's parameter callback"
        self._announce(new=[p for p in parameters if p.name not in self._declared],
                       changed=[p for p in parameters if p.name in self._declared])
        for parameter in parameters:
            self._declared[parameter.name] = parameter
            if parameter.name != name:  # one a pre-set callback added: set here
                self._bus.params.keep(parameter.name, parameter.value)
        self._pending_post = parameters
        return None

    def _announce(self, **parameters: list[Parameter]) -> None:
        """A change after start, on /parameter_events (parameter_events.py)."""
        if not self._announcing or not any(parameters.values()):
            return
        if self._events is None:
            from rclpy.parameter_events import ParameterEvents  # at the first change

            self._events = ParameterEvents(self)
        self._events.announce(**parameters)

    def _describe_for_bus(self, name: str) -> dict[str, Any]:
        """The descriptor as plain fields, with its name and the declared type filled in
        (a ParameterDescriptor made in the node often has neither)."""
        if name not in self._declared:
            return {"name": name, "type": 0}
        fields = _fields(self.describe_parameter(name))
        fields["name"] = fields.get("name") or name
        fields["type"] = fields.get("type") or self._declared[name].type_.value
        return fields

    def _on_bus_set(self, name: str, value: Any) -> None:
        """`launcher param set` (or ros2 param) changed one: the callbacks hear of it."""
        parameter = Parameter(name, value=_plain(value))
        pending, self._pending_post = self._pending_post, None
        if pending is not None and any(p.name == name for p in pending):
            self._post_set(pending)  # (gated: validated and stored already)
            return
        if self._declared.get(name) == parameter:
            return
        self._announce(new=[] if name in self._declared else [parameter],
                       changed=[parameter] if name in self._declared else [])
        self._declared[name] = parameter
        for callback in self._set_callbacks:
            callback([parameter])


def _fields(message: Any) -> Any:
    """A message of rclpy's classes as plain data (dicts and lists)."""
    if hasattr(message, "get_fields_and_field_types"):
        return {f: _fields(getattr(message, f)) for f in message.get_fields_and_field_types()}
    if hasattr(message, "tolist"):
        return message.tolist()
    if isinstance(message, list | tuple):
        return [_fields(m) for m in message]
    return message


def _plain(value: Any) -> Any:
    return list(value) if isinstance(value, tuple) else value


def _kind(value: Any) -> Any:
    try:
        return Parameter.Type.from_parameter_value(_plain(value))
    except TypeError:
        return None
