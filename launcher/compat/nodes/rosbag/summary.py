"""What a bag holds, read off rosbags' Reader (its connections and per-connection index):
connections chosen by topic and filter, message times and counts, type and topic info,
compression, and the text of `rosbag info` (Bag's str)."""

from __future__ import annotations

import collections
import heapq
import statistics
import time
from collections.abc import Callable
from typing import Any

from rosbags.rosbag1.reader import Header, RecordType, read_uint32
from rosbags.typesys.msg import denormalize_msgtype

TopicTuple = collections.namedtuple("TopicTuple",
                                    ["msg_type", "message_count", "connections", "frequency"])
TypesAndTopicsTuple = collections.namedtuple("TypesAndTopicsTuple", ["msg_types", "topics"])
CompressionTuple = collections.namedtuple("CompressionTuple",
                                          ["compression", "uncompressed", "compressed"])


def canonical(topic: str) -> str:
    """A topic as rosbags names it: no doubled or trailing slashes."""
    return "/" * topic.startswith("/") + "/".join(part for part in topic.split("/") if part)


def header(connection: Any) -> dict[str, bytes]:
    """The connection header ROS 1's rosbag gives (its values bytes, as read from a file)."""
    fields = {"topic": connection.topic, "type": denormalize_msgtype(connection.msgtype),
              "md5sum": connection.digest, "message_definition": connection.msgdef.data}
    if getattr(connection.ext, "callerid", None) is not None:
        fields["callerid"] = connection.ext.callerid
    if getattr(connection.ext, "latching", None) is not None:
        fields["latching"] = str(connection.ext.latching)
    return {key: value.encode() for key, value in fields.items()}


def connections(reader: Any, topics: Any = None,
                connection_filter: Callable[..., bool] | None = None) -> list[Any]:
    """The reader's connections on `topics` (all if none) that `connection_filter` takes."""
    wanted = {canonical(topic) for topic in topics} if topics else None
    chosen = []
    for connection in reader.connections:
        if wanted is not None and canonical(connection.topic) not in wanted:
            continue
        if connection_filter and not connection_filter(
                connection.topic, denormalize_msgtype(connection.msgtype), connection.digest,
                connection.msgdef.data, header(connection)):
            continue
        chosen.append(connection)
    return chosen


def span(reader: Any, error: type[Exception]) -> tuple[int, int]:
    """(first, last) message time in nanoseconds; `error` when the bag has no message."""
    entries = [index for index in reader.indexes.values() if index]
    if not entries:
        raise error("Bag contains no message")
    return min(index[0].time for index in entries), max(index[-1].time for index in entries)


def types_and_topics(reader: Any, topic_filters: Any = None) -> TypesAndTopicsTuple:
    """rosbag's get_type_and_topic_info() of the reader's bag."""
    types: dict[str, str] = {}
    for connection in sorted(reader.connections, key=lambda c: c.msgtype):
        types.setdefault(denormalize_msgtype(connection.msgtype), connection.digest)
    if topic_filters is not None and not isinstance(topic_filters, list):
        topic_filters = [topic_filters]
    names = sorted(set(topic_filters if topic_filters is not None
                       else (c.topic for c in reader.connections)))
    topics = {}
    for name in names:
        on_topic = connections(reader, [name])
        if not on_topic:
            continue
        times = [entry.time for entry in heapq.merge(*(reader.indexes[c.id] for c in on_topic))]
        periods = [(b - a) / 1e9 for a, b in zip(times, times[1:], strict=False)]
        median = statistics.median(periods) if periods else 0.0
        topics[name] = TopicTuple(denormalize_msgtype(on_topic[0].msgtype), len(times),
                                  len(on_topic), 1.0 / median if median > 0 else None)
    return TypesAndTopicsTuple(msg_types=types, topics=topics)


def compression(reader: Any, default: str) -> CompressionTuple:
    """The compression most chunks use, and the chunks' uncompressed and compressed bytes."""
    counts: collections.Counter[str] = collections.Counter()
    uncompressed = compressed = 0
    for position in reader.chunks:
        reader.bio.seek(position)
        found = Header.read(reader.bio, RecordType.CHUNK)
        counts[found.get_string("compression")] += 1
        uncompressed += found.get_uint32("size")
        compressed += read_uint32(reader.bio)
    name = max(sorted(counts), key=lambda k: counts[k]) if counts else default
    return CompressionTuple(name, uncompressed, compressed)


def _size(size: float) -> str:
    for suffix in ("KB", "MB", "GB", "TB", "PB"):
        size /= 1024.0
        if size < 1024.0:
            return f"{size:.1f} {suffix}"
    return "-"


def _when(secs: float) -> str:
    return time.strftime("%b %d %Y %H:%M:%S", time.localtime(secs)) + \
        f"{secs - int(secs):.2f}"[1:]


def describe(bag: Any, reader: Any) -> str:
    """`rosbag info`'s text of a bag."""
    rows = [("path", bag.filename)] if bag.filename else []
    rows.append(("version", "2.0"))
    count = sum(len(index) for index in reader.indexes.values())
    if count:
        first, last = (t / 1e9 for t in span(reader, ValueError))
        rows += [("duration", f"{last - first:.1f}s"),
                 ("start", f"{_when(first)} ({first:.2f})"),
                 ("end", f"{_when(last)} ({last:.2f})")]
    rows += [("size", _size(bag.size)), ("messages", str(count))]
    packed = compression(reader, "none")
    rows.append(("compression", packed.compression))
    info = types_and_topics(reader)
    width = max((len(t) for t in info.msg_types), default=0)
    rows += [("types" if n == 0 else "", f"{kind:<{width}} [{digest}]")
             for n, (kind, digest) in enumerate(info.msg_types.items())]
    topic_width = max((len(t) for t in info.topics), default=0)
    rows += [("topics" if n == 0 else "",
              f"{name:<{topic_width}}   {t.message_count} msg{'s' if t.message_count > 1 else ' '}"
              f" : {t.msg_type}") for n, (name, t) in enumerate(info.topics.items())]
    return "\n".join(f"{(key + ':') if key else '':<13}{value}" for key, value in rows)
