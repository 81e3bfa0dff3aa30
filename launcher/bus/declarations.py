"""A node's parameters declared as data, as ros2_controllers declare theirs with
generate_parameter_library: name, type, default, description, bounds, read-only. The
controllers and the built-in nodes declare theirs so (node.params.declare reads them).

One reader checks what the parameter files gave against the declaration (by schema.problem,
the one check of declared values: required, bounds, choices, of a string or of each string of
an array; a ParameterError names the node), fills in the defaults (so `ros2 param list` shows
every one, as a ROS node does) and the node describes each from it (`ros2 param describe`). A
name may hold a placeholder, `gains.{joints}.p`: one parameter for each name of the list (or text)
parameter `joints` declared before it, as generate_parameter_library's `__map_joints` keys."""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import Any, NamedTuple

from launcher.errors import ParameterError
from launcher.schema import problem

REQUIRED: Any = object()
PLACEHOLDER = re.compile(r"\{(\w+)\}")

# rcl_interfaces/msg/ParameterType, by the declaration's type names
TYPES = {"bool": 1, "int": 2, "double": 3, "string": 4, "double_array": 8, "string_array": 9}
_CHECKS: dict[str, Callable[[Any], bool]] = {
    "bool": lambda v: isinstance(v, bool),
    "int": lambda v: isinstance(v, int) and not isinstance(v, bool),
    "double": lambda v: isinstance(v, int | float) and not isinstance(v, bool),
    "string": lambda v: isinstance(v, str),
    "string_array": lambda v: isinstance(v, list | tuple) and all(isinstance(x, str) for x in v),
    "double_array": lambda v: isinstance(v, list | tuple) and
    all(isinstance(x, int | float) and not isinstance(x, bool) for x in v),
}
RCLCPP_NAMES = {0: "not set", 1: "bool", 2: "integer", 3: "double", 4: "string",
                5: "byte_array", 6: "bool_array", 7: "integer_array", 8: "double_array",
                9: "string_array"}  # ParameterValue's types, as rclcpp names them
_EXPECTED = {"bool": "true or false", "int": "a whole number", "double": "a number",
             "string": "text", "string_array": "a list of names",
             "double_array": "a list of numbers"}


class Param(NamedTuple):
    name: str
    type: str  # a key of TYPES
    default: Any = REQUIRED
    description: str = ""
    minimum: float | None = None
    maximum: float | None = None
    read_only: bool = False  # a set from outside is refused, as rclcpp refuses it
    non_empty: bool = False  # an array that must name something
    # the texts a string (each string of an array) may be: generate_parameter_library's one_of
    choices: tuple[str, ...] = ()
    above: float | None = None  # a number must exceed it (> 0: gt<>, not ≥ 0)
    below: float | None = None  # a number must stay under it

    @property
    def required(self) -> bool:
        return self.default is REQUIRED


def expand(declared: tuple[Param, ...], known: dict[str, Any]) -> list[tuple[str, Param]]:
    """(full name, declaration) of each parameter, placeholders filled from `known` (the
    values of the parameters they name; a placeholder not known yet is left as it is)."""
    names = []
    for param in declared:
        keys = PLACEHOLDER.findall(param.name)
        if not keys:
            names.append((param.name, param))
            continue
        filled = [param.name]
        for key in keys:
            value = known.get(key)
            if value is None:
                break
            items = [value] if isinstance(value, str) else list(value)
            filled = [name.replace(f"{{{key}}}", str(item)) for name in filled for item in items]
        else:
            names += [(name, param) for name in filled]
    return names


def read(declared: tuple[Param, ...], values: dict[str, Any], only: tuple[str, ...] = (),
         node: str = "") -> dict[str, Any]:
    """The declared parameters' values (those named in `only`, else all), from `values` (the
    values of `node`, which a ParameterError names), checked and with defaults filled in."""
    found: dict[str, Any] = {}
    chosen = tuple(p for p in declared if not only or p.name in only)
    for param in chosen:
        for name, _ in expand((param,), {**values, **found}):
            found[name] = _one(name, param, values.get(name), node)
    return found


def _one(name: str, param: Param, value: Any, node: str = "") -> Any:
    """`value` checked and typed (None: the default); a ParameterError naming `node`."""
    found = _problem(f"parameter '{name}'", param, value)
    if found:
        raise ParameterError(name, found, node)
    if value is None:
        return list(param.default) if isinstance(param.default, list) else param.default
    return _typed(param.type, value)


def _problem(what: str, param: Param, value: Any) -> str | None:
    if value is not None and not _CHECKS[param.type](value):
        return f"{what}: expected {_EXPECTED[param.type]}, got {value!r}"
    if param.non_empty and value is not None and not value:
        return f"{what} is empty"
    return problem(_typed(param.type, value), param, what)


def _typed(type_name: str, value: Any) -> Any:
    """A value of the declared type as the node reads it: a double a float, an array a list."""
    if value is None or type_name in ("bool", "int", "string"):
        return value
    if type_name == "double":
        return float(value)
    return [float(v) for v in value] if type_name == "double_array" else list(value)


def refusal(name: str, param: Param, value: Any) -> str | None:
    """Why a set from outside of a declared parameter is refused, in rclcpp's words (a value
    of another type, or out of its range), or None."""
    if not _CHECKS[param.type](value):
        from launcher.bus.parameters import type_of

        return (f"Wrong parameter type, parameter {{{name}}} is of type "
                f"{{{RCLCPP_NAMES[TYPES[param.type]]}}}, setting it to "
                f"{{{RCLCPP_NAMES[type_of(value)]}}} is not allowed.")
    try:
        _one(name, param, value)
    except ParameterError as exc:
        if param.type in ("int", "double") and not param.choices:
            kind = "integer" if param.type == "int" else "floating point"
            return f"Parameter {{{name}}} doesn't comply with {kind} range."
        return str(exc)
    return None


def descriptor(name: str, param: Param) -> dict[str, Any]:
    """rcl_interfaces/msg/ParameterDescriptor's fields for a declared parameter (its range
    holds its bounds; an exclusive one on a double is told in words too, as the range's ends
    are valid values)."""
    fields: dict[str, Any] = {"name": name, "type": TYPES[param.type],
                              "description": param.description, "read_only": param.read_only}
    told = [f"one of: {', '.join(param.choices)}"] if param.choices else []
    if param.type != "int":
        told += [f"{words} {bound:g}" for words, bound in (("greater than", param.above),
                                                           ("less than", param.below))
                 if bound is not None]
    if told:
        fields["additional_constraints"] = "; ".join(told)
    return {**fields, **_range(param)}


def _range(param: Param) -> dict[str, Any]:
    low = param.minimum if param.minimum is not None else param.above
    high = param.maximum if param.maximum is not None else param.below
    if low is None and high is None:
        return {}
    if param.type == "int":  # whole numbers: > 0 is ≥ 1
        low = math.floor(low) + 1 if param.minimum is None and low is not None else low
        high = math.ceil(high) - 1 if param.maximum is None and high is not None else high
        return {"integer_range": [{"from_value": int(low) if low is not None else -2**63,
                                   "to_value": int(high) if high is not None else 2**63 - 1,
                                   "step": 0}]}
    return {"floating_point_range": [{"from_value": low if low is not None else -math.inf,
                                      "to_value": high if high is not None else math.inf,
                                      "step": 0.0}]}
