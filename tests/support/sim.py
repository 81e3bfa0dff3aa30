"""Worlds for tests of the sim: a recording transport, a world made from MJCF, the diffbot's launch."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

from launcher.sim import mjcf
from launcher.sim.resources import find_world
from launcher.sim.world import World

IDENTITY = [1.0, 0.0, 0.0, 0.0]


class Recorder:
    """Stands in for the bus: keeps what is published, hands out the subscription callbacks."""

    def __init__(self) -> None:
        self.published: dict[str, list] = {}
        self.callbacks: dict[str, object] = {}
        self.logged: list[tuple[str, str]] = []
        self.logger = SimpleNamespace(**{level: self._logs(level)
                                         for level in ("info", "warning", "error", "debug")})

    def _logs(self, level):
        return lambda message, once=False: self.logged.append((level, message))

    def publisher(self, type_name, topic, qos=10, ros=False):
        box = self.published.setdefault(topic, [])
        return SimpleNamespace(publish=box.append, destroy=lambda: None,
                               get_subscription_count=lambda: 1)

    def subscribe(self, type_name, topic, callback, ros=False):
        self.callbacks[topic] = callback
        return SimpleNamespace(destroy=lambda: self.callbacks.pop(topic, None))

    def message(self, type_name, **fields):
        return SimpleNamespace(**fields)

    def header(self, seconds, frame_id):
        return SimpleNamespace(stamp=seconds, frame_id=frame_id)

    def vector(self, x, y, z):
        return SimpleNamespace(x=x, y=y, z=z)

    def pose(self, x, y, z, quat):
        return SimpleNamespace(position=SimpleNamespace(x=x, y=y, z=z), orientation=quat)

    def messages(self, level):
        return [m for lv, m in self.logged if lv == level]


def make_world(text: str | None = None, path: Path | None = None, **values) -> World:
    path = path or find_world("empty.xml")
    source = mjcf.read(text if text is not None else path.read_text(), path, values)
    world = World(mjcf.compile_spec(source), str(path), Recorder(), source.plugins)
    world.load_world_plugins()
    return world


ROBOT = str(Path(__file__).resolve().parent.parent / "data" / "diffbot.urdf")


SIM_LAUNCH = f"""
launch:
  - node: {{pkg: mujoco_sim, exec: sim, args: "-v 3 -r", output: screen}}
  - node: {{pkg: mujoco_sim, exec: create, output: screen,
           args: "-name bot -file {ROBOT} -z 0.06"}}
"""
