"""What every sensor does: its Gazebo names (scoped name, default topic, frame id), its
schedule in sim time, Gazebo's lazy updates (work only while someone subscribes, unless
`<always_on>`), the world system it needs, and the ROS topics its gazebo_ros plugins publish
(classic.py)."""

from __future__ import annotations

import math
from typing import Any

from launcher.sim import schedule
from launcher.sim.plugins import Plugin
from launcher.sim.sdf.xmltree import SdfError
from launcher.sim.sensors import ALSO_RUN_BY, SYSTEM_CLASSES, SYSTEMS
from launcher.sim.sensors.classic import ClassicOutputs, classic_outputs
from launcher.sim.sensors.config import SensorConfig
from launcher.sim.sensors.metrics import MESSAGE, SUFFIX, Metrics, enabled
from launcher.sim.sensors.noise import generator
from launcher.sim.sensors.topics import TopicClaims


class Sensor(Plugin):
    """A sensor of an entity's link; subclasses say what they publish and measure it."""

    message_type = ""  # the sim's type
    suffix = ""  # Gazebo's topic suffix
    missing = ""  # the world system it needs and the world lacks
    publisher: Any = None  # on the sim's topic
    metrics_publisher: Any = None
    metrics: Metrics | None = None

    def __init__(self, sim: Any, entity: Any, config: SensorConfig) -> None:
        super().__init__(sim, entity, config)
        self.config = config
        self.label = f"sensor '{config.name}' ({config.element.get('type', config.kind)})"
        self.ros = ClassicOutputs([])  # its gazebo_ros plugins' topics (classic.py)

    # --- names, as gz-sim gives them ------------------------------------------------------
    @property
    def scoped_name(self) -> str:
        """`model::link::sensor` (`model::joint::sensor` on a joint): the sensor's name and
        default frame id in Gazebo."""
        return f"{self.entity.name}::{self._parent}::{self.config.name}"

    @property
    def _parent(self) -> str:
        """Its link or joint, scoped within the model (`inner::link`)."""
        return self.config.joint or self.config.scope_link

    def default_topic(self) -> str:
        *models, parent = self._parent.split("::")
        path = "".join(f"/model/{m}" for m in [self.entity.name, *models])
        kind = "joint" if self.config.joint else "link"
        return f"/world/{self.sim.world_name}{path}/{kind}/{parent}/sensor/{self.config.name}"

    def topic_name(self, suffix: str | None = None) -> str:
        if self.config.topic:
            topic = self.config.topic
            return topic if topic.startswith("/") else f"/{topic}"
        return f"{self.default_topic()}/{self.suffix if suffix is None else suffix}"

    @property
    def frame_id(self) -> str:
        return self.config.frame_id or self.scoped_name

    # --- the plugin's hooks -----------------------------------------------------------------
    def setup(self) -> None:
        """Read the settings (once, whichever of prepare and load comes first)."""
        if getattr(self, "rng", None) is not None:
            return
        rate = self.config.update_rate
        if not math.isfinite(rate) or rate < 0:
            element = self.config.element.find("update_rate")
            raise SdfError(f"{self.label}: <update_rate> must be a number of Hz ≥ 0 (0: every "
                           f"step), got '{element.stripped if element is not None else rate}'",
                           element.location if element is not None else None)
        self.rng = generator(getattr(self.sim, "seed", 0), self.scoped_name)
        self.period = schedule.period(rate)
        try:
            self.configure()
        except SdfError as exc:  # say which sensor, wherever in it the mistake is
            if exc.message.startswith(self.label):
                raise
            raise SdfError(f"{self.label}: {exc.message}", exc.location) from None
        self.ros = ClassicOutputs(classic_outputs(self.config.element, self.config.kind,
                                                  self.config.scope_link, self.label,
                                                  self._warn, self.config.namespace))

    def _warn(self, where: Any, message: str) -> None:
        self.sim.transport.logger.warning(f"{where.location.file}:{where.location.line}: "
                                          f"{message}")

    def prepare(self, spec: Any) -> None:
        self.setup()

    def load(self) -> None:
        self.setup()
        # a gazebo_ros plugin's sensor runs as in Gazebo classic, which has no systems
        self.missing = "" if self.ros.outputs else self._missing_system()
        if self.missing:
            self.sim.transport.logger.warning(
                f"{self.config.where}: {self.label} publishes nothing: the world does not "
                f"load {self.missing} (add <plugin filename=\"{self.missing}\" …/> to the "
                "world), as in Gazebo")
        else:
            clash = self.claims.claim(self.topic_name(), self.message_type, self)
            if clash:
                self.missing = "a topic of its own"
                self.sim.transport.logger.warning(
                    f"{self.config.where}: {self.label} is left out: {clash}; give one of "
                    "them a <topic> of its own")
        if not self.missing:  # a sensor that cannot publish advertises nothing
            self.make_publishers()
        self.reset()

    @property
    def claims(self) -> TopicClaims:
        """The sim's record of its sensors' topics (one per sim)."""
        claims = getattr(self.sim, "sensor_topics", None)
        if claims is None:
            claims = self.sim.sensor_topics = TopicClaims()
        return claims

    def make_publishers(self) -> None:
        transport = self.sim.transport
        self.publisher = transport.publisher(self.message_type, self.topic_name())
        self.ros.open(transport)
        if enabled(self.config.element):
            self.metrics = Metrics(self.scoped_name, self.config.update_rate)
            self.metrics_publisher = transport.publisher(MESSAGE,
                                                         f"{self.topic_name()}/{SUFFIX}")

    def configure(self) -> None:
        """Read the sensor's own settings (subclasses)."""

    def bind(self, model: Any, data: Any) -> None:
        self.site = model.site(f"{self.entity.name}/{self.config.site}").id

    def reset(self) -> None:
        self.next_update = math.inf if self.missing else 0.0

    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        if not schedule.serve(self, now, self.period, self.watched()):
            return
        message = self.measure(model, data)
        if message is None:
            return
        if self.reports(message):
            self.publisher.publish(message)
        self.ros.publish(self, message, data, self.config.always_on)
        if self.metrics_publisher is not None and \
                self.metrics_publisher.get_subscription_count() > 0:
            self.metrics_publisher.publish(self.sim.transport.message(
                MESSAGE, **self.metrics.update(now)))

    def watched(self) -> bool:
        """Whether the sensor has work: `<always_on>`, or someone listens to any of it."""
        return self.config.always_on or self.publisher.get_subscription_count() > 0 or \
            self.ros.wanted() or \
            (self.metrics_publisher is not None and
             self.metrics_publisher.get_subscription_count() > 0)

    def reports(self, message: Any) -> bool:
        """Whether the sim's topic gets this reading (a contact sensor's only when touching)."""
        return True

    def measure(self, model: Any, data: Any) -> Any:
        """The message to publish now, or None for none."""
        raise NotImplementedError

    def close(self) -> None:
        self.claims.release(self)
        for publisher in (self.publisher, self.metrics_publisher):
            if publisher is not None:
                publisher.destroy()
        self.ros.close()

    # --- helpers ------------------------------------------------------------------------------
    def header(self, data: Any) -> Any:
        return self.sim.transport.header(data.time, self.frame_id)

    def _missing_system(self) -> str:
        systems = getattr(self.sim, "systems", None)
        needed = SYSTEMS[self.config.kind]
        either = [needed, *filter(None, [ALSO_RUN_BY.get(self.config.element.get("type", ""))])]
        names = {*either, *(f"gz::sim::systems::{SYSTEM_CLASSES[n]}" for n in either)}
        return "" if systems is None or names & set(systems) else needed
