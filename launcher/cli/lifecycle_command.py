"""`launcher lifecycle nodes | list | get | set`, as `ros2 lifecycle` has them: the nodes that
serve `~/get_state`, their state, the transitions they offer, and a transition asked for by
label (`configure`, `activate`, …) or id. One that is not allowed from the node's state is an
error naming the ones that are."""

from __future__ import annotations

import argparse

from launcher.bus import graph, keys
from launcher.bus.messages import build
from launcher.bus.node import Node
from launcher.bus.session import open_session
from launcher.errors import LaunchError, did_you_mean

GET_STATE = "/get_state"


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("lifecycle", help="lifecycle nodes: nodes, list, get, set")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    nodes = verbs.add_parser("nodes", help="the lifecycle nodes on the graph")
    nodes.set_defaults(run=run_nodes)
    listing = verbs.add_parser("list", help="the transitions a node offers now")
    listing.add_argument("node", help="the node (/lc_talker)")
    listing.add_argument("-a", "--all", action="store_true", help="every transition")
    listing.set_defaults(run=run_list)
    get = verbs.add_parser("get", help="a node's state")
    get.add_argument("node", nargs="?", help="the node (all of them without)")
    get.set_defaults(run=run_get)
    change = verbs.add_parser("set", help="take a transition")
    change.add_argument("node", help="the node")
    change.add_argument("transition", help="its label (configure, activate, …) or id")
    change.set_defaults(run=run_set)


def _lifecycle_nodes() -> list[str]:
    session = open_session("client")
    try:
        return sorted({e.topic[:-len(GET_STATE)] for e in graph.entities(session,
                                                                         space=keys.ROS)
                       if e.kind == keys.SERVICE and e.topic.endswith(GET_STATE) and
                       e.type_name == "lifecycle_msgs/srv/GetState"})
    finally:
        session.close()


def _checked(name: str) -> str:
    known = _lifecycle_nodes()
    node = name if name.startswith("/") else f"/{name}"
    if node not in known:
        raise LaunchError(f"Node not found: '{node}' is not a lifecycle node on the graph"
                          f"{did_you_mean(node, known)}; lifecycle nodes: "
                          f"{', '.join(known) or 'none'}")
    return node


def _call(node: str, service: str, type_name: str, values: dict | None = None) -> object:
    client_node = Node("_launcher_lifecycle", argv=[], parameter_services=False)
    try:
        client = client_node.create_client(type_name, f"{node}/{service}")
        return client.call(build(f"{type_name}_Request", values or {}), 5.0)
    finally:
        client_node.destroy_node()


def run_nodes(args: argparse.Namespace) -> int:
    for node in _lifecycle_nodes():
        print(node)
    return 0


def run_get(args: argparse.Namespace) -> int:
    for node in [_checked(args.node)] if args.node else _lifecycle_nodes():
        state = _call(node, "get_state", "lifecycle_msgs/srv/GetState").current_state
        prefix = f"{node}: " if not args.node else ""
        print(f"{prefix}{state.label} [{state.id}]")
    return 0


def _transitions(node: str, everything: bool) -> list[object]:
    service = "get_transition_graph" if everything else "get_available_transitions"
    return list(_call(node, service, "lifecycle_msgs/srv/GetAvailableTransitions")
                .available_transitions)


def run_list(args: argparse.Namespace) -> int:
    node = _checked(args.node)
    for d in _transitions(node, args.all):
        print(f"- {d.transition.label} [{d.transition.id}]\n"
              f"\tStart: {d.start_state.label}\n\tGoal: {d.goal_state.label}")
    return 0


def run_set(args: argparse.Namespace) -> int:
    node = _checked(args.node)
    offered = _transitions(node, False)
    wanted = args.transition
    chosen = [d for d in offered if d.transition.label == wanted or
              str(d.transition.id) == wanted]
    if not chosen:
        state = _call(node, "get_state", "lifecycle_msgs/srv/GetState").current_state
        names = [d.transition.label for d in offered]
        raise LaunchError(f"Unknown transition requested '{wanted}': {node} is {state.label}, "
                          f"where it offers {', '.join(names) or 'none'}"
                          f"{did_you_mean(wanted, names)}")
    transition = chosen[0].transition
    done = _call(node, "change_state", "lifecycle_msgs/srv/ChangeState",
                 {"transition": {"id": transition.id, "label": transition.label}})
    if not done.success:
        raise LaunchError(f"Transition {transition.label} of {node} failed (its callback "
                          "returned FAILURE or ERROR; see the node's log)")
    print("Transitioning successful")
    return 0
