"""`launcher action list | info | type | send_goal`, as `ros2 action` has them.

An action is found by its send_goal service (`NAME/_action/send_goal`, typed
`pkg/action/T_SendGoal`): its servers are the nodes serving that, its clients the nodes
calling it. `send_goal` waits for a server (up to `--timeout`, where ros2 waits forever: one
that is not there is an error naming the actions there are), sends the goal, prints the
feedback with `--feedback`, then the result and the status; Ctrl-C cancels the goal first.
"""

from __future__ import annotations

import argparse
import os
import threading

import yaml

from launcher.bus import actions as protocol
from launcher.bus import graph, keys
from launcher.bus.messages import MessageError, build, to_data
from launcher.bus.node import Node
from launcher.bus.session import open_session
from launcher.bus.types import UnknownType, registry
from launcher.errors import LaunchError, UsageError, did_you_mean

SEND_GOAL = protocol.endpoint("", protocol.SEND_GOAL)  # how an action's send_goal name ends
FOREVER = 365 * 24 * 3600.0


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("action", help="actions: list, info, type, send_goal")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="the actions on the graph")
    listing.add_argument("-t", "--show-types", action="store_true",
                         help="each action's type too")
    listing.add_argument("-c", "--count-actions", action="store_true",
                         help="only how many there are")
    listing.set_defaults(run=run_list)
    info = verbs.add_parser("info", help="an action's servers and clients")
    info.add_argument("name", help="the action (/fibonacci)")
    info.add_argument("-t", "--show-types", action="store_true", help="their types too")
    info.add_argument("-c", "--count", action="store_true", help="only how many")
    info.set_defaults(run=run_info)
    kind = verbs.add_parser("type", help="the type of an action")
    kind.add_argument("name", help="the action")
    kind.set_defaults(run=run_type)
    send = verbs.add_parser("send_goal", help="send a goal and wait for its result")
    send.add_argument("name", help="the action (/fibonacci)")
    send.add_argument("type", help="its type (example_interfaces/action/Fibonacci)")
    send.add_argument("goal", nargs="?", default="{}", help="the goal as YAML")
    send.add_argument("-f", "--feedback", action="store_true", help="print the feedback")
    send.add_argument("--timeout", type=float, default=10.0,
                      help="seconds to wait for a server (default 10)")
    send.set_defaults(run=run_send_goal)


# --- the graph ----------------------------------------------------------------------------------
def _endpoints() -> list[keys.Entity]:
    session = open_session("client")
    try:
        return [e for e in graph.entities(session, space=keys.ROS)
                if e.kind in (keys.SERVICE, keys.CLIENT) and e.topic.endswith(SEND_GOAL)]
    finally:
        session.close()


def _actions(found: list[keys.Entity]) -> dict[str, set[str]]:
    """{action name: its types} of the actions that have a server."""
    actions: dict[str, set[str]] = {}
    for entity in found:
        if entity.kind == keys.SERVICE:
            actions.setdefault(entity.topic[:-len(SEND_GOAL)], set()).add(
                entity.type_name.removesuffix("_SendGoal"))
    return actions


def _named(name: str, found: list[keys.Entity]) -> set[str]:
    actions = _actions(found)
    if name not in actions:
        raise LaunchError(f"unknown action '{name}'{did_you_mean(name, list(actions))}; "
                          f"{_listing(actions)}")
    return actions[name]


def _listing(actions: dict[str, set[str]]) -> str:
    return f"the graph's actions: {', '.join(sorted(actions))}" if actions else \
        "the graph has no action servers"


def run_list(args: argparse.Namespace) -> int:
    actions = _actions(_endpoints())
    if args.count_actions:
        print(len(actions))
        return 0
    for name in sorted(actions):
        print(f"{name} [{', '.join(sorted(actions[name]))}]" if args.show_types else name)
    return 0


def run_type(args: argparse.Namespace) -> int:
    for type_name in sorted(_named(args.name, _endpoints())):
        print(type_name)
    return 0


def run_info(args: argparse.Namespace) -> int:
    found = _endpoints()
    types = _named(args.name, found)
    mine = [e for e in found if e.topic == args.name + SEND_GOAL]
    print(f"Action: {args.name}")
    for kind, title in ((keys.CLIENT, "Action clients"), (keys.SERVICE, "Action servers")):
        nodes = sorted({e.node_fqn for e in mine if e.kind == kind})
        print(f"{title}: {len(nodes)}")
        if args.count:
            continue
        for node in nodes:
            print(f"    {node} [{', '.join(sorted(types))}]" if args.show_types
                  else f"    {node}")
    return 0


# --- send_goal ------------------------------------------------------------------------------------
def _yaml(message: object) -> str:
    return yaml.safe_dump(to_data(message), sort_keys=False, default_flow_style=False)


def run_send_goal(args: argparse.Namespace) -> int:
    try:
        action = registry().action(args.type)
    except UnknownType as exc:
        raise UsageError(str(exc)) from None
    try:
        values = yaml.safe_load(args.goal)
    except yaml.YAMLError as exc:
        raise UsageError(f"the goal is not valid YAML: {exc}") from None
    try:
        goal = build(f"{action}_Goal", values)
    except MessageError as exc:
        raise UsageError(f"the goal for {action}: {exc}") from None
    name = args.name if args.name.startswith("/") else f"/{args.name}"
    node = Node("_launcher_action_send_goal", argv=[], parameter_services=False)
    try:
        return _send(node, name, action, goal, args)
    finally:
        node.destroy_node()


def _send(node: Node, name: str, action: str, goal: object, args: argparse.Namespace) -> int:
    send = node.create_client(protocol.send_goal_type(action),
                              protocol.endpoint(name, protocol.SEND_GOAL))
    results = node.create_client(protocol.get_result_type(action),
                                 protocol.endpoint(name, protocol.GET_RESULT))
    goal_id = {"uuid": list(os.urandom(16))}
    early: list[str] | None = []  # feedback that came before the goal's answer, held till it
    lock = threading.Lock()

    def say_feedback(text: str) -> None:
        with lock:
            if early is not None:
                early.append(text)
                return
        print(text, flush=True)
    if args.feedback:
        def on_feedback(message: object) -> None:
            if list(message.goal_id.uuid) == goal_id["uuid"]:  # type: ignore[attr-defined]
                say_feedback(f"Feedback:\n    {_yaml(message.feedback)}")  # type: ignore
        node.create_subscription(protocol.feedback_type(action),
                                 protocol.endpoint(name, protocol.FEEDBACK),
                                 on_feedback, inline=True)
    print("Waiting for an action server to become available...", flush=True)
    if not send.wait_for_service(args.timeout):
        actions = _actions(_endpoints())
        raise LaunchError(f"no action server for {name} ({action}) after {args.timeout:g} s"
                          f"{did_you_mean(name, list(actions))}; {_listing(actions)}")
    print(f"Sending goal:\n     {_yaml(goal)}", flush=True)
    request = build(f"{action}_SendGoal_Request", {"goal_id": goal_id, "goal": to_data(goal)})
    response = send.call(request, args.timeout)
    if not response.accepted:
        print("Goal was rejected.")
        return 0
    print(f"Goal accepted with ID: {bytes(goal_id['uuid']).hex()}\n", flush=True)
    with lock:
        held, early = early or [], None
    for text in held:
        print(text, flush=True)
    outcome: dict[str, object] = {}
    done = threading.Event()

    def wait_for_result() -> None:
        try:
            outcome["result"] = results.call(
                build(f"{action}_GetResult_Request", {"goal_id": goal_id}), FOREVER)
        except LaunchError as exc:
            outcome["error"] = exc
        done.set()
    threading.Thread(target=wait_for_result, daemon=True).start()
    try:
        while not done.wait(0.1):
            pass
    except KeyboardInterrupt:
        _cancel(node, name, goal_id)
        return 130
    if "error" in outcome:
        raise outcome["error"]  # type: ignore[misc]
    result = outcome["result"]
    print(f"Result:\n    {_yaml(result.result)}")  # type: ignore[attr-defined]
    print(f"Goal finished with status: "
          f"{protocol.STATE_NAMES.get(result.status, result.status)}")  # type: ignore[attr-defined]
    return 0


def _cancel(node: Node, name: str, goal_id: dict[str, list[int]]) -> None:
    """Ctrl-C while the goal runs: cancel it, as ros2 action send_goal does."""
    print("Canceling goal...", flush=True)
    cancel = node.create_client(protocol.CANCEL_TYPE,
                                protocol.endpoint(name, protocol.CANCEL_GOAL))
    response = cancel.call(build("action_msgs/srv/CancelGoal_Request",
                                 {"goal_info": {"goal_id": goal_id}}), 5.0)
    canceling = list(response.goals_canceling)
    if not canceling:
        print("Failed to cancel goal")
    elif list(canceling[0].goal_id.uuid) != goal_id["uuid"]:
        print("Canceled goal with incorrect goal ID")
    else:
        print("Goal canceled.")
