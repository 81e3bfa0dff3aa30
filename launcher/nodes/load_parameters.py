"""Put a launch's ROS 1 parameters on the graph's parameter server (bus/graph_parameters.py),
as roslaunch sets them on the master: `python -m launcher.nodes.load_parameters FILE`, FILE a
JSON map of full ROS 1 names to values that the launch wrote privately. Waits for the server
(the graph's router, maybe still starting) as long as a node waits for the router; then
writes FILE.loaded, which the launch's nodes wait for before they ask the server (loaded or
not: a failure is this process's error, and the nodes go on), and stays on the graph until
the launch ends (a helper: it does not keep the launch running)."""

from __future__ import annotations

import json
import sys

from launcher.bus import discovery
from launcher.bus import graph_parameters as graph
from launcher.bus.node import Node
from launcher.errors import LaunchError, reported

NAME = "load_parameters"


def main(argv: list[str] | None = None) -> int:
    words = sys.argv[1:] if argv is None else argv
    if "--ros-args" in words:
        words = words[:words.index("--ros-args")]
    if len(words) != 1:
        print(f"usage: python -m launcher.nodes.{NAME} FILE", file=sys.stderr)
        return 2
    return reported(lambda: load(words[0]), NAME)


def load(path: str) -> int:
    try:
        try:
            with open(path, encoding="utf-8") as handle:
                values = json.load(handle)
        except (OSError, ValueError) as exc:
            raise LaunchError(f"cannot read the launch's parameters from '{path}': "
                              f"{exc}") from None
        node = Node(f"_{NAME}", argv=[], parameter_services=False)
    except BaseException:
        graph.mark_loaded(path)  # the nodes need not wait for what will not come
        raise
    try:
        try:
            graph.GraphParameters(node, discovery.timeout()).set_many(values)
        finally:
            graph.mark_loaded(path)
        count = len(values)
        # (the launch reads "set on the graph's parameter server": the helper's work is done)
        node.get_logger().info(f"{count} parameter{'s' if count != 1 else ''} set on the "
                               f"graph's parameter server ({graph.NODE})")
        # on the graph until the launch ends: the router, and with it the parameters, stay
        # while the launch runs, as roslaunch's master does
        node.spin()
    finally:
        node.destroy_node()
    return 0


if __name__ == "__main__":
    sys.exit(main())
