"""The parameter services every node offers, as ROS 2 nodes do: `~/list_parameters`,
`~/get_parameters`, `~/set_parameters`, `~/describe_parameters` (rcl_interfaces), and Python
values <-> rcl_interfaces/msg/ParameterValue. A set with no value (NOT_SET) deletes."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launcher.bus.messages import build

NOT_SET, BOOL, INTEGER, DOUBLE, STRING = 0, 1, 2, 3, 4
BOOL_ARRAY, INTEGER_ARRAY, DOUBLE_ARRAY, STRING_ARRAY = 6, 7, 8, 9
VALUE = "rcl_interfaces/msg/ParameterValue"
LIST, GET, SET = ("rcl_interfaces/srv/ListParameters", "rcl_interfaces/srv/GetParameters",
                  "rcl_interfaces/srv/SetParameters")
DESCRIBE = "rcl_interfaces/srv/DescribeParameters"
# Their RIHS01 hashes (Jazzy's rcl_interfaces; tests/unit check them against the .srv files):
# with them, a node offers the services without reading their definitions until asked.
HASHES = {
    LIST: "RIHS01_3e6062bfbb27bfb8730d4cef2558221f51a11646d78e7bb30a1e83afac3aad9d",
    GET: "RIHS01_bf9803d5c74cf989a5de3e0c2e99444599a627c7ff75f97b8c05b01003675cbc",
    SET: "RIHS01_56eed9a67e169f9cb6c1f987bc88f868c14a8fc9f743a263bc734c154015d7e0",
    DESCRIBE: "RIHS01_845b484d71eb0673dae682f2e3ba3c4851a65a3dcfb97bddd82c5b57e91e4cff",
}
TYPE_NAMES = {NOT_SET: "not set", BOOL: "boolean", INTEGER: "integer", DOUBLE: "double",
              STRING: "string", 5: "byte array", BOOL_ARRAY: "boolean array",
              INTEGER_ARRAY: "integer array", DOUBLE_ARRAY: "double array",
              STRING_ARRAY: "string array"}


def to_message(value: Any) -> Any:
    if value is None:
        return build(VALUE, {"type": NOT_SET})
    if isinstance(value, bool):
        return build(VALUE, {"type": BOOL, "bool_value": value})
    if isinstance(value, int):
        return build(VALUE, {"type": INTEGER, "integer_value": value})
    if isinstance(value, float):
        return build(VALUE, {"type": DOUBLE, "double_value": value})
    if isinstance(value, list) and value:
        kinds = {bool: (BOOL_ARRAY, "bool_array_value"), int: (INTEGER_ARRAY,
                 "integer_array_value"), float: (DOUBLE_ARRAY, "double_array_value"),
                 str: (STRING_ARRAY, "string_array_value")}
        kind, field = kinds.get(type(value[0]), (STRING_ARRAY, "string_array_value"))
        return build(VALUE, {"type": kind, field: value})
    return build(VALUE, {"type": STRING, "string_value": str(value)})


def from_message(message: Any) -> Any:
    fields = {BOOL: "bool_value", INTEGER: "integer_value", DOUBLE: "double_value",
              STRING: "string_value", BOOL_ARRAY: "bool_array_value",
              INTEGER_ARRAY: "integer_array_value", DOUBLE_ARRAY: "double_array_value",
              STRING_ARRAY: "string_array_value"}
    if message.type not in fields:
        return None
    value = getattr(message, fields[message.type])
    return value.tolist() if hasattr(value, "tolist") else value


def describe(value: Any) -> str:
    """As `ros2 param get` prints it."""
    kind = {bool: "Boolean", int: "Integer", float: "Double", str: "String"}.get(type(value))
    if kind is None:
        return f"Array value is: {value}" if isinstance(value, list) else "Parameter not set."
    return f"{kind} value is: {value}"


def serve(node: Any) -> None:
    """Declare the three parameter services on `node`."""

    def list_parameters(request: Any, response: Any) -> Any:
        names = sorted(n for n in node.parameters
                       if not request.prefixes or any(n.startswith(p) for p in request.prefixes))
        response.result = build("rcl_interfaces/msg/ListParametersResult", {"names": names})
        return response

    def get_parameters(request: Any, response: Any) -> Any:
        values = node.parameters
        response.values = [to_message(values.get(name)) for name in request.names]
        return response

    def set_parameters(request: Any, response: Any) -> Any:
        results = []
        for parameter in request.parameters:
            refused = node.params.request(parameter.name, from_message(parameter.value))
            results.append(build("rcl_interfaces/msg/SetParametersResult",
                                 {"successful": refused is None, "reason": refused or ""}))
        response.results = results
        return response

    def describe_parameters(request: Any, response: Any) -> Any:
        response.descriptors = [build("rcl_interfaces/msg/ParameterDescriptor",
                                      node.params.describe(name)) for name in request.names]
        return response

    node.create_service(LIST, "~/list_parameters", list_parameters, type_hash=HASHES[LIST])
    node.create_service(GET, "~/get_parameters", get_parameters, type_hash=HASHES[GET])
    node.create_service(SET, "~/set_parameters", set_parameters, type_hash=HASHES[SET])
    node.create_service(DESCRIBE, "~/describe_parameters", describe_parameters,
                        type_hash=HASHES[DESCRIBE])


def nested(items: Iterable[tuple[str, Any]]) -> dict[str, Any]:
    """Dotted parameter names and their values as nested maps (`a.b` is `{a: {b: …}}`), as
    a params file and ROS 1's parameter tree have them."""
    tree: dict[str, Any] = {}
    for name, value in items:
        *outer, last = name.split(".")
        level = tree
        for part in outer:
            level = level.setdefault(part, {})
        level[last] = value
    return tree


def type_of(value: Any) -> int:
    """The ParameterValue type number of a Python value."""
    return to_message(value).type if value is not None else NOT_SET
