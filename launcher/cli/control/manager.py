"""The controller manager a `control` verb talks to (`-c/--controller-manager`), and the
calls that only say whether they worked."""

from __future__ import annotations

import argparse
from collections.abc import Callable

from launcher.bus.node import Node
from launcher.errors import LaunchError
from launcher.lifecycle import ACTIVE, INACTIVE, LABELS, UNCONFIGURED
from launcher.nodes.spawner import Manager

CM_WAIT = 5.0


def manager_of(args: argparse.Namespace) -> tuple[Node, Manager]:
    node = Node("_launcher_control", argv=[], parameter_services=False)
    name = args.controller_manager if args.controller_manager.startswith("/") else \
        f"/{args.controller_manager}"
    try:
        return node, Manager(node, name, CM_WAIT, 10.0)
    except LaunchError:
        node.destroy_node()
        raise LaunchError(f"no controller manager '{name}' answers on the graph (waited "
                          f"{CM_WAIT:g} s); is the sim running with the gz_ros2_control "
                          f"plugin, or ros2_control_node? Another name: -c NAME") from None


def on_manager(work: Callable[[Manager, argparse.Namespace], int]
               ) -> Callable[[argparse.Namespace], int]:
    """A verb's run: `work` on the manager -c names, its client node gone after."""
    def run(args: argparse.Namespace) -> int:
        node, manager = manager_of(args)
        try:
            return work(manager, args)
        finally:
            node.destroy_node()
    return run


def state_of(manager: Manager, name: str) -> str:
    for c in manager.call("list_controllers").controller:
        if c.name == name:
            return c.state
    return ""


def simple_call(service: str, field: str, done: str, failed: str
                ) -> Callable[[argparse.Namespace], int]:
    """A verb's run that calls `service` on the name given as `field`, and says how it went."""
    @on_manager
    def run(manager: Manager, args: argparse.Namespace) -> int:
        if not manager.call(service, name=getattr(args, field)).ok:
            raise LaunchError(failed.format(getattr(args, field)))
        print(done.format(getattr(args, field)))
        return 0
    return run


def add_manager_option(parser: argparse.ArgumentParser) -> None:
    """`-c/--controller-manager`, which every verb of `control` takes."""
    parser.add_argument("-c", "--controller-manager", default="/controller_manager",
                        help="name of the controller manager ROS node (default "
                             "/controller_manager)")


def add_state_arguments(parser: argparse.ArgumentParser, name: str, what: str) -> None:
    """NAME STATE [-c MANAGER]: what to take to which lifecycle state."""
    parser.add_argument(name, help=what)
    parser.add_argument("state", choices=[LABELS[s] for s in (UNCONFIGURED, INACTIVE, ACTIVE)],
                        help="the state to take it to")
    add_manager_option(parser)
