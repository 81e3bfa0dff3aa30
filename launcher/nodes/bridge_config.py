"""parameter_bridge's configuration: ros_gz's bridge.yaml schema and its command-line form.

YAML: a list of entries. Topics: `topic_name` (both sides) or `ros_topic_name` /
`gz_topic_name` (either alone names both), `ros_type_name`, `gz_type_name` (both required),
`direction` (BIDIRECTIONAL, GZ_TO_ROS, ROS_TO_GZ), `lazy`, `subscriber_queue`,
`publisher_queue`. Services: `service_name`, `ros_type_name`, `gz_req_type_name`,
`gz_rep_type_name`. `sim_*` keys are accepted for `gz_*` ones. The keys are declared once
(TopicKeys, ServiceKeys) and checked by launcher's one record builder. The file may be a jinja2
template, rendered with the node's parameters. A bad entry is reported with its file, line
and number and skipped (a type neither side knows: at its key's line and column, with "did you
mean"); an empty file or a top level that is not a list is an error.

Command line: `topic@ROS_TYPE@SIM_TYPE` (both ways), `[` (sim → ROS), `]` (ROS → sim); a ROS
type with `/srv/` makes a service.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError
from launcher.records import dataclass
from launcher.schema import Kind, attr, build
from launcher.user_files import read_text

DIRECTIONS = ("BIDIRECTIONAL", "GZ_TO_ROS", "ROS_TO_GZ")


@dataclass
class TopicKeys:
    """A topic entry of bridge.yaml, as ros_gz reads it."""

    topic_name: str | None = attr(Kind.TEXT, doc="The topic on both sides.")
    ros_topic_name: str | None = attr(Kind.TEXT, doc="The ROS side (alone: both sides).")
    gz_topic_name: str | None = attr(Kind.TEXT, aliases=("sim_topic_name",),
                                     doc="The sim side (alone: both sides).")
    ros_type_name: str = attr(Kind.TEXT, "", required=True)
    gz_type_name: str = attr(Kind.TEXT, "", required=True, aliases=("sim_type_name",))
    direction: str = attr(Kind.TEXT, "BIDIRECTIONAL", choices=DIRECTIONS)
    lazy: bool = attr(Kind.BOOL, False,
                      doc="Subscribe to the source only while the destination is heard.")
    subscriber_queue: int = attr(Kind.INT, 10, minimum=1)
    publisher_queue: int = attr(Kind.INT, 10, minimum=1)


@dataclass
class ServiceKeys:
    """A service entry of bridge.yaml."""

    service_name: str = attr(Kind.TEXT, "", required=True)
    ros_type_name: str = attr(Kind.TEXT, "", required=True)
    gz_req_type_name: str = attr(Kind.TEXT, "", required=True, aliases=("sim_req_type_name",))
    gz_rep_type_name: str = attr(Kind.TEXT, "", required=True, aliases=("sim_rep_type_name",))


@dataclass
class Entry:
    ros_name: str
    sim_name: str
    ros_type: str
    sim_type: str  # a service: the sim's service type
    direction: str = "BIDIRECTIONAL"
    lazy: bool = False
    subscriber_queue: int = 10
    publisher_queue: int = 10
    service: bool = False
    where: str = ""


@dataclass(frozen=True)
class Types:
    """How a type name becomes the bus's: each raises a LaunchError for one it does not know."""

    sim: Callable[[str], str]
    ros: Callable[[str], str]


def parse_entry(raw: Any, where: str, types: Types,
                places: Mapping[str, str] | None = None) -> Entry:
    """One entry at `where`; `places` says where each key's value is, in the same form."""
    def typed(check: Callable[[str], str], key: str, name: str) -> str:
        try:
            return check(name)
        except LaunchError as exc:
            raise LaunchError(f"{(places or {}).get(key, where)}: {key}: {exc.message}") \
                from None

    if not isinstance(raw, Mapping):
        raise LaunchError(f"{where}: an entry must be a mapping of keys, got "
                          f"{type(raw).__name__}")
    if "service_name" in raw:
        service = build(ServiceKeys, raw, where)
        return Entry(service.service_name, service.service_name, service.ros_type_name,
                     typed(types.sim, "gz_req_type_name",
                           f"{service.gz_req_type_name}|{service.gz_rep_type_name}"),
                     service=True, where=where)
    values = dict(raw)
    if isinstance(values.get("direction"), str):  # ros_gz reads it in any case
        values["direction"] = values["direction"].upper()
    keys = build(TopicKeys, values, where)
    if keys.topic_name and (keys.ros_topic_name or keys.gz_topic_name):
        raise LaunchError(f"{where}: topic_name names both sides; it cannot be combined with "
                          "ros_topic_name or gz_topic_name")
    ros_name = keys.topic_name or keys.ros_topic_name or keys.gz_topic_name
    sim_name = keys.topic_name or keys.gz_topic_name or keys.ros_topic_name
    if not ros_name or not sim_name:
        raise LaunchError(f"{where}: no topic: give topic_name, or ros_topic_name and/or "
                          "gz_topic_name")
    return Entry(ros_name, sim_name, typed(types.ros, "ros_type_name", keys.ros_type_name),
                 typed(types.sim, "gz_type_name", keys.gz_type_name), keys.direction, keys.lazy,
                 keys.subscriber_queue, keys.publisher_queue, where=where)


def load_file(path: str, parameters: Mapping[str, Any], types: Types,
              report: Callable[[str], None]) -> tuple[list[Entry], int]:
    """The entries of a config file, and how many it has: bad ones are reported and left
    out."""
    import yaml

    file = Path(path)
    if not file.is_file():
        raise LaunchError(f"bridge config file '{path}' does not exist")
    text = read_text(file)
    if file.name.endswith(".j2") or "{{" in text or "{%" in text:
        text = _render(text, file, parameters)
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml's, where PyYAML has it
    try:
        document = yaml.compose(text, Loader=loader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        line = f":{mark.line + 1}:{mark.column + 1}" if mark else ""
        raise LaunchError(f"{path}{line}: not valid YAML: "
                          f"{getattr(exc, 'problem', None) or exc}") from None
    if document is None:
        raise LaunchError(f"{path}: the bridge config is empty; expected a list of entries")
    if not isinstance(document, yaml.SequenceNode):
        raise LaunchError(f"{path}:{document.start_mark.line + 1}: the top level must be a "
                          "list of entries (each starting with '- ')")
    entries = []
    construct = yaml.SafeLoader("").construct_object  # (values from the nodes composed once)
    for number, node in enumerate(document.value, 1):
        where = f"{path}:{node.start_mark.line + 1}: entry {number}"
        try:
            raw = construct(node, deep=True)
            entries.append(parse_entry(raw, where, types, _places(path, node, number)))
        except LaunchError as exc:
            report(f"{exc}; skipped")
    return entries, len(document.value)


def _places(path: str, node: Any, number: int) -> dict[str, str]:
    """Where each key's value of entry `number` (a mapping node) is."""
    import yaml

    pairs = node.value if isinstance(node, yaml.MappingNode) else []
    return {str(key.value): f"{path}:{value.start_mark.line + 1}:"
                            f"{value.start_mark.column + 1}: entry {number}"
            for key, value in pairs}


@functools.lru_cache(maxsize=32)
def _template(text: str) -> Any:
    """A config's template, compiled once per text (one file serves every robot's bridge)."""
    import jinja2

    environment = jinja2.Environment(undefined=jinja2.StrictUndefined,
                                     keep_trailing_newline=True)
    return environment.from_string(text)


def _render(text: str, file: Path, parameters: Mapping[str, Any]) -> str:
    import jinja2

    try:
        return _template(text).render(**parameters)
    except jinja2.UndefinedError as exc:
        raise LaunchError(f"{file}: template error: {exc.message}; give it as a parameter "
                          "of the bridge (-p NAME:=VALUE)") from None
    except jinja2.TemplateSyntaxError as exc:
        raise LaunchError(f"{file}:{exc.lineno}: template syntax error: {exc.message}") \
            from None


def parse_argument(text: str, types: Types) -> Entry:
    """`topic@ROS_TYPE@SIM_TYPE`, with `[` or `]` for one direction."""
    name, _, rest = text.partition("@")
    if rest.count("@") == 1:
        (ros_type, sim), direction = rest.split("@"), "BIDIRECTIONAL"
    elif "@" not in rest and ("[" in rest) != ("]" in rest):
        separator = "[" if "[" in rest else "]"
        ros_type, sim = rest.split(separator, 1)
        direction = "GZ_TO_ROS" if separator == "[" else "ROS_TO_GZ"
    else:
        raise LaunchError(f"bridge argument '{text}': expected TOPIC@ROS_TYPE@SIM_TYPE (or "
                          "TOPIC@ROS_TYPE[SIM_TYPE for sim to ROS, ] for ROS to sim)")
    if not (name and ros_type and sim):
        raise LaunchError(f"bridge argument '{text}': the topic and both types are needed")
    where = f"argument '{text}'"
    if "/srv/" in ros_type:
        return Entry(name, name, ros_type, _checked(types.sim, f"{sim}|", where), service=True,
                     where=where)
    return Entry(name, name, _checked(types.ros, ros_type, where),
                 _checked(types.sim, sim, where), direction, where=where)


def _checked(check: Callable[[str], str], name: str, where: str) -> str:
    try:
        return check(name)
    except LaunchError as exc:
        raise LaunchError(f"{where}: {exc.message}") from None
