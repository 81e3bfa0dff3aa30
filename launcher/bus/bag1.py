"""ROS 1 bags (`.bag`, format 2.0), through rosbags: a writer with the rosbag2 writer's
interface (add, write, close), so bag.Recorder records into either; `rosbag info`'s summary;
and conversion between a `.bag` and a rosbag2 bag (for play, and `launcher bag convert`).
Messages travel as CDR on the graph and are stored in ROS 1's serialization, converted by
the type store that knows every type in use."""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

from launcher.bus.bag import size_text
from launcher.bus.interfaces import ros1_spelling
from launcher.bus.qos import QoS
from launcher.bus.types import registry
from launcher.errors import LaunchError

ROSBAG_UNITS = ("B", "KB", "MB", "GB")  # as `rosbag info` names them


def check_writable(path: Path) -> None:
    """A new `.bag` at `path`: said before anything is recorded when it cannot be."""
    folder = path.parent if str(path.parent) else Path(".")
    if path.exists():
        raise LaunchError(f"'{path}' already exists; choose another name (-O)")
    if not folder.is_dir():
        raise LaunchError(f"cannot write '{path}': the folder '{folder}' does not exist")
    try:  # a real try: permission bits, a read-only mount, /proc: whatever stops a write
        with tempfile.NamedTemporaryFile(dir=folder, prefix=".rosbag-probe-"):
            pass
    except OSError as exc:
        raise LaunchError(f"cannot write '{path}': the folder '{folder}' is not writable "
                          f"({exc.strerror})") from None


class Bag1Writer:
    """Writes one ROS 1 bag; messages come as CDR (the graph's) and are stored as ROS 1's."""

    def __init__(self, path: Path) -> None:
        from rosbags.rosbag1 import Writer

        check_writable(path)
        self.path = path
        self._writer = Writer(path)
        try:
            self._writer.open()
        except OSError as exc:
            raise LaunchError(f"cannot write '{path}': {exc.strerror}") from None
        self._connections: dict[str, tuple[Any, str]] = {}

    def add(self, topic: str, type_name: str, offered: list[QoS]) -> None:
        types = registry()
        types.ensure(type_name)
        latched = any(q.transient_local for q in offered)
        connection = self._writer.add_connection(topic, type_name, typestore=types.store,
                                                 callerid="/rosbag_record",
                                                 latching=1 if latched else None)
        self._connections[topic] = (connection, type_name)

    def write(self, topic: str, stamp: int, payload: bytes) -> None:
        connection, type_name = self._connections[topic]
        self._writer.write(connection, stamp, registry().store.cdr_to_ros1(payload, type_name))

    def close(self) -> None:
        self._writer.close()


def info(path: Path) -> str:
    """`rosbag info`'s summary of a ROS 1 bag."""
    from rosbags.rosbag1 import Reader

    reader = _opened(path, Reader)
    try:
        duration = reader.duration / 1e9 if reader.message_count else 0.0
        types = sorted({(c.msgtype, c.digest) for c in reader.connections})
        counts: dict[str, tuple[int, str]] = {}
        for connection in reader.connections:
            count, _ = counts.get(connection.topic, (0, connection.msgtype))
            counts[connection.topic] = (count + connection.msgcount, connection.msgtype)
        width = max((len(t) for t in counts), default=0)
        lines = [f"path:        {path}", "version:     2.0",
                 f"duration:    {duration:.1f}s",
                 f"start:       {reader.start_time / 1e9:.2f}" if reader.message_count
                 else "start:       -",
                 f"end:         {reader.end_time / 1e9:.2f}" if reader.message_count
                 else "end:         -",
                 f"size:        {size_text(path.stat().st_size, ROSBAG_UNITS)}",
                 f"messages:    {reader.message_count}", "compression: none"]
        for number, (kind, digest) in enumerate(types):
            lines.append(f"{'types:' if number == 0 else '':<13}{ros1_spelling(kind)} [{digest}]")
        for number, (topic, (count, kind)) in enumerate(sorted(counts.items())):
            lines.append(f"{'topics:' if number == 0 else '':<13}{topic:<{width}}   "
                         f"{count} msg{'' if count == 1 else 's'}    : {ros1_spelling(kind)}")
    finally:
        reader.close()
    return "\n".join(lines)


def to_rosbag2(path: Path, folder: Path) -> None:
    """Convert the ROS 1 bag at `path` into a new rosbag2 bag (MCAP) at `folder`."""
    _convert(path, folder, "mcap")


def convert(source: Path, target: Path) -> None:
    """`.bag` → rosbag2 (MCAP) folder, or a rosbag2 folder → `.bag`, by what `source` is."""
    if source.suffix == ".bag":
        if target.exists():
            raise LaunchError(f"'{target}' already exists; choose another output folder")
        _convert(source, target, "mcap")
    else:
        if not (source / "metadata.yaml").is_file():
            raise LaunchError(f"'{source}' is neither a ROS 1 bag (.bag) nor a rosbag2 bag "
                              "(a folder with metadata.yaml)")
        if target.suffix != ".bag":
            raise LaunchError(f"'{target}': a ROS 1 bag's name ends in .bag")
        check_writable(target)
        _convert(source, target, "")


def _convert(source: Path, target: Path, storage: str) -> None:
    from rosbags.convert import ConverterError
    from rosbags.convert import convert as rosbags_convert

    if not source.exists():
        raise LaunchError(f"'{source}': no such bag")
    try:
        rosbags_convert([source], target, storage or "mcap", 8 if storage else 9, None,
                        "file", registry().store, None, [], [], [], [])
    except ConverterError as exc:
        raise LaunchError(f"cannot convert '{source}': {exc}") from None


def temporary_rosbag2(path: Path) -> tempfile.TemporaryDirectory[str]:
    """A temporary folder holding `path` (a ROS 1 bag) as a rosbag2 bag, under `bag/`."""
    holder = tempfile.TemporaryDirectory(prefix="launcher-rosbag-")
    to_rosbag2(path, Path(holder.name) / "bag")
    return holder


def _opened(path: Path, reader: Any) -> Any:
    from rosbags.rosbag1 import ReaderError

    if not path.is_file():
        raise LaunchError(f"'{path}': no such bag")
    opened = reader(path)
    try:
        opened.open()
    except ReaderError as exc:
        raise LaunchError(f"'{path}' is not a ROS 1 bag: {exc}") from None
    return opened
