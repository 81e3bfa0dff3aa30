"""controller_manager: loads, configures, switches and unloads controllers and runs them over
the hardware each cycle, with controller_manager_msgs' services, as ros2_control's does.

    manager = ControllerManager(node, components, parameter_files)
    ManagerServices(manager)      # its services on the node (manager_services.py)
    manager.update(time)          # at update_rate: read hardware, update controllers, write

Every callback runs on the thread that calls `update` (the sim's loop, or ros2_control_node's
spin), so a switch lands between two cycles. A controller's parameters come from the files the
manager was started with (gz_ros2_control's `<parameters>`) and its `<name>.params_file`; its
type from the manager's `<name>.type`. Switches follow controller_manager's rules: STRICT
refuses the whole request when one part fails, BEST_EFFORT does what it can; a command
interface is never claimed twice, and a refused switch leaves the running controllers running.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import Any

from launcher.bus.declarations import Param
from launcher.bus.node import Node
from launcher.control.controller import Controller, ControllerError
from launcher.control.controllers import TYPES, controller_class
from launcher.control.resources import Component, Resources
from launcher.control.yaml_places import Places, key_place, params_files
from launcher.errors import LaunchError, ParameterError, did_you_mean
from launcher.lifecycle import (
    ACTIVATE,
    ACTIVE,
    CLEANUP,
    CONFIGURE,
    DEACTIVATE,
    INACTIVE,
    INACTIVE_SHUTDOWN,
    LABELS,
    MACHINE,
    UNCONFIGURED,
    UNCONFIGURED_SHUTDOWN,
    reached,
)

BEST_EFFORT, STRICT, AUTO, FORCE_AUTO = 1, 2, 3, 4
PARAMETERS = (  # controller_manager's own (a controller's <name>.type and .params_file too)
    Param("update_rate", "int", 100, "control cycles a second: read the hardware, update "
          "the active controllers, write (Hz)", minimum=1),
)


# what a request makes of a controller: the lifecycle transitions (launcher/lifecycle.py) of
# the first path that the table allows from the controller's state, and controller_manager's
# words when it allows none (configured again: cleaned up first; an active one is unloaded by
# none of them)
REQUESTS: dict[str, tuple[tuple[tuple[int, ...], ...], str]] = {
    "configure": (((CONFIGURE,), (CLEANUP, CONFIGURE)),
                  "Controller '{name}' can not be configured from '{state}' state."),
    "cleanup": (((CLEANUP,),), "Controller '{name}' can not be cleaned-up from '{state}' state."),
    "unload": (((UNCONFIGURED_SHUTDOWN,), (INACTIVE_SHUTDOWN,)),
               "Could not unload controller with name '{name}' because it is still active"),
}
SAID = {CONFIGURE: "Configuring controller: '{name}'",  # (logged as a transition begins)
        UNCONFIGURED_SHUTDOWN: "Unloading controller: '{name}'",
        INACTIVE_SHUTDOWN: "Unloading controller: '{name}'"}


def missing(name: str, doing: str) -> str:
    """controller_manager's words for a controller it does not have."""
    return (f"Could not {doing} controller with name '{name}' because no controller with "
            "this name exists")


class ControllerManager:
    def __init__(self, node: Node, components: list[Component], parameter_files: list[str],
                 remaps: list[str] | None = None) -> None:
        self.node, self.log = node, node.get_logger()
        self.resources = Resources(components)
        self.files = list(parameter_files)
        self.remaps = list(remaps or [])
        self.controllers: dict[str, Controller] = {}
        self.active: list[Controller] = []  # in activation order: their update order
        self.update_rate = self._declared(node)["update_rate"]
        self.period = 1.0 / self.update_rate
        self.time = 0.0
        self._last: float | None = None
    def _declared(self, node: Node) -> dict[str, Any]:
        """The manager's own parameters, checked; a bad one refused at its line."""
        try:
            return node.params.declare(PARAMETERS)
        except ParameterError as exc:  # (it names the manager's node)
            place = key_place(self.files, node.name, exc.name)
            raise (LaunchError(f"{place}: {exc}") if place else exc) from None

    # --- the cycle -------------------------------------------------------------------------
    def update(self, time: float) -> None:
        period = time - self._last if self._last is not None else self.period
        self._last = self.time = time
        self.resources.read(time, period)
        for controller in self.active:
            rate = controller.update_rate
            if rate and rate < self.update_rate and controller.last_update is not None and \
                    time - controller.last_update < 1.0 / rate - 1e-9:
                continue
            since = time - controller.last_update if controller.last_update is not None \
                else period
            controller.last_update = time
            try:
                controller.update(time, since)
            except Exception as exc:  # a controller's bug: it stops, the others go on
                self.log.error(f"controller '{controller.name}' raised in update: "
                               f"{type(exc).__name__}: {exc}; it is deactivated")
                self._deactivate(controller)
        self.resources.write(time, period)

    # --- lifecycle of controllers ---------------------------------------------------------
    def load(self, name: str) -> tuple[bool, str]:
        if name in self.controllers:
            return False, f"A controller named '{name}' was already loaded inside the " \
                          f"controller manager"
        parameters = self.node.parameters
        type_name = parameters.get(f"{name}.type")
        files = self._files_of(name)
        places = Places.find(files, name, self.node.namespace or "/")
        where = places.block
        if not type_name:
            at = f"{where}: " if where else ""
            return False, (f"{at}The 'type' param was not defined for '{name}' (give it "
                           f"'{name}: type: <package>/<Class>' under "
                           f"{self.node.name}'s ros__parameters, or 'type' in {name}'s own)")
        cls = controller_class(str(type_name))
        if cls is None:
            place = key_place(self.files, self.node.name, f"{name}.type") or where
            at = f"{place}: " if place else ""
            return False, (f"{at}Loader for controller '{name}' (type '{type_name}') not found; "
                           f"available classes: {', '.join(sorted(TYPES))}"
                           f"{did_you_mean(str(type_name), TYPES)}")
        self.log.info(f"Loading controller : '{name}' of type '{type_name}'")
        controller_node = self._node_for(name, files)
        controller = cls(name, controller_node, str(type_name), places)
        try:
            controller.on_init()
        except ControllerError as exc:
            controller_node.destroy_node()
            return False, str(exc)
        self.controllers[name] = controller
        return True, ""

    def _node_for(self, name: str, files: list[str]) -> Node:
        argv = ["--ros-args"]
        for path in files:
            argv += ["--params-file", path]
        argv += ["-p", "use_sim_time:=true"]
        for remap in self.remaps:
            argv += ["-r", remap]
        node = Node(name, namespace=self.node.namespace, argv=argv, session=self.node.session,
                    sim_time=self.node.get_clock().source)  # (in the sim: its own time)
        node.spin_with(self.node)
        return node

    def configure(self, name: str) -> tuple[bool, str]:
        return self._request(name, "configure")

    def cleanup(self, name: str) -> tuple[bool, str]:
        return self._request(name, "cleanup")

    def unload(self, name: str) -> tuple[bool, str]:
        done = self._request(name, "unload")
        if done[0]:
            controller = self.controllers.pop(name)
            controller.node.destroy_node()
        return done

    def _request(self, name: str, doing: str) -> tuple[bool, str]:
        """Take controller `name` along the path REQUESTS gives for `doing` from its state;
        a ControllerError stops it where it is."""
        controller = self.controllers.get(name)
        if controller is None:
            return False, missing(name, doing)
        paths, refused = REQUESTS[doing]
        path = next((p for p in paths if MACHINE.allows(controller.state, p[0])), None)
        if path is None:
            return False, refused.format(name=name, state=LABELS[controller.state])
        try:
            for transition in path:
                if transition in SAID:
                    self.log.info(SAID[transition].format(name=name))
                controller.take(transition)
        except ControllerError as exc:
            return False, str(exc)
        return True, ""

    def switch(self, activate: list[str], deactivate: list[str],
               strictness: int = STRICT) -> tuple[bool, str]:
        """Deactivate, then activate, as one step between two cycles."""
        strict = strictness != BEST_EFFORT
        messages: list[str] = []
        to_stop, to_start = [], []
        for action, names, into in (("deactivate", deactivate, to_stop),
                                    ("activate", activate, to_start)):
            for name in names:
                if name in self.controllers:
                    into.append(self.controllers[name])
                    continue
                message = missing(name, action) + did_you_mean(name, self.controllers)
                if strict:
                    self.log.error(f"{message}; aborting, no controller is switched "
                                   f"('STRICT' switch)")
                    return False, message
                messages.append(message)
        freed = {i for c in to_stop for i, owner in self.resources.claimed.items()
                 if owner == c.name}
        taken: set[str] = set()
        starting: list[Controller] = []
        for controller in to_start:
            problem = self._cannot_activate(controller, to_stop, freed, taken)
            if problem:
                self.log.warning(problem)
                if strict:
                    return False, problem
                messages.append(problem)
                continue
            starting.append(controller)
            taken.update(controller.command_interfaces())
        stopping = [c for c in to_stop if c.state == ACTIVE]
        for controller in to_stop:
            if controller.state != ACTIVE and controller not in to_start:
                message = f"Controller with name '{controller.name}' is not active, so it " \
                          f"can not be deactivated."
                if strict:
                    return False, message
                messages.append(message)
        if strict and not (starting or stopping) and (activate or deactivate):
            return False, "\n".join(messages)
        for controller in stopping:
            self._deactivate(controller)
        for controller in starting:
            self._activate(controller)
        if starting:
            self.log.info(f"Activating controllers: [ {' '.join(c.name for c in starting)} ]")
        ok = bool(starting or stopping) or not (activate or deactivate)
        return ok, "\n".join(messages)

    def _files_of(self, name: str) -> list[str]:
        """The parameter files that may hold controller `name`'s settings."""
        return [*self.files, *params_files(self.node.parameters.get(f"{name}.params_file"))]

    def _place_of(self, controller: Controller, interface: str) -> str:
        """`file:line:column: ` of the setting that asked for `interface` (its joint, else its
        interface name) in the controller's parameters, or ""."""
        joint, _, kind = interface.rpartition("/")
        place = controller.places.value([interface, joint, kind])
        return f"{place}: " if place else ""

    def _cannot_activate(self, controller: Controller, stopping: list[Controller],
                         freed: set[str], taken: set[str]) -> str:
        name = controller.name
        if controller.state == UNCONFIGURED:
            return (f"Controller with name '{name}' is in 'unconfigured' state. The controller "
                    f"needs to be configured to be in 'inactive' state before it can be checked "
                    f"and activated.")
        if controller.state == ACTIVE and controller not in stopping:
            return f"Controller with name '{name}' is already active."
        resources = self.resources
        for interface in controller.command_interfaces():
            if not resources.available(interface, command=True):
                return self._unavailable(controller, interface, "command", resources.commands)
            if interface in resources.claimed and interface not in freed:
                return (f"Unable to activate controller '{name}' since the command interface "
                        f"'{interface}' is currently claimed by another controller "
                        f"('{resources.claimed[interface]}').")
            if interface in taken:
                return (f"Unable to activate controller '{name}' since the command interface "
                        f"'{interface}' will be used by another controller that is being "
                        f"activated.")
        for interface in controller.state_interfaces() or []:
            if not resources.available(interface, command=False):
                return self._unavailable(controller, interface, "state", resources.states)
        return ""

    def _unavailable(self, controller: Controller, interface: str, kind: str,
                     exported: Collection[str]) -> str:
        """Why `controller` cannot activate: its `kind` interface is not among those the
        hardware exports."""
        return (f"{self._place_of(controller, interface)}Unable to activate controller "
                f"'{controller.name}' since the {kind} interface '{interface}' is not available "
                f"(the hardware exports: {', '.join(sorted(exported)) or 'none'})"
                f"{did_you_mean(interface, exported)}")

    def _activate(self, controller: Controller) -> None:
        wanted = controller.state_interfaces()
        names = sorted(self.resources.states) if wanted is None else wanted
        controller.states = {n: self.resources.states[n] for n in names}
        controller.commands = self.resources.claim(controller.name,
                                                   controller.command_interfaces())
        controller.last_update = None
        try:
            controller.take(ACTIVATE)
        except Exception as exc:
            self.log.error(f"Could not activate controller : '{controller.name}': {exc}")
            self.resources.release(controller.name)
            controller.commands = []
            return
        self.active.append(controller)

    def _deactivate(self, controller: Controller) -> None:
        try:
            controller.on_deactivate()
        except Exception as exc:  # it stops all the same
            self.log.error(f"controller '{controller.name}' raised in on_deactivate: "
                           f"{type(exc).__name__}: {exc}")
        finally:
            self.resources.release(controller.name)
            controller.commands = []
            controller.state = reached(ACTIVE, DEACTIVATE)  # (raised or not)
            if controller in self.active:
                self.active.remove(controller)

    def set_component_state(self, name: str, target: int) -> bool:
        """Move a hardware component to `target` (unconfigured, inactive, active); the
        controllers using its command interfaces stop when it leaves active. False (and
        logged) for an unknown component or state."""
        found = [c for c in self.resources.components if c.info.name == name]
        if not found or target not in (UNCONFIGURED, INACTIVE, ACTIVE):
            if not found:
                known = [c.info.name for c in self.resources.components]
                self.log.error(f"Hardware component '{name}' is unknown"
                               f"{did_you_mean(name, known)}")
            return False
        component = found[0]
        if target != ACTIVE:  # its command interfaces go: the controllers using them stop
            for controller in list(self.active):
                if any(self.resources.owner.get(i) is component
                       for i in controller.command_interfaces()):
                    self._deactivate(controller)
        component.state = target
        return True

    def shutdown(self) -> None:
        for controller in list(self.active):
            self._deactivate(controller)
        for controller in list(self.controllers.values()):
            controller.node.destroy_node()
        self.controllers.clear()
