"""`launcher action send_goal`: send a goal and wait for its result."""

from __future__ import annotations

import argparse
import os
import threading

import yaml

from launcher.bus import actions as protocol
from launcher.bus.messages import MessageError, build, to_data
from launcher.bus.node import Node
from launcher.bus.types import UnknownType, registry
from launcher.cli.action.lookup import actions_served, listing_text, send_goal_endpoints
from launcher.cli.message_text import message_from
from launcher.errors import LaunchError, UsageError, did_you_mean

FOREVER = 365 * 24 * 3600.0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("name", help="the action (/fibonacci)")
    parser.add_argument("type", help="its type (example_interfaces/action/Fibonacci)")
    parser.add_argument("goal", nargs="?", default="{}", help="the goal as YAML")
    parser.add_argument("-f", "--feedback", action="store_true", help="print the feedback")
    parser.add_argument("--timeout", type=float, default=10.0,
                        help="seconds to wait for a server (default 10)")


def _yaml(message: object) -> str:
    return yaml.safe_dump(to_data(message), sort_keys=False, default_flow_style=False)


def run(args: argparse.Namespace) -> int:
    try:
        action = registry().action(args.type)
    except UnknownType as exc:
        raise UsageError(str(exc)) from None
    try:
        goal = message_from(f"{action}_Goal", args.goal, "goal")
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
        actions = actions_served(send_goal_endpoints())
        raise LaunchError(f"no action server for {name} ({action}) after {args.timeout:g} s"
                          f"{did_you_mean(name, list(actions))}; {listing_text(actions)}")
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
