"""rosbag2 bags (MCAP or SQLite storage): record topics as received (CDR) with the QoS their
publishers offer, and play them back with it.

A bag is a folder: its storage files and metadata.yaml (version 9, as Jazzy writes it). A bag
split by `--max-bag-duration` or `--max-bag-size` has several files, `NAME_0.mcap`,
`NAME_1.mcap`, …, listed in order in its metadata, as rosbag2 splits them.
"""

from __future__ import annotations

import os
import shutil
import sys
import threading
import time
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import yaml
from rosbags.interfaces import (
    Qos,
    QosDurability,
    QosHistory,
    QosLiveliness,
    QosReliability,
    QosTime,
)
from rosbags.rosbag2 import Reader, StoragePlugin, Writer

from launcher.bus import graph
from launcher.bus.node import Node
from launcher.bus.qos import QoS, QoSPolicyError
from launcher.bus.types import DISTRO, registry
from launcher.errors import LaunchError, Location

ROS_DISTRO = DISTRO.removeprefix("ros2_")  # the recorded definitions are this distro's
STORAGES = {"mcap": StoragePlugin.MCAP, "sqlite3": StoragePlugin.SQLITE3}
SUFFIXES = {"mcap": ".mcap", "sqlite3": ".db3"}
_INFINITE = QosTime(9223372036, 854775807)  # rmw's "infinite" duration, as Jazzy records it


def recorded_qos(qos: QoS) -> Qos:
    """A QoS as rosbag2's metadata keeps it."""
    return Qos(QosHistory.KEEP_LAST, qos.depth,
               QosReliability.RELIABLE if qos.reliable else QosReliability.BEST_EFFORT,
               QosDurability.TRANSIENT_LOCAL if qos.transient_local else QosDurability.VOLATILE,
               _INFINITE, _INFINITE, QosLiveliness.AUTOMATIC, _INFINITE, False)


def replayed_qos(profiles: Iterable[Qos]) -> QoS:
    """The QoS to play a topic with: latched if any publisher was, reliable unless none was."""
    profiles = list(profiles)
    if not profiles:
        return QoS(depth=1000)
    latched = any(p.durability == QosDurability.TRANSIENT_LOCAL for p in profiles)
    reliable = any(p.reliability != QosReliability.BEST_EFFORT for p in profiles)
    return QoS(depth=max(1000 if not latched else 1, *(p.depth for p in profiles)),
               reliable=reliable, transient_local=latched)


class BagWriter:
    """Writes a bag, split into files when a duration (ns) or size (bytes, counted as the
    messages' sizes) is reached."""

    def __init__(self, output: Path, storage: str = "mcap", max_duration: int | None = None,
                 max_size: int | None = None) -> None:
        if output.exists():
            raise LaunchError(f"'{output}' already exists; choose another output folder")
        self.output, self.storage = output, storage
        self.max_duration, self.max_size = max_duration, max_size
        self.topics: dict[str, tuple[str, list[Qos]]] = {}
        output.mkdir(parents=True)
        self._pieces: list[Path] = []
        self._writer: Writer | None = None
        self._connections: dict[str, Any] = {}
        self._start = 0
        self._bytes = 0
        self._open()

    def _open(self) -> None:
        name = f"{self.output.name}_{len(self._pieces)}"
        self._pieces.append(self.output / f".{name}")
        self._writer = Writer(self._pieces[-1], version=9, storage_plugin=STORAGES[self.storage])
        self._writer.open()
        self._connections = {}
        for topic, (type_name, offered) in self.topics.items():
            self._connect(topic, type_name, offered)
        self._start, self._bytes = 0, 0

    def _connect(self, topic: str, type_name: str, offered: list[Qos]) -> None:
        types = registry()
        assert self._writer is not None
        self._connections[topic] = self._writer.add_connection(
            topic, type_name, typestore=types.store, offered_qos_profiles=offered)

    def add(self, topic: str, type_name: str, offered: list[QoS]) -> None:
        registry().ensure(type_name)
        self.topics[topic] = (type_name, [recorded_qos(q) for q in offered])
        self._connect(topic, type_name, self.topics[topic][1])

    def write(self, topic: str, stamp: int, payload: bytes) -> None:
        if self._start and (
                self.max_duration and stamp - self._start >= self.max_duration
                or self.max_size and self._bytes >= self.max_size):
            self._close_piece()
            self._open()
        assert self._writer is not None
        self._writer.write(self._connections[topic], stamp, payload)
        self._start = self._start or stamp
        self._bytes += len(payload)

    def _close_piece(self) -> None:
        assert self._writer is not None
        self._writer.close()
        self._writer = None

    def close(self) -> None:
        """Close the last file and write metadata.yaml for them all."""
        self._close_piece()
        pieces = []
        for folder in self._pieces:
            info = yaml.safe_load((folder / "metadata.yaml").read_text())
            info = info["rosbag2_bagfile_information"]
            (stored,) = info["relative_file_paths"]
            name = folder.name.lstrip(".") + SUFFIXES[self.storage]
            os.replace(folder / stored, self.output / name)
            shutil.rmtree(folder)
            pieces.append((name, info))
        write_metadata(self.output, self.storage, pieces)


def write_metadata(output: Path, storage: str, pieces: list[tuple[str, dict]]) -> None:
    """metadata.yaml for a bag of these files (each with the metadata rosbags wrote for it)."""
    counted = [(n, i) for n, i in pieces if i["message_count"]]
    starts = [i["starting_time"]["nanoseconds_since_epoch"] for _, i in counted]
    ends = [i["starting_time"]["nanoseconds_since_epoch"] + i["duration"]["nanoseconds"]
            for _, i in counted]
    start = min(starts) if starts else 0
    topics: dict[str, dict] = {}
    for _, info in pieces:
        for entry in info["topics_with_message_count"]:
            name = entry["topic_metadata"]["name"]
            kept = topics.setdefault(name, {"topic_metadata": entry["topic_metadata"],
                                            "message_count": 0})
            kept["message_count"] += entry["message_count"]
    document = {"rosbag2_bagfile_information": {
        "version": 9,
        "storage_identifier": storage,
        "duration": {"nanoseconds": (max(ends) - start) if ends else 0},
        "starting_time": {"nanoseconds_since_epoch": start},
        "message_count": sum(i["message_count"] for _, i in pieces),
        "topics_with_message_count": list(topics.values()),
        "compression_format": "",
        "compression_mode": "",
        "relative_file_paths": [name for name, _ in pieces],
        "files": [{"path": name, "starting_time": info["starting_time"],
                   "duration": info["duration"], "message_count": info["message_count"]}
                  for name, info in pieces],
        "custom_data": None,
        "ros_distro": ROS_DISTRO,
    }}
    (output / "metadata.yaml").write_text(yaml.safe_dump(document, sort_keys=False))


def load_qos_overrides(path: str) -> dict[str, QoS]:
    """`--qos-profile-overrides-path`: `{/topic: {reliability:, durability:, history:, depth:}}`
    as ros2 bag takes it; errors name the file and line."""
    from launcher.user_files import read_text

    try:
        text = read_text(path)
        document = yaml.safe_load(text) or {}
    except OSError as exc:
        raise LaunchError(f"cannot read QoS overrides: {exc.strerror}", Location(path)) from None
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        where = Location(path, mark.line + 1, mark.column + 1) if mark else Location(path)
        raise LaunchError(f"QoS overrides are not valid YAML: {exc.problem}", where) from None
    if not isinstance(document, dict):
        raise LaunchError("QoS overrides: expected a map of topic names to QoS settings",
                          Location(path, 1))
    out = {}
    for topic, settings in document.items():
        where = Location(path, _line_of(text, str(topic)))
        if not isinstance(settings, dict):
            raise LaunchError(f"QoS overrides: '{topic}' needs a map (reliability, durability, "
                              "history, depth)", where)
        unknown = set(settings) - {"reliability", "durability", "history", "depth"}
        if unknown:
            raise LaunchError(f"QoS overrides: '{topic}' has unknown keys "
                              f"{', '.join(sorted(unknown))}; expected reliability, "
                              "durability, history, depth", where)
        depth = settings.get("depth", 10)
        if not isinstance(depth, int) or isinstance(depth, bool) or depth < 1:
            raise LaunchError(f"QoS overrides: '{topic}': depth is a whole number ≥ 1, got "
                              f"{depth!r}", where)
        named = {p: None if settings.get(p) is None else str(settings[p])
                 for p in ("history", "reliability", "durability")}
        try:
            out[str(topic)] = QoS().with_policies(depth=depth, **named)
        except QoSPolicyError as exc:
            raise LaunchError(f"QoS overrides: '{topic}': {exc}", where) from None
    return out


def _line_of(text: str, key: str) -> int:
    for number, line in enumerate(text.splitlines(), 1):
        if line.lstrip().startswith((f"{key}:", f"'{key}':", f'"{key}":')):
            return number
    return 1


class Recorder:
    """Subscribes to topics (all of them with `everything`, found as they appear) and writes
    every message with its arrival time and its publishers' QoS."""

    def __init__(self, node: Node, writer: BagWriter, topics: list[str], everything: bool,
                 overrides: dict[str, QoS] | None = None) -> None:
        self.node, self.writer = node, writer
        self.topics, self.everything = set(topics), everything
        self.overrides = overrides or {}
        self.counts: dict[str, int] = {}

    def discover(self) -> None:
        for name, info in graph.topics(self.node.graph_session()).items():
            if name in self.counts or not info.publishers:
                continue
            if self.everything or name in self.topics:
                offered = [q for q in (QoS.from_key(e.qos) for e in info.publishers)
                           if q is not None]
                self._subscribe(name, sorted(info.types)[0], offered)

    def _subscribe(self, topic: str, type_name: str, offered: list[QoS]) -> None:
        self.writer.add(topic, type_name, offered)
        self.counts[topic] = 0

        def write(payload: bytes, topic: str = topic) -> None:
            self.writer.write(topic, time.time_ns(), payload)
            self.counts[topic] += 1

        # Transient local unless overridden: latched topics (/robot_description) are recorded.
        qos = self.overrides.get(topic, QoS(depth=1000, transient_local=True))
        self.node.create_subscription(type_name, topic, write, qos, raw=True)

    def run(self, duration: float | None) -> None:
        end = None if duration is None else time.monotonic() + duration
        next_scan = 0.0
        try:
            while end is None or time.monotonic() < end:
                if time.monotonic() >= next_scan:
                    self.discover()
                    next_scan = time.monotonic() + 1.0
                self.node.spin_once(0.05)
        except KeyboardInterrupt:
            pass
        self.writer.close()


def describe(path: Path) -> str:
    metadata = _metadata(path)
    with Reader(path) as reader:
        files = metadata.get("relative_file_paths") or []
        lines = [f"Files:             {', '.join(files)}",
                 f"Bag size:          {size_text(sum(f.stat().st_size for f in path.iterdir()))}",
                 f"Storage id:        {metadata.get('storage_identifier', '')}",
                 f"ROS Distro:        {metadata.get('ros_distro', '')}",
                 f"Duration:          {reader.duration / 1e9:.3f} s",
                 f"Start:             {reader.start_time / 1e9:.3f}",
                 f"End:               {reader.end_time / 1e9:.3f}",
                 f"Messages:          {reader.message_count}",
                 "Topic information:"]
        for connection in reader.connections:
            lines.append(f"  Topic: {connection.topic} | Type: {connection.msgtype} | "
                         f"Count: {connection.msgcount} | Serialization Format: cdr")
    return "\n".join(lines)


def _metadata(path: Path) -> dict[str, Any]:
    try:
        return yaml.safe_load((path / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
    except (OSError, KeyError, TypeError, yaml.YAMLError):
        return {}


def size_text(count: float, units: tuple[str, ...] = ("B", "KiB", "MiB", "GiB")) -> str:
    """A number of bytes as `ros2 bag info` says it (rosbag's `info` names them KB, MB, GB)."""
    for unit in units[:-1]:
        if count < 1024:
            return f"{count:.1f} {unit}"
        count /= 1024
    return f"{count:.1f} {units[-1]}"


class Pause:
    """Playback paused and resumed from the terminal (or whatever feeds stdin): a line (Enter)
    toggles, as space does in ros2 bag play's keyboard controls."""

    def __init__(self, paused: bool) -> None:
        self.running = threading.Event()
        if not paused:
            self.running.set()
        if sys.stdin is not None and (paused or sys.stdin.isatty()):
            threading.Thread(target=self._keys, daemon=True).start()
        if paused:
            print("paused: press Enter to play (and again to pause)", flush=True)

    def _keys(self) -> None:
        for _ in sys.stdin:
            if self.running.is_set():
                self.running.clear()
                print("paused", flush=True)
            else:
                self.running.set()
                print("playing", flush=True)


def play(node: Node, path: Path, rate: float, loop: bool, *, topics: list[str] | None = None,
         clock: float | None = None, paused: bool = False, offset: float = 0.0) -> int:
    """Publish the bag's messages at their recorded pace (times `rate`), each topic with the
    QoS its publishers offered; `clock` Hz: /clock from the bag's time, as `ros2 bag play
    --clock`. Returns how many were sent."""
    if rate <= 0:
        raise LaunchError(f"--rate must be > 0, got {rate}")
    sent = 0
    with Reader(path) as reader:
        chosen = [c for c in reader.connections if not topics or c.topic in topics]
        if topics:
            missing = sorted(set(topics) - {c.topic for c in chosen})
            if missing:
                known = sorted({c.topic for c in reader.connections})
                raise LaunchError(f"the bag has no topic {', '.join(missing)}; it has "
                                  f"{', '.join(known)}")
        publishers = {c.id: node.create_publisher(
            c.msgtype, c.topic, replayed_qos(getattr(c.ext, "offered_qos_profiles", ())))
            for c in chosen}
        clock_pub = node.create_publisher("rosgraph_msgs/msg/Clock", "/clock",
                                          QoS(depth=1, reliable=False)) if clock else None
        pause = Pause(paused)
        time.sleep(0.3)  # let subscribers find the publishers
        first = reader.start_time + int(offset * 1e9)
        while True:
            next_clock = 0.0
            start_wall = time.monotonic()
            for connection, stamp, data in reader.messages(connections=chosen, start=first):
                while True:
                    if not pause.running.is_set():
                        held = time.monotonic()
                        pause.running.wait()
                        start_wall += time.monotonic() - held
                    delay = (stamp - first) / 1e9 / rate - (time.monotonic() - start_wall)
                    if clock_pub is not None and time.monotonic() >= next_clock:
                        bag_now = first + int((time.monotonic() - start_wall) * rate * 1e9)
                        _publish_clock(node, clock_pub, min(bag_now, stamp))
                        next_clock = time.monotonic() + 1.0 / clock
                    if delay <= 0:
                        break
                    time.sleep(min(delay, 1.0 / clock if clock else delay))
                publishers[connection.id].publish_raw(bytes(data))
                sent += 1
            if not loop:
                return sent


def _publish_clock(node: Node, publisher: Any, stamp: int) -> None:
    sec, nanosec = divmod(stamp, 1_000_000_000)
    publisher.publish(node.message("rosgraph_msgs/msg/Clock",
                                   clock={"sec": sec, "nanosec": nanosec}))
