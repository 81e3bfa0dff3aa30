"""`launcher control VERB`: ros2controlcli's verbs against a controller manager, printed as
`ros2 control` prints them: list_controllers, list_controller_types,
list_hardware_interfaces, list_hardware_components, load_controller, set_controller_state,
switch_controllers, unload_controller, set_hardware_component_state, cleanup_controller,
reload_controller_libraries and view_controller_chains.

`-c/--controller-manager` names the manager (default /controller_manager). A manager that
is not on the graph is an error after CM_WAIT seconds. view_controller_chains writes
`controller_diagram.gv` and, with graphviz's `dot`, `controller_diagram.gv.pdf` in the
current folder (ROS 2 writes them into the shared /tmp) and prints where.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

from launcher.bus.node import Node
from launcher.errors import LaunchError
from launcher.nodes.spawner import Manager, type_from

CM_WAIT = 5.0
STATES = {1: "unconfigured", 2: "inactive", 3: "active", 4: "finalized"}


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("control", help="ros2_control's controller manager")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)

    def verb(name: str, help_text: str, run: Any) -> argparse.ArgumentParser:
        sub = verbs.add_parser(name, help=help_text)
        sub.add_argument("-c", "--controller-manager", default="/controller_manager",
                         help="name of the controller manager ROS node (default "
                              "/controller_manager)")
        sub.set_defaults(run=run)
        return sub

    listing = verb("list_controllers", "the loaded controllers, their type and state",
                   run_list_controllers)
    for flag, text in (("--claimed-interfaces", "each one's claimed interfaces"),
                       ("--required-state-interfaces", "the state interfaces each needs"),
                       ("--required-command-interfaces", "the command interfaces each needs"),
                       ("--chained-interfaces", "the interfaces each is chained to"),
                       ("--reference-interfaces", "the references each exports (deprecated "
                                                  "in ROS 2: --exported-interfaces)"),
                       ("--exported-interfaces", "the state and reference interfaces each "
                                                 "exports")):
        listing.add_argument(flag, action="store_true", help=text)
    listing.add_argument("-v", "--verbose", action="store_true",
                         help="update rate and every interface list")
    verb("list_controller_types", "the controller types the manager can load",
         run_list_types)
    verb("list_hardware_interfaces", "the command and state interfaces",
         run_list_interfaces).add_argument("-v", "--verbose", action="store_true",
                                           help="with each interface's data type")
    verb("list_hardware_components", "the hardware components",
         run_list_components).add_argument("-v", "--verbose", action="store_true",
                                           help="with the state interfaces and data types")
    load = verb("load_controller", "load a controller", run_load)
    load.add_argument("controller_name", help="the controller (a name in the manager's YAML)")
    load.add_argument("param_file", nargs="?", help="a YAML file with its parameters")
    load.add_argument("--set-state", choices=("inactive", "active"),
                      help="configure it (inactive), or configure and activate it (active)")
    state = verb("set_controller_state", "configure, activate, deactivate or clean up",
                 run_set_state)
    state.add_argument("controller_name", help="the controller")
    state.add_argument("state", choices=("unconfigured", "inactive", "active"),
                       help="the state to take it to")
    switch = verb("switch_controllers", "activate and deactivate in one step", run_switch)
    switch.add_argument("--deactivate", nargs="*", default=[], help="controllers to stop")
    switch.add_argument("--activate", nargs="*", default=[], help="controllers to start")
    strictness = switch.add_mutually_exclusive_group()
    strictness.add_argument("--strict", action="store_true",
                            help="all or nothing (the default)")
    strictness.add_argument("--best-effort", action="store_true",
                            help="switch what can be switched")
    switch.add_argument("--activate-asap", action="store_true",
                        help="accepted: a switch always lands between two control cycles")
    switch.add_argument("--switch-timeout", type=float, default=5.0,
                        help="seconds the manager may take to switch (default 5)")
    unload = verb("unload_controller", "unload a controller", run_unload)
    unload.add_argument("controller_name", help="the controller")
    cleanup = verb("cleanup_controller", "clean up a controller", run_cleanup)
    cleanup.add_argument("controller_name", help="the controller")
    component = verb("set_hardware_component_state", "a hardware component's state",
                     run_component_state)
    component.add_argument("hardware_component_name", help="the hardware component")
    component.add_argument("state", choices=("unconfigured", "inactive", "active"),
                           help="the state to take it to")
    verb("reload_controller_libraries", "reload the controller libraries", run_reload)\
        .add_argument("--force-kill", action="store_true",
                      help="accepted: launcher's controllers are Python classes")
    verb("view_controller_chains", "draw the controllers and their interfaces (graphviz)",
         run_view)


def _manager(args: argparse.Namespace) -> tuple[Node, Manager]:
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


def _with_manager(args: argparse.Namespace, work: Any) -> int:
    node, manager = _manager(args)
    try:
        return work(manager)
    finally:
        node.destroy_node()


def run_list_controllers(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        controllers = manager.call("list_controllers").controller
        if not controllers:
            print("No controllers are currently loaded!")
            return 0
        name_w = max(len(c.name) for c in controllers)
        type_w = max(len(c.type) for c in controllers)
        state_w = max(len(c.state) for c in controllers)
        for c in controllers:
            print(f"{c.name:<{name_w}} {c.type:<{type_w}}  {c.state:<{state_w}}")
            if args.verbose:
                print(f"\tupdate_rate: {c.update_rate} Hz")
                print(f"\tis_async: {c.is_async}")
            for flag, title, values in (
                    (args.claimed_interfaces, "claimed interfaces", c.claimed_interfaces),
                    (args.required_command_interfaces, "required command interfaces",
                     c.required_command_interfaces),
                    (args.required_state_interfaces, "required state interfaces",
                     c.required_state_interfaces),
                    (args.chained_interfaces, "chained to interfaces", []),
                    (args.reference_interfaces or args.exported_interfaces,
                     "exported reference interfaces", c.reference_interfaces),
                    (args.reference_interfaces or args.exported_interfaces,
                     "exported state interfaces", c.exported_state_interfaces)):
                if flag or args.verbose:
                    print(f"\t{title}:")
                    for value in values:
                        print(f"\t\t{value}")
        return 0
    return _with_manager(args, work)


def run_list_types(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        response = manager.call("list_controller_types")
        for type_name, base in zip(response.types, response.base_classes, strict=True):
            print(f"{type_name:70s} {base}")
        return 0
    return _with_manager(args, work)


def run_list_interfaces(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        response = manager.call("list_hardware_interfaces")
        print("command interfaces")
        for item in sorted(response.command_interfaces, key=lambda i: i.name):
            kind = f" [{item.data_type}]" if args.verbose else ""
            availability = "[available]" if item.is_available else "[unavailable]"
            claim = "[claimed]" if item.is_claimed else "[unclaimed]"
            print(f"\t{item.name}{kind} {availability} {claim}")
        print("state interfaces")
        for item in sorted(response.state_interfaces, key=lambda i: i.name):
            kind = f" [{item.data_type}]" if args.verbose else ""
            print(f"\t{item.name}{kind}")
        return 0
    return _with_manager(args, work)


def run_list_components(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        for index, c in enumerate(manager.call("list_hardware_components").component):
            print(f"Hardware Component {index + 1}\n\tname: {c.name}\n\ttype: {c.type}")
            print(f"\tplugin name: {c.plugin_name}\n"
                  f"\tstate: id={c.state.id} label={c.state.label}\n"
                  f"\tread/write rate: {c.rw_rate} Hz\n"
                  f"\tis_async: {c.is_async}\n"
                  f"\tcommand interfaces")
            for item in c.command_interfaces:
                kind = f" [{item.data_type}]" if args.verbose else ""
                print(f"\t\t{item.name}{kind} "
                      f"{'[available]' if item.is_available else '[unavailable]'} "
                      f"{'[claimed]' if item.is_claimed else '[unclaimed]'}")
            if args.verbose:
                print("\tstate interfaces")
                for item in c.state_interfaces:
                    print(f"\t\t{item.name} [{item.data_type}] "
                          f"{'[available]' if item.is_available else '[unavailable]'}")
        return 0
    return _with_manager(args, work)


def _state_of(manager: Manager, name: str) -> str:
    for c in manager.call("list_controllers").controller:
        if c.name == name:
            return c.state
    return ""


def run_load(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        name = args.controller_name
        if _state_of(manager, name):
            print(f"Controller : {name} already loaded, skipping load_controller!")
        else:
            if args.param_file:
                path = os.path.abspath(args.param_file)
                if not os.path.exists(path):
                    print(f"Controller parameter file : {args.param_file} does not exist, "
                          f"Aborting!", file=sys.stderr)
                    return 1
                type_name, found = type_from([path], name, "/")
                if found:
                    manager.set_parameter(f"{name}.params_file", str([path]))
                    if type_name:
                        manager.set_parameter(f"{name}.type", type_name)
            if not manager.call("load_controller", name=name).ok:
                print(f"Failed loading controller {name} check controller_manager logs",
                      file=sys.stderr)
                return 1
            print(f"Successfully loaded controller {name}")
        if args.set_state:
            if not manager.call("configure_controller", name=name).ok:
                print(f"Error configuring controller : {name}", file=sys.stderr)
                return 1
            if args.set_state == "active" and not manager.switch([name], [], 5.0).ok:
                print(f"Error activating controller : {name}, check controller_manager logs",
                      file=sys.stderr)
                return 1
            print(f"Successfully loaded controller {name} into state {args.set_state}")
        return 0
    return _with_manager(args, work)


def run_set_state(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        name, target = args.controller_name, args.state
        current = _state_of(manager, name)
        if not current:
            raise LaunchError(f"controller {name} does not seem to be loaded")
        if target == "unconfigured":
            if current != "inactive":
                raise LaunchError(f"cannot cleanup {name} from its current state {current}")
            if not manager.call("cleanup_controller", name=name).ok:
                raise LaunchError("Error cleaning up controller, check controller_manager logs")
            print(f"successfully cleaned up {name}")
        elif target == "inactive":
            if current == "unconfigured":
                if not manager.call("configure_controller", name=name).ok:
                    raise LaunchError("Error configuring controller, check controller_manager "
                                      "logs")
                print(f"Successfully configured {name}")
            elif current == "active":
                if not manager.switch([], [name], 5.0).ok:
                    raise LaunchError("Error stopping controller, check controller_manager "
                                      "logs")
                print(f"Successfully deactivated {name}")
            else:
                raise LaunchError(f"cannot put {name} in 'inactive' state from its current "
                                  f"state {current}")
        else:
            if current != "inactive":
                raise LaunchError(f"cannot activate {name} from its current state {current}")
            response = manager.switch([name], [], 5.0)
            if not response.ok:
                raise LaunchError(f"Error activating {name}, check controller_manager logs"
                                  f"{': ' + response.message if response.message else ''}")
            print(f"Successfully activated {name}")
        return 0
    return _with_manager(args, work)


def run_switch(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        sec = int(args.switch_timeout)
        response = manager.call(
            "switch_controller", activate_controllers=args.activate,
            deactivate_controllers=args.deactivate, strictness=1 if args.best_effort else 2,
            activate_asap=args.activate_asap, timeout=manager.node.message(
                "builtin_interfaces/msg/Duration", sec=sec,
                nanosec=int((args.switch_timeout - sec) * 1e9)))
        if not response.ok:
            raise LaunchError(f"Error switching controllers, check controller_manager logs"
                              f"{': ' + response.message if response.message else ''}")
        print("Successfully switched controllers")
        return 0
    return _with_manager(args, work)


def _simple(service: str, field: str, done: str, failed: str) -> Any:
    def run(args: argparse.Namespace) -> int:
        def work(manager: Manager) -> int:
            if not manager.call(service, name=getattr(args, field)).ok:
                raise LaunchError(failed.format(getattr(args, field)))
            print(done.format(getattr(args, field)))
            return 0
        return _with_manager(args, work)
    return run


run_unload = _simple("unload_controller", "controller_name", "Successfully unloaded controller {}",
                     "Error unloading controller {}, check controller_manager logs")
run_cleanup = _simple("cleanup_controller", "controller_name",
                      "Successfully cleaned up controller {}",
                      "Error cleaning up controller {}, check controller_manager logs")


def run_reload(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        manager.call("reload_controller_libraries", force_kill=args.force_kill)
        print("Reload successful")
        return 0
    return _with_manager(args, work)


def run_component_state(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        ids = {"unconfigured": 1, "inactive": 2, "active": 3}
        make = manager.node.message
        response = manager.call("set_hardware_component_state",
                                name=args.hardware_component_name,
                                target_state=make("lifecycle_msgs/msg/State",
                                                  id=ids[args.state], label=args.state))
        if not response.ok:
            raise LaunchError(f"Error setting {args.hardware_component_name} to {args.state}, "
                              f"check controller_manager logs")
        print(f"Successfully set {args.hardware_component_name} to state {args.state}")
        return 0
    return _with_manager(args, work)


def run_view(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        controllers = manager.call("list_controllers").controller
        interfaces = manager.call("list_hardware_interfaces")
        lines = ["digraph controller_diagram {", "  rankdir=LR;",
                 "  node [shape=record, fontname=Helvetica];"]
        for c in controllers:
            inputs = "|".join(c.required_state_interfaces) or " "
            outputs = "|".join(c.claimed_interfaces or c.required_command_interfaces) or " "
            lines.append(f'  "{c.name}" [label="{c.name} ({c.state})|{{{{{inputs}}}|'
                         f'{{{outputs}}}}}"];')
        commands = [i.name for i in interfaces.command_interfaces]
        states = [i.name for i in interfaces.state_interfaces]
        lines.append(f'  "command_interfaces" [label="command interfaces|{"|".join(commands)}"];')
        lines.append(f'  "state_interfaces" [label="state interfaces|{"|".join(states)}"];')
        for c in controllers:
            if c.required_state_interfaces:
                lines.append(f'  "state_interfaces" -> "{c.name}";')
            if c.required_command_interfaces:
                lines.append(f'  "{c.name}" -> "command_interfaces";')
        lines.append("}")
        gv = Path("controller_diagram.gv").resolve()
        gv.write_text("\n".join(lines) + "\n")
        dot = shutil.which("dot")
        if dot is None:
            raise LaunchError(f"graphviz's dot is not installed, so {gv} is written but not "
                              f"its PDF: apt-get install graphviz")
        pdf = gv.with_name("controller_diagram.gv.pdf")
        subprocess.run([dot, "-Tpdf", str(gv), "-o", str(pdf)], check=True)
        print(f"Diagram written to {pdf} (graphviz source: {gv})")
        return 0
    return _with_manager(args, work)
