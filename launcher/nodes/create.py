"""`create`: spawn an entity into a running sim (ros_gz_sim's create, the classic spawner's flags).

  create [-world W] (-file F | -string XML | -param P | -topic T) [-name N | -entity N]
         [-allow_renaming [true|false]] [-x X] [-y Y] [-z Z] [-R ROLL] [-P PITCH] [-Y YAW]
         [-timeout SECONDS] [-keyframe KEY]
The same names work as parameters (`--ros-args -p name:=robot -p topic:=robot_description`).
`-topic` waits for a latched std_msgs/String (robot_state_publisher's robot_description);
`-param P` reads this node's own parameter P. Without `-world`, the one sim on the bus is
used. It waits up to `-timeout` (30 s) for the sim's create service; exit 0 on success, 1 with
the sim's reason, 2 on bad arguments. `-keyframe KEY` (launcher's) starts an MJCF robot's
joints from its `<key name="KEY">`, and every reset of the world puts them back there.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Sequence
from typing import Any

from launcher.arguments import flag_words
from launcher.errors import LaunchError, ParseError, UsageError, did_you_mean, reported
from launcher.records import asdict, dataclass
from launcher.schema import Kind, attr, build, declared_fields, frontend_name

SOURCES = ("file", "string", "param", "topic")


@dataclass
class Options:
    """create's options: ros_gz_sim's flags (`-name`, the classic spawner's `-entity`), the
    same names as `-p` parameters."""

    world: str = attr(Kind.TEXT, "", doc="The world to spawn into (default: the one sim).")
    file: str = attr(Kind.TEXT, "", doc="A description file, model:// or package:// URI.")
    string: str = attr(Kind.TEXT, "", doc="The description itself.")
    param: str = attr(Kind.TEXT, "", doc="A parameter of this node holding it.")
    topic: str = attr(Kind.TEXT, "", doc="A latched std_msgs/String topic holding it.")
    name: str = attr(Kind.TEXT, "", aliases=("entity",))
    allow_renaming: bool = attr(Kind.BOOL, False)
    x: float = attr(Kind.FLOAT, 0.0)
    y: float = attr(Kind.FLOAT, 0.0)
    z: float = attr(Kind.FLOAT, 0.0)
    R: float = attr(Kind.FLOAT, 0.0)
    P: float = attr(Kind.FLOAT, 0.0)
    Y: float = attr(Kind.FLOAT, 0.0)
    timeout: float = attr(Kind.FLOAT, 30.0, minimum=0.0, doc="Seconds to wait for the sim.")
    keyframe: str = attr(Kind.TEXT, "", doc="An MJCF description's keyframe (<key name>) its "
                         "joints start from and every reset returns to (launcher's).")


NAMES = {spelling for f, spec in declared_fields(Options)
         for spelling in (frontend_name(f, spec), *spec.aliases)}


class SimNotFound(LaunchError):
    """No sim answered in time (a runtime error: exit 1)."""


def parse(argv: list[str], parameters: dict[str, Any]) -> dict[str, Any]:
    """The options from `-p` parameters, then the command line's flags over them."""
    values: dict[str, Any] = {k: v for k, v in parameters.items() if k in NAMES}
    for word, words in flag_words(argv, __doc__):
        key = word[1:] if word.startswith("-") else ""
        if key not in NAMES:
            flags = sorted(f"-{name}" for name in NAMES)
            raise UsageError(f"unknown option '{word}'{did_you_mean(word, flags)} (options: "
                             f"{', '.join(flags)})")
        if key == "allow_renaming":  # a flag, or a flag with true/false after it
            lowered = words[0].lower() if words else ""
            values[key] = words.pop(0) if lowered in ("true", "false", "1", "0") else True
            continue
        if not words:
            raise UsageError(f"{word} needs a value")
        values[key] = words.pop(0)
    try:
        options = asdict(build(Options, values))
    except ParseError as exc:
        raise UsageError(f"-{exc.message}") from None
    given = [key for key in SOURCES if options[key]]
    if not given:
        raise UsageError("nothing to spawn: give one of -file, -string, -param or -topic")
    if len(given) > 1:
        raise UsageError(f"give one source, not {', '.join('-' + g for g in given)}")
    options["source"] = given[0]
    return options


def find_world(node: Any, deadline: float, timeout: float, service: str = "create",
               type_name: str = "mujoco_sim/srv/Create", option: str = "-world") -> str:
    """The name of the one world whose `service` is on the bus (waits for it)."""
    from launcher.bus import graph, keys

    while True:
        found = graph.servers(node.graph_session(), "", type_name, 0.5, keys.SIM)
        worlds = sorted({e.topic.split("/")[2] for e in found
                         if e.topic.startswith("/world/") and e.topic.endswith(f"/{service}")})
        if len(worlds) == 1:
            return worlds[0]
        if len(worlds) > 1:
            raise UsageError(f"several sims are running ({', '.join(worlds)}): choose one with "
                             f"{option}")
        if time.monotonic() > deadline:
            raise SimNotFound(f"no sim answered: no /world/<name>/{service} service appeared "
                              f"within {timeout:g} s")
        time.sleep(0.1)


def description(node: Any, options: dict[str, Any], deadline: float) -> tuple[str, str]:
    """(text, file) of what to spawn."""
    source = options["source"]
    if source == "file":
        return "", str(options["file"])
    if source == "string":
        return str(options["string"]), ""
    if source == "param":
        value = node.parameters.get(options["param"])
        if not value:
            raise UsageError(f"-param {options['param']}: this node has no such parameter (set "
                             f"it with --ros-args -p {options['param']}:=…)")
        return str(value), ""
    from launcher.bus.qos import LATCHED

    received: list[str] = []
    node.create_subscription("std_msgs/msg/String", options["topic"],
                             lambda message: received.append(message.data), LATCHED)
    while not received:
        if time.monotonic() > deadline:
            raise SimNotFound(f"nothing arrived on '{node.resolve(options['topic'])}' "
                              "(a latched std_msgs/String, as robot_state_publisher's) "
                              f"within {options.get('timeout', 30.0):g} s")
        node.spin_once(0.1)
    return received[-1], ""


def run(argv: list[str]) -> int:
    from launcher.bus.node import Node

    node = Node("create", argv=argv)
    try:
        return spawn(node)
    except SimNotFound as exc:
        raise SimNotFound(f"{exc.message}; is the sim running? (-timeout sets the wait)") \
            from None
    finally:
        node.destroy_node()


def spawn(node: Any, joints: Sequence[tuple[str, float]] = ()) -> int:
    """Spawn as the node's flags say; `joints` are first joint positions (spawn_model -J)."""
    from launcher.bus import keys
    from launcher.sim.transform import pose_from  # no MuJoCo, no numpy

    options = parse(node.args, node.parameters)
    timeout = float(options.get("timeout", 30.0))
    deadline = time.monotonic() + timeout
    world = options.get("world") or find_world(node, deadline, timeout)
    text, file = description(node, options, deadline)
    client = node.create_client("mujoco_sim/srv/Create", f"/world/{world}/create",
                                space=keys.SIM)
    if not client.wait_for_service(max(0.0, deadline - time.monotonic())):
        raise SimNotFound(f"the sim's /world/{world}/create service did not answer within "
                          f"{timeout:g} s")
    position, quat = pose_from([options.get(k, 0.0) for k in ("x", "y", "z", "R", "P", "Y")])
    request = node.message("mujoco_sim/srv/Create_Request", name=options.get("name", ""),
                           allow_renaming=bool(options.get("allow_renaming", False)),
                           sdf=text, sdf_filename=file,
                           joint_names=[j for j, _ in joints],
                           joint_positions=[float(v) for _, v in joints],
                           keyframe=options.get("keyframe", ""))
    request.pose.position.x, request.pose.position.y, request.pose.position.z = position
    orientation = request.pose.orientation
    orientation.w, orientation.x, orientation.y, orientation.z = quat
    response = client.call(request, timeout=max(10.0, deadline - time.monotonic()))
    if not response.success:
        raise LaunchError(f"the sim refused: {response.message}")
    node.get_logger().info(f"spawned '{response.name}' into world '{world}'")
    return 0


def component() -> Any:
    """create in a component container: it spawns once, from its parameters (`name`, `x`,
    `topic`, …, as its flags), on its own thread, then ends its spin and is unloaded. A
    failure (no sim, a refused spawn) is raised there: the container reports and unloads it."""
    from launcher.bus.node import Node

    node = Node("create")
    parse([], node.parameters)  # bad options are the load's error

    def once() -> None:
        timer.cancel()
        try:
            spawn(node)
        finally:
            node.shutdown()

    timer = node.create_timer(1e-6, once)
    return node


def main() -> int:
    return reported(lambda: run(sys.argv[1:]), "create")


if __name__ == "__main__":
    sys.exit(main())
