"""rosbag.bag: ROS 1 bag files (format 2.0) read and written through rosbags, with launcher's
rospy messages and rospy.Time stamps.

What differs from ROS 1's rosbag: bags of format 1.2 and encrypted bags are refused (rosbags
reads neither); a connection header keeps topic, type, md5sum, message_definition, callerid
and latching (what rosbags stores); a raw message's position is None; appending rewrites the
bag into a new file that replaces it at close (rosbags writes only new files).
"""

from __future__ import annotations

import collections
import io
import time
from collections.abc import Callable, Iterator
from operator import attrgetter
from pathlib import Path
from typing import Any

import rospy
from rosbags.typesys.msg import denormalize_msgtype

from rosbag import summary
from rosbag._recording import BagOpenError, Recording, StreamPath, open_reader
from rosbag._ros1 import ros1_types

found_lz4 = True  # (rosbags writes and reads LZ4 chunks itself)


class ROSBagException(Exception):
    """Base class for exceptions in rosbag."""

    def __init__(self, value: Any = None) -> None:
        self.value = value
        self.args = (value,)

    def __str__(self) -> str:
        return str(self.value)


class ROSBagFormatException(ROSBagException):
    """The bag file's format is broken or not one this reads."""

    def __init__(self, value: Any) -> None:
        super().__init__(value)


class ROSBagUnindexedException(ROSBagException):
    """The bag has no index (its recording was cut off)."""

    def __init__(self, *args: Any) -> None:
        super().__init__("Unindexed bag")


class ROSBagEncryptNotSupportedException(ROSBagException):
    """Encryption was asked for and is not supported."""

    def __init__(self, value: Any) -> None:
        super().__init__(value)


class ROSBagEncryptException(ROSBagException):
    """Encrypting or decrypting failed."""

    def __init__(self, value: Any) -> None:
        super().__init__(value)


class Compression:
    """Allowable compression types."""

    NONE = "none"
    BZ2 = "bz2"
    LZ4 = "lz4"


BagMessage = collections.namedtuple("BagMessage", "topic message timestamp")
BagMessageWithConnectionHeader = collections.namedtuple(
    "BagMessageWithConnectionHeader", "topic message timestamp connection_header")


class ComparableMixin:
    """Rich comparisons from one `_cmpkey()`."""

    def _compare(self, other: Any, method: Callable[[Any, Any], bool]) -> Any:
        try:
            return method(self._cmpkey(), other._cmpkey())
        except (AttributeError, TypeError):
            return NotImplemented

    def _cmpkey(self) -> Any:
        raise NotImplementedError

    def __lt__(self, other: Any) -> Any:
        return self._compare(other, lambda s, o: s < o)

    def __le__(self, other: Any) -> Any:
        return self._compare(other, lambda s, o: s <= o)

    def __eq__(self, other: Any) -> Any:
        return self._compare(other, lambda s, o: s == o)

    def __ge__(self, other: Any) -> Any:
        return self._compare(other, lambda s, o: s >= o)

    def __gt__(self, other: Any) -> Any:
        return self._compare(other, lambda s, o: s > o)

    def __ne__(self, other: Any) -> Any:
        return self._compare(other, lambda s, o: s != o)

    __hash__ = None  # type: ignore[assignment]


_COMPRESSIONS = (Compression.NONE, Compression.BZ2, Compression.LZ4)


def _check_compression(compression: str) -> str:
    if compression not in _COMPRESSIONS:
        raise ValueError(f"compression must be one of: {', '.join(_COMPRESSIONS)}")
    return compression


def _check_threshold(chunk_threshold: int) -> int:
    if chunk_threshold < 0:
        raise ValueError("chunk_threshold must be greater than or equal to zero")
    return chunk_threshold


def nanoseconds(stamp: Any) -> int:
    """A rospy/genpy Time (or seconds as a number) in nanoseconds."""
    if hasattr(stamp, "to_nsec"):
        return int(stamp.to_nsec())
    if hasattr(stamp, "secs"):
        return int(stamp.secs) * 1_000_000_000 + int(stamp.nsecs)
    return int(round(float(stamp) * 1e9))


def stamp(ns: int) -> Any:
    """rospy.Time of nanoseconds."""
    return rospy.Time(*divmod(ns, 1_000_000_000))


class Bag:
    """A ROS 1 bag file, opened to read ('r'), write ('w', truncating) or append ('a')."""

    def __init__(self, f: Any, mode: str = "r", compression: str = Compression.NONE,
                 chunk_threshold: int = 768 * 1024, allow_unindexed: bool = False,
                 options: dict[str, Any] | None = None, skip_index: bool = False) -> None:
        if options is not None:
            if type(options) is not dict:
                raise ValueError("options must be of type dict")
            compression = options.get("compression", compression)
            chunk_threshold = options.get("chunk_threshold", chunk_threshold)
        self._compression = _check_compression(compression)
        self._chunk_threshold = _check_threshold(chunk_threshold)
        if not f:
            raise ValueError("filename (or stream) is invalid")
        if mode not in ("r", "w", "a"):
            raise ValueError(f'mode "{mode}" is invalid')
        self._mode, self._skip_index = mode, skip_index
        stream = isinstance(f, io.IOBase)
        self._filename = None if stream else str(f)
        self._version: int | None = 200
        self._reader: Any = None  # rosbags' Reader: the file's, or a snapshot of a recording
        self._recording: Recording | None = None
        self._decoders: dict[int, tuple[Callable[[Any], Any], Any]] = {}
        self._closed = False
        try:
            if mode == "r":
                self._reader = open_reader(StreamPath(f) if stream else Path(f))
            elif stream and mode == "a":
                raise ROSBagException("appending to a stream is not supported: give the "
                                      "bag's file name")
            else:
                self._recording = Recording(f if stream else Path(f), compression,
                                            chunk_threshold, append=mode == "a")
        except BagOpenError as exc:
            self._closed = True
            if exc.unindexed:
                raise ROSBagUnindexedException() from None
            raise ROSBagException(f"{self._filename or 'stream'}: {exc}") from None
        except OSError:
            self._closed = True
            raise

    def __iter__(self) -> Iterator[Any]:
        return self.read_messages()

    def __enter__(self) -> Bag:
        return self

    def __exit__(self, exc_type: Any, exc_value: Any, traceback: Any) -> None:
        self.close()

    def __str__(self) -> str:
        return summary.describe(self, self._contents())

    # --- properties -----------------------------------------------------------------------
    @property
    def options(self) -> dict[str, Any]:
        """The bag options: compression and chunk_threshold."""
        return {"compression": self._compression, "chunk_threshold": self._chunk_threshold}

    filename = property(attrgetter("_filename"), doc="The file's name (None for a stream).")
    version = property(attrgetter("_version"), doc="The format's version, 200 for 2.0.")
    mode = property(attrgetter("_mode"), doc="'r', 'w' or 'a'.")

    @property
    def size(self) -> int:
        """The file's size in bytes."""
        handle = self._file()
        position = handle.tell()
        handle.seek(0, io.SEEK_END)
        size = handle.tell()
        handle.seek(position)
        return size

    def _set_compression(self, compression: str) -> None:
        self._compression = _check_compression(compression)
        if self._recording is not None:
            self._recording.set_compression(compression)

    def _set_chunk_threshold(self, chunk_threshold: int) -> None:
        self._chunk_threshold = _check_threshold(chunk_threshold)
        if self._recording is not None:
            self.flush()
            self._recording.writer.chunk_threshold = chunk_threshold

    compression = property(attrgetter("_compression"), _set_compression,
                           doc="The compression of chunks written from now on.")
    chunk_threshold = property(attrgetter("_chunk_threshold"), _set_chunk_threshold,
                               doc="The uncompressed size at which a chunk is written.")

    # --- reading --------------------------------------------------------------------------
    def read_messages(self, topics: Any = None, start_time: Any = None, end_time: Any = None,
                      connection_filter: Callable[..., bool] | None = None, raw: bool = False,
                      return_connection_header: bool = False) -> Iterator[Any]:
        """BagMessage(topic, message, timestamp) of each message, in time order, optionally
        only the given topics, times (inclusive) and connections. `raw`: the message is
        (type, bytes, md5sum, position, class)."""
        reader = self._contents()
        if topics and isinstance(topics, str):
            topics = [topics]
        chosen = summary.connections(reader, topics, connection_filter)
        start = nanoseconds(start_time) if start_time else None
        stop = nanoseconds(end_time) + 1 if end_time else None
        return self._messages(reader, chosen, start, stop, raw, return_connection_header)

    def _messages(self, reader: Any, chosen: list[Any], start: int | None, stop: int | None,
                  raw: bool, with_header: bool) -> Iterator[Any]:
        if not chosen:  # (rosbags reads every connection when given none)
            return
        for connection, ns, data in reader.messages(chosen, start, stop):
            decode, cls = self._decoder(connection)
            message = (denormalize_msgtype(connection.msgtype), bytes(data), connection.digest,
                       None, cls) if raw else decode(data)
            if with_header:
                yield BagMessageWithConnectionHeader(connection.topic, message, stamp(ns),
                                                     summary.header(connection))
            else:
                yield BagMessage(connection.topic, message, stamp(ns))

    def _decoder(self, connection: Any) -> tuple[Callable[[Any], Any], Any]:
        found = self._decoders.get(connection.id)
        if found is None:
            try:
                found = ros1_types().reader(connection.msgtype, connection.digest,
                                            connection.msgdef.data)
            except ValueError as exc:
                raise ROSBagException(str(exc)) from None
            self._decoders[connection.id] = found
        return found

    def get_message_count(self, topic_filters: Any = None) -> int:
        """How many messages the bag holds, optionally only on the given topic(s)."""
        if topic_filters is not None:
            info = self.get_type_and_topic_info(topic_filters)
            return sum(topic.message_count for topic in info.topics.values())
        return sum(len(entries) for entries in self._contents().indexes.values())

    def get_start_time(self) -> float:
        """The time of the bag's first message, in seconds."""
        return summary.span(self._contents(), ROSBagException)[0] / 1e9

    def get_end_time(self) -> float:
        """The time of the bag's last message, in seconds."""
        return summary.span(self._contents(), ROSBagException)[1] / 1e9

    def get_type_and_topic_info(self, topic_filters: Any = None) -> Any:
        """TypesAndTopicsTuple(msg_types {type: md5sum}, topics {topic: TopicTuple(msg_type,
        message_count, connections, frequency)}), optionally only the given topic(s)."""
        return summary.types_and_topics(self._contents(), topic_filters)

    def get_compression_info(self) -> Any:
        """CompressionTuple(compression, uncompressed, compressed) of the bag's chunks."""
        return summary.compression(self._contents(), self._compression)

    # --- writing --------------------------------------------------------------------------
    def write(self, topic: str, msg: Any, t: Any = None, raw: bool = False,
              connection_header: dict[str, Any] | None = None) -> None:
        """Write a message (or, `raw`, a (type, bytes, md5sum[, position], class) tuple) on
        a topic at time `t` (now if None)."""
        recording = self._writing()
        if not topic:
            raise ValueError("topic is invalid")
        if not msg:
            raise ValueError("msg is invalid")
        ns = time.time_ns() if t is None else nanoseconds(t)
        if raw:
            if len(msg) not in (4, 5):
                raise ValueError("msg must be of length 4 or 5")
            type_name, data, md5sum = msg[0], msg[1], msg[2]
        else:
            type_name, data = ros1_types().serialize(msg)
            md5sum = ""
        connection = recording.connection(topic, type_name, md5sum, connection_header)
        recording.writer.write(connection, ns, bytes(data))
        self._reader_stale()

    def flush(self) -> None:
        """Write the open chunk to the file, so that reads see every message."""
        if self._closed:
            raise ValueError("I/O operation on closed bag")
        if self._recording is not None:
            self._recording.flush()

    def reindex(self) -> Iterator[int]:
        """Rebuild the index of an unindexed bag: not supported (rosbags reads indexed bags
        only); an indexed bag needs none."""
        raise ROSBagException("reindexing is not supported by launcher's rosbag (rosbags reads "
                              "indexed bags only)")

    def set_encryptor(self, encryptor: str | None = None, param: Any = None) -> None:
        """Only None (no encryption) is taken: rosbags reads and writes no encrypted bags."""
        if encryptor:
            raise ROSBagEncryptNotSupportedException(
                f"encryptor {encryptor!r} is not supported: launcher's rosbag writes and reads "
                "unencrypted bags only")

    def close(self) -> None:
        """Close the bag (writing its index when written); closing twice does nothing."""
        if self._closed:
            return
        self._closed = True
        self._reader_stale()
        if self._recording is not None:
            self._recording.close()

    # --- the file --------------------------------------------------------------------------
    def _file(self) -> Any:
        if self._closed:
            raise ValueError("I/O operation on closed bag")
        return self._recording.file if self._recording is not None else self._reader.bio

    def _writing(self) -> Recording:
        if self._closed:
            raise ValueError("I/O operation on closed bag")
        if self._recording is None:
            raise ValueError("bag is open for reading ('r'): open it with mode 'w' or 'a' "
                             "to write")
        return self._recording

    def _contents(self) -> Any:
        """The rosbags Reader over every message written so far."""
        if self._closed:
            raise ValueError("I/O operation on closed bag")
        if self._reader is None and self._recording is not None:
            self._reader = self._recording.snapshot()
        return self._reader

    def _reader_stale(self) -> None:
        if self._reader is not None:
            self._reader.close()
        self._reader = None
