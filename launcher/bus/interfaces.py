"""Message, service and action definitions from packages: `msg/*.msg`, `srv/*.srv` and
`action/*.action`.

`<pkg>/msg/<Name>` comes from `<pkg>/msg/<Name>.msg`; `<pkg>/srv/<Name>` from
`<pkg>/srv/<Name>.srv`, whose halves become `<Name>_Request` and `<Name>_Response`. A service's
type hash is ROS 2's: over the service type with its request, response and synthesised event
message (whose `char[16] client_gid` is hashed as `uint8[16]`, as ROS 2 does).
`<pkg>/action/<Name>` comes from `<pkg>/action/<Name>.action`, expanded as rosidl expands it:
`<Name>_Goal`, `_Result` and `_Feedback`; the services `<Name>_SendGoal` (goal id and goal →
accepted and stamp) and `<Name>_GetResult` (goal id → status and result); the message
`<Name>_FeedbackMessage` (goal id and feedback). An error in a definition is at its
file:line:column. A field's default value (`uint64 steps 1`), which rosbags' parser reads past,
is kept in DEFAULTS under the type's name, what a new message of the type starts with (as
rosidl's generated classes do).
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


UUID = "unique_identifier_msgs/msg/UUID"
ACTION_PARTS = ("_Goal", "_Result", "_Feedback")
# the names an action's parts take, longest first (what is stripped to find the action)
ACTION_SUFFIXES = ("_FeedbackMessage", "_SendGoal", "_GetResult", *ACTION_PARTS)


DEFAULTS: dict[str, dict[str, Any]] = {}  # type -> field -> its default value
_FALSE, _TRUE = ("false", "0"), ("true", "1")


def parse_msg(text: str, name: str, file: Path, first_line: int = 1) -> dict[str, Any]:
    from rosbags.typesys import get_types_from_msg  # (only for packages' own definitions)

    try:
        parsed = dict(get_types_from_msg(text, name))
    except Exception as exc:  # rosbags' parser errors carry the reason and the offset
        where, line = _where(str(exc), text, name, file, first_line)
        raise LaunchError(f"invalid message definition: cannot read '{line.strip()}' "
                          f"(expected a field `TYPE NAME [DEFAULT]` or a constant "
                          f"`TYPE NAME=VALUE`)" if line else
                          f"invalid message definition: {exc}", where) from None
    found = field_defaults(text, file, first_line)
    if found:
        DEFAULTS[name] = found
    else:
        DEFAULTS.pop(name, None)
    return parsed


def field_defaults(text: str, file: Path, first_line: int = 1) -> dict[str, Any]:
    """The fields of a definition that have a default value (`TYPE NAME VALUE`), as values."""
    found: dict[str, Any] = {}
    for number, line in enumerate(text.splitlines(), first_line):
        words = _uncommented(line).split(None, 2)
        if len(words) < 3 or "=" in words[1] or words[2].startswith("="):
            continue  # no default, or a constant
        kind, field, written = words[0], words[1], words[2].strip()
        try:
            found[field] = _default_value(kind, written)
        except ValueError:
            raise LaunchError(f"invalid default value '{written}' for {kind} {field} "
                              f"(expected {_expected(kind)})", Location(str(file), number)) \
                from None
    return found


def _expected(kind: str) -> str:
    base = kind.split("[")[0].split("<=")[0]
    one = {"bool": "true or false", "float32": "a number", "float64": "a number",
           "string": "a string", "wstring": "a string"}.get(base, "a whole number")
    return f"[{one}, …]" if "[" in kind else one


def _uncommented(line: str) -> str:
    quote = ""
    for index, char in enumerate(line):
        if quote:
            quote = "" if char == quote else quote
        elif char in "\"'":
            quote = char
        elif char == "#":
            return line[:index]
    return line


def _default_value(kind: str, written: str) -> Any:
    base = kind.split("[")[0].split("<=")[0].split("/")[-1]
    if "[" not in kind:
        return _scalar(base, written)
    if not (written.startswith("[") and written.endswith("]")):
        raise ValueError(written)
    inner = written[1:-1].strip()
    items = [] if not inner else _items(inner)
    return [_scalar(base, item.strip()) for item in items]


def _items(text: str) -> list[str]:
    items, current, quote = [], "", ""
    for char in text:
        if quote:
            quote = "" if char == quote else quote
        elif char in "\"'":
            quote = char
        elif char == ",":
            items.append(current)
            current = ""
            continue
        current += char
    items.append(current)
    return items


def _scalar(base: str, written: str) -> Any:
    if base in ("string", "wstring"):
        if len(written) >= 2 and written[0] == written[-1] and written[0] in "\"'":
            return written[1:-1]
        return written
    if base == "bool":
        if written.lower() in _TRUE:
            return True
        if written.lower() in _FALSE:
            return False
        raise ValueError(written)
    if base in ("float32", "float64"):
        return float(written)
    return int(written, 0)


def _renamed_defaults(old: str, new: str) -> None:
    if old in DEFAULTS:
        DEFAULTS[new] = DEFAULTS.pop(old)


def _where(reason: str, text: str, name: str, file: Path, first_line: int
           ) -> tuple[Location, str]:
    """The file:line:column of a rosbags parse error in `text`, and that line's text."""
    import re

    found = re.search(r"\n(\d+)\n", reason)
    if found is None:
        return Location(str(file), first_line), ""
    offset = int(found.group(1)) - len(f"MSG: {name}\n")  # (rosbags parses it so headed)
    offset = min(max(offset, 0), len(text))
    start = text.rfind("\n", 0, offset) + 1
    end = text.find("\n", offset)
    return (Location(str(file), first_line + text.count("\n", 0, offset), offset - start + 1),
            text[start:end if end >= 0 else len(text)])


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
    for half, text, first in (("_Request", lines[:cut], 1),
                              ("_Response", lines[cut + 1:], cut + 2)):
        parsed = parse_msg("\n".join(text), f"{package}/msg/{base}{half}", file, first)
        _renamed_defaults(f"{package}/msg/{base}{half}", f"{name}{half}")
        for key, value in parsed.items():
            out[f"{name}{half}" if key == f"{package}/msg/{base}{half}" else key] = value
    return out


def parse_action(text: str, name: str, file: Path) -> dict[str, Any]:
    """An `.action` file (goal, result and feedback, between two `---` lines), expanded as
    rosidl expands it (see the module text)."""
    lines = text.splitlines()
    cuts = [i for i, line in enumerate(lines) if line.strip() == "---"]
    if len(cuts) != 2:
        raise LaunchError(f"an .action file needs exactly two '---' lines (goal, result, "
                          f"feedback), found {len(cuts)}",
                          Location(str(file), cuts[2] + 1 if len(cuts) > 2 else 0))
    package, _, base = name.split("/")
    sections = ((lines[:cuts[0]], 1), (lines[cuts[0] + 1:cuts[1]], cuts[0] + 2),
                (lines[cuts[1] + 1:], cuts[1] + 2))
    out: dict[str, Any] = {}
    for part, (section, first) in zip(ACTION_PARTS, sections, strict=True):
        parsed = parse_msg("\n".join(section), f"{package}/msg/{base}{part}", file, first)
        _renamed_defaults(f"{package}/msg/{base}{part}", f"{name}{part}")
        for key, value in parsed.items():
            out[f"{name}{part}" if key == f"{package}/msg/{base}{part}" else key] = value
    out.update(action_definitions(name))
    return out


def action_definitions(name: str) -> dict[str, Any]:
    """The services and message rosidl adds to an action's goal, result and feedback."""
    goal_id = ("goal_id", (T.NAME, UUID))
    return {
        f"{name}_SendGoal_Request": ([], [goal_id, ("goal", (T.NAME, f"{name}_Goal"))]),
        f"{name}_SendGoal_Response": ([], [("accepted", (T.BASE, ("bool", 0))),
                                           ("stamp", (T.NAME, TIME))]),
        f"{name}_GetResult_Request": ([], [goal_id]),
        f"{name}_GetResult_Response": ([], [("status", (T.BASE, ("int8", 0))),
                                            ("result", (T.NAME, f"{name}_Result"))]),
        f"{name}_FeedbackMessage": ([], [goal_id,
                                         ("feedback", (T.NAME, f"{name}_Feedback"))]),
    }


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
    """('msg'|'srv'|'action', file) for `pkg/msg/Name`, `pkg/srv/Name` or `pkg/action/Name`
    in the package's folder."""
    _, kind, base = name.split("/")
    path = package_share / kind / f"{base}.{kind}"
    return (kind, path) if kind in ("msg", "srv", "action") and path.is_file() else None


ROS1_ACTION_SUFFIXES = ("ActionGoal", "ActionResult", "ActionFeedback", "Action", "Goal",
                        "Result", "Feedback")


def ros1_spelling(name: str) -> str:
    """`pkg/msg/Name` as ROS 1 writes a type, `pkg/Name`; any other name as it is."""
    parts = name.split("/")
    return f"{parts[0]}/{parts[-1]}" if len(parts) == 3 else name


def ros1_action_base(name: str) -> tuple[str, str] | None:
    """(package, action) when `pkg/msg/<X><suffix>` names one of the messages ROS 1's
    genaction makes of `action/<X>.action`; None otherwise."""
    package, kind, base = name.split("/")
    if kind != "msg":
        return None
    for suffix in ROS1_ACTION_SUFFIXES:
        if base.endswith(suffix) and len(base) > len(suffix):
            return package, base[:-len(suffix)]
    return None


def parse_ros1_action(text: str, package: str, action: str, file: Path) -> dict[str, Any]:
    """An `.action` file as ROS 1's genaction expands it, into `pkg/msg/` messages:
    `<X>Goal`, `<X>Result`, `<X>Feedback`; `<X>ActionGoal` (header, actionlib_msgs GoalID,
    goal), `<X>ActionResult` and `<X>ActionFeedback` (header, GoalStatus, result or
    feedback), and `<X>Action` holding the three (what actionlib's Python takes)."""
    name = f"{package}/action/{action}"
    parsed = parse_action(text, name, file)
    out: dict[str, Any] = {}
    for part in ACTION_PARTS:
        out[f"{package}/msg/{action}{part[1:]}"] = parsed[f"{name}{part}"]
        _renamed_defaults(f"{name}{part}", f"{package}/msg/{action}{part[1:]}")
    out.update({k: v for k, v in parsed.items() if not k.startswith(name)})
    header = ("header", (T.NAME, "std_msgs/msg/Header"))
    status = ("status", (T.NAME, "actionlib_msgs/msg/GoalStatus"))
    m = f"{package}/msg/{action}"
    out[f"{m}ActionGoal"] = ([], [header, ("goal_id", (T.NAME, "actionlib_msgs/msg/GoalID")),
                                  ("goal", (T.NAME, f"{m}Goal"))])
    out[f"{m}ActionResult"] = ([], [header, status, ("result", (T.NAME, f"{m}Result"))])
    out[f"{m}ActionFeedback"] = ([], [header, status,
                                      ("feedback", (T.NAME, f"{m}Feedback"))])
    out[f"{m}Action"] = ([], [("action_goal", (T.NAME, f"{m}ActionGoal")),
                              ("action_result", (T.NAME, f"{m}ActionResult")),
                              ("action_feedback", (T.NAME, f"{m}ActionFeedback"))])
    return out
