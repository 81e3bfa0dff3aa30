"""TriggeredPublisher (gz-sim-triggered-publisher-system): when a message on the input topic
matches, publish the outputs, as gz-sim's.

    <input type="gz.msgs.Boolean" topic="/start"><match field="data">true</match></input>
    <output type="gz.msgs.Twist" topic="/model/rover/cmd_vel">linear: {x: 0.5}</output>
    <delay_ms>500</delay_ms>

Each `<match>` (all must hold) compares, in Gazebo's text format, the whole message or its
`field` (a dotted path) with the text; `logic_type="negative"` turns one around. No `<match>`:
every input triggers. `<output>` (repeatable) is published `<delay_ms>` of sim time later (0:
at once). Types are `gz.msgs.*` (or `ignition.msgs.*`) names of the sim's messages. A
`<service>` output is accepted and not called (said once): the sim's own services answer on
the thread that would have to wait for them. Mistakes (an unknown type, text that does not
parse or fit) are errors at the plugin's line.
"""

from __future__ import annotations

import math
from typing import Any

from launcher.bus.messages import MessageError, build, to_data
from launcher.bus.types import registry
from launcher.errors import LaunchError
from launcher.sim import gz_msgs, prototext, schedule
from launcher.sim.plugins import Plugin, PluginError

TOLERANCE = 1e-6  # floating-point fields compare equal within this


def sim_type_of(gz_type: str) -> tuple[str, str]:
    """(the sim's type, Gazebo's short name) of `gz.msgs.NAME`; LaunchError if none."""
    for prefix in ("gz.msgs.", "ignition.msgs.", "mujoco_sim/msg/"):
        if gz_type.startswith(prefix):
            short = gz_type[len(prefix):]
            break
    else:
        raise LaunchError(f"'{gz_type}' is not a Gazebo message type (gz.msgs.NAME)")
    name = "PoseV" if short == "Pose_V" else short
    try:
        registry().message_class(f"mujoco_sim/msg/{name}")
    except LaunchError as exc:  # its suggestions, in Gazebo's names
        hint = str(exc)[str(exc).find(" (did you mean"):] if "did you mean" in str(exc) else ""
        raise LaunchError(f"the sim has no message type '{gz_type}'"
                          f"{hint.replace('mujoco_sim/msg/', 'gz.msgs.')}") from None
    return f"mujoco_sim/msg/{name}", name


class TriggeredPublisher(Plugin):
    unknown_parameters = "ignore"

    def prepare(self, spec: Any) -> None:
        element = self.config.element
        source = element.find("input")
        if source is None or not source.get("type") or not source.get("topic"):
            raise self._error("needs <input type=\"gz.msgs.…\" topic=\"…\"/>")
        self.input_type, self.input_short = self._type(source.get("type", ""))
        self.input_topic = source.get("topic", "")
        self.matches = []
        for match in source.findall("match"):
            text = (match.text or "").strip()
            negative = match.get("logic_type", "positive") == "negative"
            field = match.get("field", "")
            if field:
                wanted = prototext.parse(f"value: {text}", "<match>")["value"] \
                    if text else None
            else:
                wanted = self._parse(text, "<match>")
            self.matches.append((field, wanted, negative))
        self.outputs = []
        for output in element.findall("output"):
            type_name, short = self._type(output.get("type", ""))
            if not output.get("topic"):
                raise self._error("an <output> needs a topic")
            data = gz_msgs.to_sim(short, self._parse((output.text or "").strip(), "<output>"))
            try:
                message = build(type_name, data)
            except MessageError as exc:
                raise self._error(f"<output> text does not fit {output.get('type')}: "
                                  f"{exc.message}") from None
            self.outputs.append((type_name, output.get("topic", ""), message))
        if not self.outputs and element.find("service") is None:
            raise self._error("needs at least one <output> (or <service>)")
        if element.find("service") is not None:
            self.sim.transport.logger.warning(
                f"{self.config.where}: plugin {self.label}: <service> outputs are accepted "
                f"and not called (the sim's services answer on its own thread)")
        self.delay = self.number("delay_ms", 0.0, low=0.0) / 1000.0
        self.pending: list[float] = []

    def _error(self, message: str) -> PluginError:
        return PluginError(f"{self.config.where}: plugin {self.label}: {message}")

    def _type(self, gz_type: str) -> tuple[str, str]:
        try:
            return sim_type_of(gz_type)
        except LaunchError as exc:
            raise self._error(str(exc)) from None

    def _parse(self, text: str, what: str) -> dict[str, Any]:
        try:
            return prototext.parse(text, what) if text else {}
        except LaunchError as exc:
            raise self._error(str(exc)) from None

    def load(self) -> None:
        transport = self.sim.transport
        self.subscription = transport.subscribe(self.input_type, self.input_topic,
                                                self.on_input)
        self.publishers = [(transport.publisher(type_name, topic), message)
                           for type_name, topic, message in self.outputs]

    def bind(self, model: Any, data: Any) -> None:
        self.data = data

    def on_input(self, message: Any) -> None:
        if not self._matched(message):
            return
        if self.delay <= 0:
            self._fire()
            return
        self.pending.append(self.data.time + self.delay)
        self.next_update = min(self.pending)

    def _matched(self, message: Any) -> bool:
        if not self.matches:
            return True
        data = gz_msgs.to_gz(self.input_short, to_data(message))
        for field, wanted, negative in self.matches:
            value: Any = data
            if field:
                for part in field.split("."):
                    value = value.get(part) if isinstance(value, dict) else None
            if _same(value, wanted) == negative:
                return False
        return True

    def _fire(self) -> None:
        for publisher, message in self.publishers:
            publisher.publish(message)

    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        due = [t for t in self.pending if schedule.is_due(now, t)]
        for _ in due:
            self._fire()
        self.pending = [t for t in self.pending if not schedule.is_due(now, t)]
        self.next_update = min(self.pending) if self.pending else math.inf

    def reset(self) -> None:
        self.pending = []
        self.next_update = math.inf

    def close(self) -> None:
        self.subscription.destroy()
        for publisher, _ in self.publishers:
            publisher.destroy()


def _same(value: Any, wanted: Any) -> bool:
    """Gazebo's comparison: fields not written in the match are zero/empty (proto3)."""
    if isinstance(wanted, dict) or isinstance(value, dict):
        value = value if isinstance(value, dict) else {}
        wanted = wanted if isinstance(wanted, dict) else {}
        return all(_same(value.get(k), wanted.get(k)) for k in set(value) | set(wanted))
    if isinstance(wanted, list) or isinstance(value, list):
        value, wanted = list(value or []), list(wanted or [])
        return len(value) == len(wanted) and all(map(_same, value, wanted))
    if value is None or wanted is None:
        other = wanted if value is None else value
        return other in (None, 0, 0.0, False, "", [], {})
    if isinstance(value, float | int) and isinstance(wanted, float | int) and \
            not isinstance(value, bool) and not isinstance(wanted, bool):
        return abs(float(value) - float(wanted)) <= TOLERANCE
    return str(value) == str(wanted) if not isinstance(value, bool) else value == wanted
