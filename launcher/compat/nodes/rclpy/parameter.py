"""rclpy.parameter.Parameter: a name, a value and its ROS 2 parameter type."""

from __future__ import annotations

import array
from enum import Enum
from typing import Any

from rclpy.properties import readonly

__all__ = ["PARAMETER_SEPARATOR_STRING", "Parameter", "get_parameter_value",
           "parameter_dict_from_yaml_file", "parameter_value_to_python"]

PARAMETER_SEPARATOR_STRING = "."


class _Type(Enum):
    NOT_SET = 0
    BOOL = 1
    INTEGER = 2
    DOUBLE = 3
    STRING = 4
    BYTE_ARRAY = 5
    BOOL_ARRAY = 6
    INTEGER_ARRAY = 7
    DOUBLE_ARRAY = 8
    STRING_ARRAY = 9

    @classmethod
    def from_parameter_value(cls, value: Any) -> _Type:
        if value is None:
            return cls.NOT_SET
        if isinstance(value, bool):
            return cls.BOOL
        if isinstance(value, int):
            return cls.INTEGER
        if isinstance(value, float):
            return cls.DOUBLE
        if isinstance(value, str):
            return cls.STRING
        if isinstance(value, list | tuple | array.array) or type(value).__name__ == "ndarray":
            items = list(value)
            if isinstance(value, bytes) or all(isinstance(v, bytes) for v in items) and items:
                return cls.BYTE_ARRAY
            if all(isinstance(v, bool) for v in items):
                return cls.BOOL_ARRAY
            if all(isinstance(v, int) and not isinstance(v, bool) for v in items):
                return cls.INTEGER_ARRAY
            if all(isinstance(v, float) for v in items):
                return cls.DOUBLE_ARRAY
            if all(isinstance(v, str) for v in items):
                return cls.STRING_ARRAY
        raise TypeError(f"The given value is not one of the allowed types '{value}'.")

    def check(self, value: Any) -> bool:
        if self == _Type.NOT_SET:
            return value is None
        try:
            return _Type.from_parameter_value(value) == self or (
                self in (_Type.BOOL_ARRAY, _Type.INTEGER_ARRAY, _Type.DOUBLE_ARRAY,
                         _Type.STRING_ARRAY, _Type.BYTE_ARRAY) and len(list(value)) == 0)
        except TypeError:
            return False


class Parameter:
    Type = _Type

    def __init__(self, name: str, type_: Any = None, value: Any = None) -> None:
        if type_ is None:
            type_ = _Type.from_parameter_value(value)
        elif not isinstance(type_, _Type):  # Parameter(name, value) as some code writes it
            if value is None:
                value, type_ = type_, _Type.from_parameter_value(type_)
            else:
                raise TypeError("type must be an instance of 'Parameter.Type'")
        if not type_.check(value):
            raise ValueError(f"Type '{type_}' and value '{value}' do not agree")
        self._name, self._type_, self._value = name, type_, value

    name = readonly("_name", "The parameter's name.")
    type_ = readonly("_type_", "The parameter's Parameter.Type.")
    value = readonly("_value", "The parameter's value.")

    def __repr__(self) -> str:
        return f"Parameter(name={self._name!r}, type_={self._type_}, value={self._value!r})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Parameter) and (self._name, self._type_, self._value) == (
            other._name, other._type_, other._value)

    def get_parameter_value(self) -> Any:
        """The value as an rcl_interfaces/ParameterValue message."""
        from rcl_interfaces.msg import ParameterValue

        value = ParameterValue(type=self._type_.value)
        field = {_Type.BOOL: "bool_value", _Type.INTEGER: "integer_value",
                 _Type.DOUBLE: "double_value", _Type.STRING: "string_value",
                 _Type.BYTE_ARRAY: "byte_array_value", _Type.BOOL_ARRAY: "bool_array_value",
                 _Type.INTEGER_ARRAY: "integer_array_value",
                 _Type.DOUBLE_ARRAY: "double_array_value",
                 _Type.STRING_ARRAY: "string_array_value"}.get(self._type_)
        if field is not None:
            setattr(value, field, list(self._value) if isinstance(self._value, tuple)
                    else self._value)
        return value

    def to_parameter_msg(self) -> Any:
        """The parameter as an rcl_interfaces/Parameter message."""
        from rcl_interfaces.msg import Parameter as Message

        return Message(name=self._name, value=self.get_parameter_value())

    @classmethod
    def from_parameter_msg(cls, message: Any) -> Parameter:
        """A Parameter from an rcl_interfaces/Parameter message."""
        return cls(message.name, value=parameter_value_to_python(message.value))


def get_parameter_value(string_value: str) -> Any:
    """The rcl_interfaces/ParameterValue a string means, its type guessed as YAML reads it
    (a string when it is no valid YAML, a mapping, null or a list of mixed types)."""
    import yaml

    try:
        value = yaml.safe_load(string_value)
    except yaml.YAMLError:
        value = string_value
    if value is None or isinstance(value, dict):
        value = string_value
    try:
        return Parameter("value", value=value).get_parameter_value()
    except (TypeError, ValueError):
        return Parameter("value", value=string_value).get_parameter_value()


def parameter_value_to_python(parameter_value: Any) -> Any:
    """The Python value of an rcl_interfaces/ParameterValue message."""
    value = parameter_value
    kind = _Type(value.type)
    field = {_Type.BOOL: "bool_value", _Type.INTEGER: "integer_value",
             _Type.DOUBLE: "double_value", _Type.STRING: "string_value",
             _Type.BYTE_ARRAY: "byte_array_value", _Type.BOOL_ARRAY: "bool_array_value",
             _Type.INTEGER_ARRAY: "integer_array_value",
             _Type.DOUBLE_ARRAY: "double_array_value",
             _Type.STRING_ARRAY: "string_array_value"}.get(kind)
    if field is None:
        return None
    found = getattr(value, field)
    return list(found) if kind.name.endswith("ARRAY") else found


def parameter_dict_from_yaml_file(parameter_file: str, use_wildcard: bool = False,
                                  target_nodes: list[str] | None = None,
                                  namespace: str = "") -> dict[str, Any]:
    """{name: rcl_interfaces/Parameter} of a ROS 2 parameters file, as rclpy reads it: the
    `ros__parameters` of the target nodes (or of every node), `/**` when `use_wildcard`,
    nested maps flattened with dots."""
    import yaml

    try:
        with open(parameter_file, encoding="utf-8") as handle:
            document = yaml.safe_load(handle)
    except OSError as exc:
        raise FileNotFoundError(f"Parameter file {parameter_file} not found: {exc}") from None
    except yaml.YAMLError as exc:
        raise RuntimeError(f"Failed to parse parameter file {parameter_file}: {exc}") \
            from None
    if not isinstance(document, dict):
        raise RuntimeError(f"Param file {parameter_file} does not contain a map of nodes")
    wanted = None if target_nodes is None else {n.strip("/") for n in target_nodes}
    found: dict[str, Any] = {}
    for node, body in document.items():
        name = str(node).strip("/")
        if namespace:
            name = name.removeprefix(namespace.strip("/") + "/")
        matches = wanted is None or name in wanted or (use_wildcard and name == "**")
        if not matches:
            continue
        if not isinstance(body, dict) or "ros__parameters" not in body:
            raise RuntimeError(f"Param file {parameter_file} does not contain selected "
                               f"parameters for node {node} (no ros__parameters)")
        for key, value in _flatten(body["ros__parameters"] or {}):
            found[key] = Parameter(key, value=value).to_parameter_msg()
    return found


def _flatten(values: dict[str, Any], prefix: str = "") -> list[tuple[str, Any]]:
    out = []
    for key, value in values.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out += _flatten(value, f"{name}.")
        else:
            out.append((name, value))
    return out
