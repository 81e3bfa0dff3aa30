"""controller_manager's `spawner` and `unspawner`, as its scripts behave.

    spawner NAME… [-c CM] [-p/--param-file FILE]… [--load-only] [--inactive]
            [--activate-as-group] [--controller-manager-timeout S] [--switch-timeout S]
            [--service-call-timeout S] [-n NS] [-u/--unload-on-kill] [--controller-ros-args A]
    unspawner NAME… [-c CM] [--switch-timeout S]

spawner loads each controller (its type and `params_file` set on the manager first when a
parameter file is given), configures it and activates it (all at once with
`--activate-as-group`), and exits 0 only then; anything refused exits 1 with the reason.
unspawner deactivates and unloads. `-u` keeps spawner running and undoes its work on Ctrl-C.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
import time
from collections.abc import Callable
from typing import Any

from launcher.bus import ros_args
from launcher.bus.node import Node
from launcher.bus.wire import split_time
from launcher.control.yaml_places import block_place
from launcher.errors import LaunchError, UsageError, reported

SRV = "controller_manager_msgs/srv/"
STRICT = 2


def _parser(prog: str) -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog=prog)
    parser.add_argument("controller_names", nargs="+", help="List of controllers")
    parser.add_argument("-c", "--controller-manager", default="controller_manager",
                        help="Name of the controller manager ROS node")
    parser.add_argument("--switch-timeout", type=float, default=5.0)
    parser.add_argument("--service-call-timeout", type=float, default=10.0)
    if prog == "unspawner":
        return parser
    parser.add_argument("-p", "--param-file", action="append", default=None,
                        help="Controller param file to be loaded into controller node before "
                             "configure")
    parser.add_argument("-n", "--namespace", default=None,
                        help="DEPRECATED Namespace for the controller_manager and the "
                             "controller(s)")
    parser.add_argument("--load-only", action="store_true",
                        help="Only load the controller and leave unconfigured.")
    parser.add_argument("--inactive", action="store_true",
                        help="Load and configure the controller, however do not activate them")
    parser.add_argument("-u", "--unload-on-kill", action="store_true",
                        help="Wait until this application is interrupted and unload controllers")
    parser.add_argument("--controller-manager-timeout", type=float, default=0.0,
                        help="Time to wait for the controller manager service to be available")
    parser.add_argument("--activate-as-group", action="store_true",
                        help="Activates all the parsed controllers list together")
    parser.add_argument("--switch-asap", action=argparse.BooleanOptionalAction, default=True)
    parser.add_argument("--controller-ros-args", action="append", default=None)
    return parser


class Manager:
    """The controller manager's services, as spawner calls them."""

    def __init__(self, node: Node, name: str, wait: float, call_timeout: float) -> None:
        self.node, self.name, self.call_timeout = node, name, call_timeout
        self.log = node.get_logger()
        self._clients: dict[str, Any] = {}
        probe = self.client("list_controllers")
        waited, slice_ = 0.0, wait or 10.0
        while not probe.wait_for_service(slice_):
            waited += slice_
            if wait:
                raise LaunchError(f"Could not contact service {name}/list_controllers")
            self.log.warning(f"Could not contact service {name}/list_controllers "
                             f"(waited {waited:g} s; waiting on)")

    def client(self, service: str) -> Any:
        if service not in self._clients:
            type_name = SRV + "".join(p.capitalize() for p in service.split("_"))
            self._clients[service] = self.node.create_client(type_name,
                                                             f"{self.name}/{service}")
        return self._clients[service]

    def call(self, service: str, **fields: Any) -> Any:
        client = self.client(service)
        type_name = SRV + "".join(p.capitalize() for p in service.split("_"))
        request = self.node.message(f"{type_name}_Request", **fields)
        return client.call(request, self.call_timeout)

    def loaded(self, controller: str) -> bool:
        return any(c.name == controller for c in self.call("list_controllers").controller)

    def set_parameter(self, name: str, text: str) -> bool:
        client = self.node.create_client("rcl_interfaces/srv/SetParameters",
                                         f"{self.name}/set_parameters")
        make = self.node.message
        request = make("rcl_interfaces/srv/SetParameters_Request", parameters=[make(
            "rcl_interfaces/msg/Parameter", name=name, value=make(
                "rcl_interfaces/msg/ParameterValue", type=4, string_value=text))])
        result = client.call(request, self.call_timeout).results[0]
        return bool(result.successful)

    def switch(self, activate: list[str], deactivate: list[str], timeout: float) -> Any:
        sec, nanosec = split_time(timeout)
        return self.call("switch_controller", activate_controllers=activate,
                         deactivate_controllers=deactivate, strictness=STRICT,
                         activate_asap=True, timeout=self.node.message(
                             "builtin_interfaces/msg/Duration", sec=sec, nanosec=nanosec))


def type_from(files: list[str], controller: str, namespace: str) -> tuple[str, str]:
    """(type, file) of the controller in the parameter files, as spawner reads them."""
    import yaml

    full = f"/{controller}" if namespace == "/" else f"{namespace}/{controller}"
    for path in files:
        with open(path, encoding="utf-8") as stream:
            document = yaml.safe_load(stream) or {}
        if not isinstance(document, dict):
            continue
        wild = document.get("/**", {}) if isinstance(document.get("/**"), dict) else {}
        for block in (document.get(controller), document.get(full),
                      wild.get(f"/{controller}"), wild.get(full)):
            if isinstance(block, dict) and isinstance(block.get("ros__parameters"), dict):
                found = block["ros__parameters"].get("type")
                if found:
                    return str(found), path
                return "", path
    return "", ""


def spawn(args: argparse.Namespace, argv: list[str]) -> int:
    for path in args.param_file or []:
        if not os.path.isfile(path):
            raise UsageError(f"spawner: parameter file '{path}' does not exist")
    first = args.controller_names[0]
    node = Node(f"spawner_{first}", argv=argv)
    log = node.get_logger()
    try:
        namespace = args.namespace or node.namespace or "/"
        if not namespace.startswith("/"):
            namespace = f"/{namespace}"
        manager = Manager(node, _manager_name(args, namespace), args.controller_manager_timeout,
                          args.service_call_timeout)
        to_activate = []
        for controller in args.controller_names:
            if manager.loaded(controller):
                log.warning("Controller already loaded, skipping load_controller")
            else:
                files = args.param_file or []
                if files:
                    type_name, found_in = type_from(files, controller, namespace)
                    if found_in:
                        if not manager.set_parameter(f"{controller}.params_file", str(files)):
                            log.fatal(f'Could not set controller param "params_file" for '
                                      f'{controller}')
                            return 1
                        if type_name:
                            manager.set_parameter(f"{controller}.type", type_name)
                if not manager.call("load_controller", name=controller).ok:
                    where = block_place(args.param_file or [], controller, namespace)
                    reason = f" (its block is at {where})" if where else \
                        f" (is '{controller}' in the controller manager's parameters, with a " \
                        f"'type'? the controller manager's log says why)"
                    log.fatal(f"Failed loading controller {controller}{reason}")
                    return 1
                log.info(f"Loaded {controller}")
            if args.load_only:
                continue
            if not manager.call("configure_controller", name=controller).ok:
                log.error("Failed to configure controller")
                return 1
            if args.inactive:
                log.info(f"Configured {controller}")
                continue
            if args.activate_as_group:
                to_activate.append(controller)
                continue
            response = manager.switch([controller], [], args.switch_timeout)
            if not response.ok:
                detail = f": {response.message}" if getattr(response, "message", "") else ""
                log.error(f"Failed to activate controller : {controller}{detail}")
                return 1
            log.info(f"Configured and activated {controller}")
        if to_activate:
            response = manager.switch(to_activate, [], args.switch_timeout)
            if not response.ok:
                log.error(f"Failed to activate the parsed controllers list : {to_activate}"
                          f"{': ' + response.message if response.message else ''}")
                return 1
            log.info(f"Configured and activated all the parsed controllers list : "
                     f"{to_activate}!")
        if not args.unload_on_kill:
            return 0
        log.info("Waiting until interrupt to unload controllers")
        try:
            while True:
                time.sleep(1)
        except KeyboardInterrupt:
            signal.signal(signal.SIGINT, signal.SIG_IGN)
            active = [] if args.inactive else list(args.controller_names)
            if active and not manager.switch([], active, args.switch_timeout).ok:
                log.error("Failed to deactivate controller")
                return 1
            for controller in args.controller_names:
                manager.call("unload_controller", name=controller)
            log.info(f"Successfully unloaded controllers : {args.controller_names}")
        return 0
    finally:
        node.destroy_node()


def unspawn(args: argparse.Namespace, argv: list[str]) -> int:
    node = Node(f"unspawner_{args.controller_names[0]}", argv=argv)
    try:
        manager = Manager(node, _manager_name(args, node.namespace or "/"), 0.0,
                          args.service_call_timeout)
        log = node.get_logger()
        response = manager.switch([], list(args.controller_names), args.switch_timeout)
        if not response.ok:
            log.error(f"Failed to deactivate controllers {args.controller_names}"
                      f"{': ' + response.message if response.message else ''}")
            return 1
        log.info("Deactivated controller")
        for controller in args.controller_names:
            if not manager.call("unload_controller", name=controller).ok:
                log.error(f"Failed to unload controller : {controller}")
                return 1
            log.info("Unloaded controller")
        return 0
    finally:
        node.destroy_node()


def _signals() -> None:
    def stop(signum: int, frame: Any) -> None:
        raise KeyboardInterrupt

    signal.signal(signal.SIGTERM, stop)


def _manager_name(args: argparse.Namespace, namespace: str) -> str:
    """The controller manager's full name: `-c NAME`, in `namespace` unless absolute."""
    name = args.controller_manager
    return name if name.startswith("/") else f"{namespace.rstrip('/')}/{name}"


def _script(prog: str, command: Callable[[argparse.Namespace, list[str]], int]) -> int:
    """spawner's or unspawner's script: `command(its arguments, argv)`; argparse's exit
    (--help, a mistake) is the script's exit status, as in controller_manager's."""
    _signals()
    argv = sys.argv[1:]

    def run() -> int:
        try:
            args = _parser(prog).parse_args(ros_args.parse(argv).user_args)
        except SystemExit as exc:
            return int(exc.code or 0)
        return command(args, argv)

    return reported(run, prog)


def main() -> int:
    return _script("spawner", spawn)


def unspawner_main() -> int:
    return _script("unspawner", unspawn)


if __name__ == "__main__":
    sys.exit(main())
