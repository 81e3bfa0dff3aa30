"""A battery that drains (gz-sim-linear-battery-plugin-system, `LinearBatteryPlugin`), as
gz-sim's: state on `/model/<name>/battery/<battery_name>/state` (gz.msgs.BatteryState, at
most 50 a second of sim time), which ros_gz bridges to sensor_msgs/BatteryState.

Parameters, with gz-sim's meaning: `battery_name` and `voltage` (required), `capacity` (Ah,
required), `initial_charge` (Ah, default the capacity), `open_circuit_voltage_constant_coef`
(e0), `open_circuit_voltage_linear_coef` (e1), `resistance` (r), `smooth_current_tau` (1 s),
`power_load` (W), `start_draining`, `power_draining_topic` / `stop_power_draining_topic`
(repeatable: a message on one starts or stops the drain), `enable_recharge`,
`charging_time` (h), `recharge_by_topic`, `invert_current_sign`, `fix_issue_225`.

Each step of drain: current i = load / voltage, smoothed with tau; charge q −= i·dt; voltage
= e0 + e1·(1 − q/capacity) − r·i. The drain starts, as in gz-sim, when the model's joints
are first commanded to move (a non-zero actuator command) or when `start_draining` says so.
The state of charge is q / capacity: gz-sim's older estimate (issue 225, which sums the last
hundred currents every step and so drains about a hundred times too fast) is not reproduced;
`fix_issue_225` only keeps its other effect, a percentage of 0–100 instead of 0–1.
Recharging (`enable_recharge` with `recharge_by_topic` and the `…/recharge/start|stop`
topics) adds capacity/charging_time of current while the state of charge is below 0.9.
"""

from __future__ import annotations

import math
from typing import Any

from launcher.records import dataclass
from launcher.schema import Kind, attr
from launcher.sim import schedule
from launcher.sim.plugins import Plugin, PluginError

PUBLISH_PERIOD = 1.0 / 50  # s of sim time: gz-sim advertises the state at 50 a second
UPDATE_PERIOD = 0.01  # s of sim time between drain updates (the charge integrates exactly)
CHARGING, DISCHARGING, NOT_CHARGING, FULL = 1, 2, 3, 4


@dataclass
class Parameters:
    battery_name: str = attr(Kind.TEXT, "", required=True)
    voltage: float = attr(Kind.FLOAT, 0.0, required=True)
    capacity: float = attr(Kind.FLOAT, 0.0, required=True)
    initial_charge: float | None = attr(Kind.FLOAT, None, minimum=0.0)
    open_circuit_voltage_constant_coef: float = attr(Kind.FLOAT, 0.0)
    open_circuit_voltage_linear_coef: float = attr(Kind.FLOAT, 0.0)
    resistance: float = attr(Kind.FLOAT, 0.0)
    smooth_current_tau: float = attr(Kind.FLOAT, 1.0)
    power_load: float = attr(Kind.FLOAT, 0.0)
    start_draining: bool = attr(Kind.BOOL, False)
    power_draining_topic: list[str] = attr(Kind.NAMES)
    stop_power_draining_topic: list[str] = attr(Kind.NAMES)
    enable_recharge: bool = attr(Kind.BOOL, False)
    charging_time: float = attr(Kind.FLOAT, 3.0, above=0.0)
    recharge_by_topic: bool = attr(Kind.BOOL, False)
    invert_current_sign: bool = attr(Kind.BOOL, False)
    fix_issue_225: bool = attr(Kind.BOOL, False)
    start_on_motion: bool = attr(Kind.BOOL, True)  # what gz-sim does anyway (accepted)
    soc_threshold: float = attr(Kind.FLOAT, 0.0)  # accepted: gz-sim no longer reads it


class LinearBattery(Plugin):
    def prepare(self, spec: Any) -> None:
        p = self.params = self.parameters(Parameters)
        if p.capacity <= 0:
            raise PluginError(f"{self.config.where}: plugin {self.label}: <capacity> must be "
                              f"greater than 0 (ampere-hours), got {p.capacity:g}")
        if p.initial_charge is not None and p.initial_charge > p.capacity:
            raise PluginError(f"{self.config.where}: plugin {self.label}: <initial_charge> "
                              f"({p.initial_charge:g}) is more than <capacity> "
                              f"({p.capacity:g})")
        self.tau = p.smooth_current_tau if p.smooth_current_tau > 0 else 1.0
        self.reset()

    def reset(self) -> None:
        p = self.params
        self.charge = p.capacity if p.initial_charge is None else p.initial_charge
        self.voltage = p.voltage
        self.current = 0.0
        self.draining = p.start_draining
        self.charging = False
        self.last: float | None = None
        self.next_publish = self.next_update = 0.0
        self.warned_empty = False

    def load(self) -> None:
        p, name, transport = self.params, self.entity.name, self.sim.transport
        base = f"/model/{name}/battery/{p.battery_name}"
        self.state_pub = transport.publisher("mujoco_sim/msg/BatteryState", f"{base}/state")
        self.subscriptions = []
        for topic in p.power_draining_topic:
            self.subscriptions.append(transport.subscribe(
                "mujoco_sim/msg/Empty", topic, lambda m: self._drain(True)))
        for topic in p.stop_power_draining_topic:
            self.subscriptions.append(transport.subscribe(
                "mujoco_sim/msg/Empty", topic, lambda m: self._drain(False)))
        if p.enable_recharge and p.recharge_by_topic:
            for verb, value in (("start", True), ("stop", False)):
                self.subscriptions.append(transport.subscribe(
                    "mujoco_sim/msg/Empty", f"{base}/recharge/{verb}",
                    lambda m, value=value: setattr(self, "charging", value)))

    def _drain(self, on: bool) -> None:
        self.draining = on

    def bind(self, model: Any, data: Any) -> None:
        prefix = f"{self.entity.name}/"
        self.actuators = [i for i in range(model.nu) if model.actuator(i).name.startswith(prefix)]

    @property
    def state_of_charge(self) -> float:
        return self.charge / self.params.capacity

    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        if not self.draining and any(data.ctrl[i] != 0 for i in self.actuators):
            self.draining = True  # the robot has started moving, as gz-sim sees it
        dt = now - self.last if self.last is not None else 0.0
        self.last = now
        if dt > 0:
            self._update(dt)
        if schedule.is_due(now, self.next_publish):
            self.next_publish = schedule.following(self.next_publish, now, PUBLISH_PERIOD)
            self._publish(now)
        self.next_update = min(now + UPDATE_PERIOD, self.next_publish)

    def _update(self, dt: float) -> None:
        p = self.params
        if abs(self.voltage) < 1e-3 and not self.charging:
            return
        if self.state_of_charge < 0 and not self.charging:
            return
        load = p.power_load if self.draining else 0.0
        raw = load / self.voltage if self.voltage else 0.0
        if self.charging and self.state_of_charge < 0.9:
            raw -= p.capacity / p.charging_time
        k = min(dt / self.tau, 1.0)
        self.current += k * (raw - self.current)
        self.charge -= dt * self.current / 3600.0
        self.voltage = p.open_circuit_voltage_constant_coef + \
            p.open_circuit_voltage_linear_coef * (1 - self.charge / p.capacity) - \
            p.resistance * self.current
        if self.state_of_charge <= 0 and not self.warned_empty:
            self.warned_empty = True
            self.sim.transport.logger.warning(f"Model {self.entity.name} out of battery.")

    def _publish(self, now: float) -> None:
        if not self.state_pub.get_subscription_count():
            return
        p, transport = self.params, self.sim.transport
        status = CHARGING if self.charging else DISCHARGING if self.draining else \
            FULL if self.state_of_charge > 0.9 else NOT_CHARGING
        soc = self.state_of_charge
        self.state_pub.publish(transport.message(
            "mujoco_sim/msg/BatteryState", header=transport.header(now, ""),
            voltage=float(self.voltage), temperature=math.nan,
            current=float(-self.current if p.invert_current_sign else self.current),
            charge=float(self.charge), capacity=float(p.capacity), design_capacity=math.nan,
            percentage=float(soc * 100 if p.fix_issue_225 else soc),
            power_supply_status=status, power_supply_health=0, power_supply_technology=0,
            present=True, cell_voltage=[], cell_temperature=[], location="",
            serial_number=""))

    def close(self) -> None:
        self.state_pub.destroy()
        for subscription in self.subscriptions:
            subscription.destroy()
