"""`roscore`: the graph and its parameter server, started (or joined, when a launch or another
roscore already runs them; the server holds `/run_id`, `/rosdistro` and `/rosversion` from
its start, as roscore's master does); it prints roscore's summary and stays until Ctrl-C.
The graph's router lives on while other nodes use it, and stops a few seconds after the last
one, as launcher's routers do; its parameters go with the last of them (bus/router.py)."""

from __future__ import annotations

import argparse
import contextlib

from launcher.arguments import Parser


def main(argv: list[str], prog: str = "roscore") -> int:
    p = Parser(prog=prog, description="roscore will start up a ROS Master, a ROS Parameter "
                                      "Server and a rosout logging node (launcher's graph)")
    p.add_argument("-p", "--port", help="master port (accepted: the graph needs none)")
    p.add_argument("-v", dest="verbose", action="store_true", help="verbose printing")
    p.add_argument("-w", "--numworkers", help=argparse.SUPPRESS)
    p.add_argument("-t", "--timeout", help=argparse.SUPPRESS)
    p.parse_args_strictly(argv)

    from launcher.bus import discovery
    from launcher.bus import graph_parameters as graph
    from launcher.bus.node import Node
    from launcher.errors import LaunchError

    joined = discovery.answers(discovery.socket_path())
    discovery.start()
    node = Node("_roscore", argv=[], parameter_services=False)
    try:
        server = graph.GraphParameters(node, 10.0)
        if not server.available(10.0):
            raise LaunchError("the graph's parameter server did not answer within 10 s")
        print(_summary(str(server.get("/run_id")), joined), flush=True)
        with contextlib.suppress(KeyboardInterrupt):  # Ctrl-C ends it cleanly, as roscore's
            node.spin()
    finally:
        node.destroy_node()
    return 0


def _summary(run_id: str, joined: bool) -> str:
    from launcher.bus import discovery
    from launcher.bus.graph_parameters import ROS1_DISTRO, ROS1_VERSION

    where = discovery.socket_path()
    started = (f"joined the running graph at {where}" if joined
               else f"auto-starting new master (the graph's router at {where})")
    return "\n".join([
        "... logging to the graph's router log", "",
        f"ros_comm version {ROS1_VERSION}", "", "",
        "SUMMARY", "========", "",
        "PARAMETERS", f" * /rosdistro: {ROS1_DISTRO}", f" * /rosversion: {ROS1_VERSION}", "",
        "NODES", "", started,
        f"setting /run_id to {run_id}",
        "started core service [/rosout]", ""])
