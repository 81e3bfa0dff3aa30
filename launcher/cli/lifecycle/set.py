"""`launcher lifecycle set`: take a transition."""

from __future__ import annotations

import argparse

from launcher.cli.lifecycle.client import (
    available_transitions,
    call_node,
    checked_node,
)
from launcher.errors import LaunchError, did_you_mean


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", help="the node")
    parser.add_argument("transition", help="its label (configure, activate, …) or id")


def run(args: argparse.Namespace) -> int:
    node = checked_node(args.node)
    offered = available_transitions(node, False)
    wanted = args.transition
    chosen = [d for d in offered if d.transition.label == wanted or
              str(d.transition.id) == wanted]
    if not chosen:
        state = call_node(node, "get_state", "lifecycle_msgs/srv/GetState").current_state
        names = [d.transition.label for d in offered]
        raise LaunchError(f"Unknown transition requested '{wanted}': {node} is {state.label}, "
                          f"where it offers {', '.join(names) or 'none'}"
                          f"{did_you_mean(wanted, names)}")
    transition = chosen[0].transition
    done = call_node(node, "change_state", "lifecycle_msgs/srv/ChangeState",
                     {"transition": {"id": transition.id, "label": transition.label}})
    if not done.success:
        raise LaunchError(f"Transition {transition.label} of {node} failed (its callback "
                          "returned FAILURE or ERROR; see the node's log)")
    print("Transitioning successful")
    return 0
