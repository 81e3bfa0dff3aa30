"""rosbag2 bags in MCAP storage: record topics as received (CDR), and play them back."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

from rosbags.rosbag2 import Reader, StoragePlugin, Writer

from launcher.bus import graph
from launcher.bus.node import Node
from launcher.bus.qos import QoS
from launcher.bus.types import registry
from launcher.errors import LaunchError


class Recorder:
    """Subscribes to topics (all of them with `everything`, found as they appear) and writes
    every message with its arrival time."""

    def __init__(self, node: Node, output: Path, topics: list[str], everything: bool) -> None:
        if output.exists():
            raise LaunchError(f"'{output}' already exists; choose another output folder")
        self.node, self.topics, self.everything = node, set(topics), everything
        self.writer = Writer(output, version=9, storage_plugin=StoragePlugin.MCAP)
        self.writer.open()
        self.connections: dict[str, Any] = {}
        self.counts: dict[str, int] = {}

    def discover(self) -> None:
        for name, info in graph.topics(self.node.graph_session()).items():
            if name in self.connections or not info.publishers:
                continue
            if self.everything or name in self.topics:
                self._subscribe(name, sorted(info.types)[0])

    def _subscribe(self, topic: str, type_name: str) -> None:
        types = registry()
        types.ensure(type_name)
        connection = self.writer.add_connection(topic, type_name, typestore=types.store)
        self.connections[topic] = connection
        self.counts[topic] = 0

        def write(payload: bytes, connection: Any = connection, topic: str = topic) -> None:
            self.writer.write(connection, time.time_ns(), payload)
            self.counts[topic] += 1

        # Transient local: latched topics (/robot_description) are recorded too.
        self.node.create_subscription(type_name, topic, write,
                                      QoS(depth=1000, transient_local=True), raw=True)

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
    with Reader(path) as reader:
        files = sorted(p.name for p in path.iterdir() if p.suffix in (".mcap", ".db3"))
        lines = [f"Files:             {', '.join(files)}",
                 f"Duration:          {reader.duration / 1e9:.3f} s",
                 f"Start:             {reader.start_time / 1e9:.3f}",
                 f"End:               {reader.end_time / 1e9:.3f}",
                 f"Messages:          {reader.message_count}",
                 "Topic information:"]
        for connection in reader.connections:
            lines.append(f"  Topic: {connection.topic} | Type: {connection.msgtype} | "
                         f"Count: {connection.msgcount} | Serialization Format: cdr")
    return "\n".join(lines)


def play(node: Node, path: Path, rate: float, loop: bool) -> int:
    if rate <= 0:
        raise LaunchError(f"--rate must be > 0, got {rate}")
    sent = 0
    with Reader(path) as reader:
        publishers = {c.id: node.create_publisher(c.msgtype, c.topic, QoS(depth=1000))
                      for c in reader.connections}
        time.sleep(0.3)  # let subscribers find the publishers
        while True:
            start_wall, start_bag = time.monotonic(), None
            for connection, stamp, data in reader.messages():
                start_bag = stamp if start_bag is None else start_bag
                delay = (stamp - start_bag) / 1e9 / rate - (time.monotonic() - start_wall)
                if delay > 0:
                    time.sleep(delay)
                publishers[connection.id].publish_raw(bytes(data))
                sent += 1
            if not loop:
                return sent
