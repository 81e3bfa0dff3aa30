"""Put a launch's ROS 1 parameters on the graph's parameter server (bus/graph_parameters.py),
as roslaunch sets them on the master: `python -m launcher.nodes.load_parameters FILE`, FILE
JSON the launch wrote privately: `{"delete": [names whose trees go], "set": {full ROS 1 name:
value}}`, applied in that order. Waits for the server
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
        try:
            with open(path, encoding="utf-8") as handle:
                document = json.load(handle)
            deletions, values = list(document["delete"]), dict(document["set"])
        except (OSError, ValueError, KeyError, TypeError) as exc:
            raise LaunchError(f"cannot read the launch's parameters from '{path}': "
                              f"{exc}") from None
        node = Node(f"_{NAME}", argv=[], parameter_services=False)
    except BaseException:
        graph.mark_loaded(path)  # the nodes need not wait for what will not come
        raise
    try:
        try:
            server = graph.GraphParameters(node, discovery.timeout())
            for name in deletions:
                server.delete(name, missing_ok=True)
            if values:
                server.set_many(values)
        finally:
            graph.mark_loaded(path)
        count = len(values)
        gone = f", {len(deletions)} deleted" if deletions else ""
        # (the launch reads "set on the graph's parameter server": the helper's work is done)
        node.get_logger().info(f"{count} parameter{'s' if count != 1 else ''} set on the "
                               f"graph's parameter server ({graph.NODE}){gone}")
        # on the graph until the launch ends: the router, and with it the parameters, stay
        # while the launch runs, as roslaunch's master does
        node.spin()
    finally:
        node.destroy_node()
    return 0


if __name__ == "__main__":
    sys.exit(main())
