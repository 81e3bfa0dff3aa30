"""controller_manager_msgs' services of a ControllerManager, on its node, as ros2_control's
controller_manager offers them: each request answered from the manager, a refusal logged with
its reason (the manager's message)."""

from __future__ import annotations

from typing import Any

from launcher.control.controllers import TYPES, controller_class
from launcher.control.manager import ControllerManager
from launcher.lifecycle import LABELS, STATES, UNCONFIGURED

SRV = "controller_manager_msgs/srv/"


class ManagerServices:
    def __init__(self, manager: ControllerManager) -> None:
        self.manager = manager
        for name, callback in (("list_controllers", self.on_list_controllers),
                               ("list_controller_types", self.on_list_types),
                               ("list_hardware_components", self.on_list_components),
                               ("list_hardware_interfaces", self.on_list_interfaces),
                               ("load_controller", self.on_load),
                               ("configure_controller", self.on_configure),
                               ("cleanup_controller", self.on_cleanup),
                               ("switch_controller", self.on_switch),
                               ("unload_controller", self.on_unload),
                               ("reload_controller_libraries", self.on_reload),
                               ("set_hardware_component_state", self.on_component_state)):
            type_name = SRV + "".join(p.capitalize() for p in name.split("_"))
            manager.node.create_service(type_name, f"~/{name}", callback)

    def _answer(self, response: Any, result: tuple[bool, str]) -> Any:
        ok, message = result
        if not ok and message:
            self.manager.log.error(message)
        response.ok = ok
        return response

    def on_load(self, request: Any, response: Any) -> Any:
        return self._answer(response, self.manager.load(request.name))

    def on_configure(self, request: Any, response: Any) -> Any:
        return self._answer(response, self.manager.configure(request.name))

    def on_cleanup(self, request: Any, response: Any) -> Any:
        return self._answer(response, self.manager.cleanup(request.name))

    def on_unload(self, request: Any, response: Any) -> Any:
        return self._answer(response, self.manager.unload(request.name))

    def on_reload(self, request: Any, response: Any) -> Any:
        response.ok = True  # the controllers are Python classes: nothing to reload
        return response

    def on_switch(self, request: Any, response: Any) -> Any:
        ok, message = self.manager.switch(list(request.activate_controllers),
                                          list(request.deactivate_controllers),
                                          request.strictness)
        response.ok = ok
        if hasattr(response, "message"):
            response.message = message
        return response

    def on_list_controllers(self, request: Any, response: Any) -> Any:
        message, claimed = self.manager.node.message, self.manager.resources.claimed
        response.controller = [message(
            "controller_manager_msgs/msg/ControllerState", name=c.name,
            state=LABELS[c.state], type=c.type_name, is_async=False,
            update_rate=c.update_rate or self.manager.update_rate,
            claimed_interfaces=[i for i, o in claimed.items() if o == c.name],
            required_command_interfaces=c.command_interfaces() if c.state != UNCONFIGURED
            else [],
            required_state_interfaces=(c.state_interfaces() or []) if c.state != UNCONFIGURED
            else []) for c in self.manager.controllers.values()]
        return response

    def on_list_types(self, request: Any, response: Any) -> Any:
        response.types = sorted(TYPES)
        response.base_classes = [controller_class(t).base_class for t in response.types]
        return response

    def _interfaces(self, names: list[str], command: bool) -> list[Any]:
        make = self.manager.node.message
        return [make("controller_manager_msgs/msg/HardwareInterface", name=n, data_type="double",
                     is_available=self.manager.resources.available(n, command),
                     is_claimed=command and n in self.manager.resources.claimed) for n in names]

    def on_list_interfaces(self, request: Any, response: Any) -> Any:
        commands, states = self.manager.resources.describe()
        response.command_interfaces = self._interfaces(commands, True)
        response.state_interfaces = self._interfaces(states, False)
        return response

    def on_list_components(self, request: Any, response: Any) -> Any:
        make = self.manager.node.message
        response.component = [make(
            "controller_manager_msgs/msg/HardwareComponentState", name=c.info.name,
            type=c.info.type, is_async=False, rw_rate=self.manager.update_rate,
            plugin_name=c.info.plugin,
            state=make("lifecycle_msgs/msg/State", id=c.state, label=LABELS[c.state]),
            command_interfaces=self._interfaces(list(c.commands), True),
            state_interfaces=self._interfaces(list(c.states), False))
            for c in self.manager.resources.components]
        return response

    def on_component_state(self, request: Any, response: Any) -> Any:
        target = request.target_state.id or STATES.get(request.target_state.label, 0)
        response.ok = self.manager.set_component_state(request.name, target)
        if response.ok:
            response.state = self.manager.node.message("lifecycle_msgs/msg/State", id=target,
                                                       label=LABELS[target])
        return response
