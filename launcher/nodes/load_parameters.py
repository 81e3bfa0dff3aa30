"""Put a launch's ROS 1 parameters on the graph's parameter server (bus/graph_parameters.py),
as roslaunch sets them on the master: `python -m launcher.nodes.load_parameters FILE`, FILE
JSON the launch wrote privately: `{"before": [roslaunch's `rosparam delete|dump`, as
["delete", name] or ["dump", name, file]], "set": {full ROS 1 name: value}}`, applied in that
order. Waits for the server
(the graph's router, maybe still starting) as long as a node waits for the router; says
so once they are set (the launch then starts its nodes: a failure is this process's error,
and the launch's, and no node starts), and stays on the graph until the launch ends (a
helper: it does not keep the launch running)."""

from __future__ import annotations

import json
import sys

from launcher.bus import discovery
from launcher.bus import graph_parameters as graph
from launcher.bus.node import Node
from launcher.errors import LaunchError, UsageError, report, reported

NAME = "load_parameters"


def main(argv: list[str] | None = None) -> int:
    words = sys.argv[1:] if argv is None else argv
    if "--ros-args" in words:
        words = words[:words.index("--ros-args")]
    if len(words) != 1:
        return report(UsageError(f"usage: python -m launcher.nodes.{NAME} FILE"), NAME)
    return reported(lambda: load(words[0]), NAME)


def load(path: str) -> int:
    try:
        with open(path, encoding="utf-8") as handle:
            document = json.load(handle)
        commands, values = list(document["before"]), dict(document["set"])
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise LaunchError(f"cannot read the launch's parameters from '{path}': "
                          f"{exc}") from None
    node = Node(f"_{NAME}", argv=[], parameter_services=False)
    try:
        server = graph.GraphParameters(node, discovery.timeout())
        for command in commands:
            run(server, node, command)
        if values:
            server.set_many(values)
        count = len(values)
        deleted = sum(command[0] == "delete" for command in commands)
        gone = f", {deleted} deleted" if deleted else ""
        # (the launch reads "set on the graph's parameter server": the helper's work is done)
        node.get_logger().info(f"{count} parameter{'s' if count != 1 else ''} set on the "
                               f"graph's parameter server ({graph.NODE}){gone}")
        # on the graph until the launch ends: the router, and with it the parameters, stay
        # while the launch runs, as roslaunch's master does
        node.spin()
    finally:
        node.destroy_node()
    return 0


def run(server: graph.GraphParameters, node: Node, command: list[str]) -> None:
    """roslaunch's `rosparam delete NAME` or `rosparam dump FILE NAME`, before the launch's
    parameters are set; a name the server does not hold is said, and the launch goes on
    (roslaunch ignores the failing command)."""
    if command[0] == "delete":
        server.delete(command[1], missing_ok=True)
        return
    name, path = command[1], command[2]
    try:
        text = graph.dump_text(server.get(name)) + "\n"
    except graph.Missing:
        node.get_logger().warning(f"rosparam dump: nothing to write to '{path}': [{name}] is "
                                  "not set on the server before the launch's parameters are "
                                  "(roslaunch dumps first)")
        return
    try:
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(text)
    except OSError as exc:
        raise LaunchError(f"rosparam dump: cannot write '{path}': {exc.strerror}") from None


if __name__ == "__main__":
    sys.exit(main())
