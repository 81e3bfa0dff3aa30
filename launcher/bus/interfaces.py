"""Message and service definitions from packages: `msg/*.msg` and `srv/*.srv`.

`<pkg>/msg/<Name>` comes from `<pkg>/msg/<Name>.msg`; `<pkg>/srv/<Name>` from
`<pkg>/srv/<Name>.srv`, whose halves become `<Name>_Request` and `<Name>_Response`. A service's
type hash is ROS 2's: over the service type with its request, response and synthesised event
message (whose `char[16] client_gid` is hashed as `uint8[16]`, as ROS 2 does).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launcher.bus import kinds as T
from launcher.errors import LaunchError, Location

EVENT_INFO = "service_msgs/msg/ServiceEventInfo"
TIME = "builtin_interfaces/msg/Time"
EVENT_INFO_FIELDS = ([], [("event_type", (T.BASE, ("uint8", 0))), ("stamp", (T.NAME, TIME)),
                          ("client_gid", (T.ARRAY, ((T.BASE, ("uint8", 0)), 16))),
                          ("sequence_number", (T.BASE, ("int64", 0)))])


def parse_msg(text: str, name: str, file: Path) -> dict[str, Any]:
    from rosbags.typesys import get_types_from_msg  # (only for packages' own definitions)

    try:
        parsed = dict(get_types_from_msg(text, name))
    except Exception as exc:  # rosbags' parser errors carry the reason
        raise LaunchError(f"invalid message definition: {exc}", Location(str(file))) from None
    return parsed


def parse_srv(text: str, name: str, file: Path) -> dict[str, Any]:
    lines = text.splitlines()
    if sum(1 for line in lines if line.strip() == "---") != 1:
        raise LaunchError("a .srv file needs exactly one '---' line between request and "
                          "response", Location(str(file)))
    cut = next(i for i, line in enumerate(lines) if line.strip() == "---")
    # Parsed as pkg/msg/… so that relative names (`ParameterValue`) mean pkg/msg/…, as in
    # ROS 2; then the two halves are filed under pkg/srv/Name_Request and _Response.
    package, _, base = name.split("/")
    out: dict[str, Any] = {}
    for half, text in (("_Request", lines[:cut]), ("_Response", lines[cut + 1:])):
        parsed = parse_msg("\n".join(text), f"{package}/msg/{base}{half}", file)
        for key, value in parsed.items():
            out[f"{name}{half}" if key == f"{package}/msg/{base}{half}" else key] = value
    return out


def service_hash_definitions(name: str) -> dict[str, Any]:
    """The synthesised types ROS 2 hashes a service by (to add to the request/response)."""
    request, response, event = f"{name}_Request", f"{name}_Response", f"{name}_Event"
    return {
        EVENT_INFO: EVENT_INFO_FIELDS,
        event: ([], [("info", (T.NAME, EVENT_INFO)),
                     ("request", (T.SEQUENCE, ((T.NAME, request), 1))),
                     ("response", (T.SEQUENCE, ((T.NAME, response), 1)))]),
        name: ([], [("request_message", (T.NAME, request)),
                    ("response_message", (T.NAME, response)),
                    ("event_message", (T.NAME, event))]),
    }


def find_definition(name: str, package_share: Path) -> tuple[str, Path] | None:
    """('msg'|'srv', file) for `pkg/msg/Name` or `pkg/srv/Name` in the package's folder."""
    _, kind, base = name.split("/")
    path = package_share / kind / f"{base}.{kind}"
    return (kind, path) if kind in ("msg", "srv") and path.is_file() else None
