"""The file side of a bag: rosbags' Reader for one opened to read, rosbags' Writer for one
opened to write or append, and a Reader over what a Writer has written so far (ROS 1's
rosbag reads a bag while it writes it).

rosbags writes only new files, so a bag opened to append is copied (its connections and
messages, as stored) into a new file beside it, which replaces it when the bag is closed; a
bag written to a stream is written to a temporary file and copied into the stream at close.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from collections import defaultdict
from pathlib import Path
from typing import IO, Any

from rosbags.interfaces import Connection
from rosbags.rosbag1 import Reader, ReaderError, Writer
from rosbags.rosbag1.reader import IndexData

from launcher.bus.types import normalize
from rosbag._ros1 import ros1_types


class BagOpenError(Exception):
    """A bag that rosbags cannot open; `unindexed` when only its index is missing."""

    def __init__(self, text: str, unindexed: bool = False) -> None:
        super().__init__(text)
        self.unindexed = unindexed


class StreamPath:
    """An open binary stream as rosbags' Reader takes a path (exists, is_dir, open)."""

    def __init__(self, stream: IO[bytes]) -> None:
        self.stream = stream

    def exists(self) -> bool:
        """Always: the stream is there."""
        return True

    def is_dir(self) -> bool:
        """Never: a stream is one file."""
        return False

    def open(self, *_args: Any, **_kwargs: Any) -> IO[bytes]:
        """The stream itself, from its start."""
        self.stream.seek(0)
        return self.stream

    def __str__(self) -> str:
        return str(getattr(self.stream, "name", "<stream>"))


def open_reader(source: Path | StreamPath) -> Reader:
    """rosbags' Reader on a bag, opened (BagOpenError when it cannot be)."""
    reader = Reader(source)
    try:
        reader.open()
    except ReaderError as exc:
        text = str(exc)
        raise BagOpenError(text, unindexed="not indexed" in text) from None
    return reader


class Recording:
    """rosbags' Writer on a new file; `target` (a path or a stream) gets it at close."""

    def __init__(self, target: Path | IO[bytes], compression: str, chunk_threshold: int,
                 append: bool = False) -> None:
        self.target = target
        if isinstance(target, Path):
            self.path = target.with_name(f".{target.name}.{os.getpid()}.new") if append \
                else target
            if not append:
                target.unlink(missing_ok=True)
        else:
            handle, name = tempfile.mkstemp(prefix="rosbag-", suffix=".bag")
            os.close(handle)
            self.path = Path(name)
            self.path.unlink()
        self.writer = Writer(self.path)
        if compression != "none":
            self.writer.set_compression(Writer.CompressionFormat[compression.upper()])
        self.writer.chunk_threshold = chunk_threshold
        self.writer.open()
        self.topics: dict[str, Connection] = {}
        if append and isinstance(target, Path) and target.exists():
            self._copy(target)

    @property
    def file(self) -> Any:
        """The file being written."""
        return self.writer.bio

    def _copy(self, source: Path) -> None:
        reader = open_reader(source)
        try:
            made: dict[tuple[Any, ...], Connection] = {}
            ids: dict[int, Connection] = {}
            for old in reader.connections:
                key = (old.topic, old.msgtype, old.msgdef.data, old.digest,
                       getattr(old.ext, "callerid", None), getattr(old.ext, "latching", None))
                if key not in made:
                    made[key] = self.writer.add_connection(
                        key[0], key[1], msgdef=key[2], md5sum=key[3], callerid=key[4],
                        latching=key[5])
                ids[old.id] = self.topics[old.topic] = made[key]
            for connection, stamp, data in reader.messages():
                self.writer.write(ids[connection.id], stamp, data)
        finally:
            reader.close()

    def connection(self, topic: str, type_name: str, md5sum: str,
                   header: dict[str, Any] | None) -> Connection:
        """The topic's connection (one a topic, as ROS 1's rosbag writes), made at its first
        message from the type's definition or the connection header given."""
        found = self.topics.get(topic)
        if found is not None:
            return found
        msgdef, digest = ros1_types().definition(type_name)
        fields = {key: value.decode() if isinstance(value, bytes) else str(value)
                  for key, value in (header or {}).items()}
        latching = fields.get("latching")
        found = self.writer.add_connection(
            topic, normalize(fields.get("type", type_name)),
            msgdef=fields.get("message_definition", msgdef),
            md5sum=fields.get("md5sum", md5sum or digest), callerid=fields.get("callerid"),
            latching=int(latching) if latching and latching.isdigit() else None)
        self.topics[topic] = found
        return found

    def set_compression(self, compression: str) -> None:
        """Chunks from now on are compressed so ('none', 'bz2' or 'lz4')."""
        self.flush()
        bio, self.writer.bio = self.writer.bio, None  # (rosbags sets it before opening only)
        try:
            if compression == "none":
                self.writer.compression_format, self.writer.compressor = "none", bytes
            else:
                self.writer.set_compression(Writer.CompressionFormat[compression.upper()])
        finally:
            self.writer.bio = bio

    def flush(self) -> None:
        """Write the open chunk, so that a reader sees every message."""
        self.writer.write_chunk(self.writer.chunks[-1])
        self.writer.bio.flush()

    def snapshot(self) -> Reader:
        """A Reader over every message written so far (flushed first)."""
        self.flush()
        reader = Reader(self.path)
        reader.bio = self.path.open("rb")
        reader.connections = list(self.writer.connections)
        entries: dict[int, list[IndexData]] = defaultdict(list)
        for chunk in self.writer.chunks:
            if chunk.pos == -1:
                continue
            reader.bio.seek(chunk.pos)
            reader.chunks[chunk.pos] = reader.read_chunk()
            for connection, items in chunk.connections.items():
                entries[connection] += [IndexData(t, chunk.pos, at) for t, at in items]
        reader.indexes = {c.id: sorted(entries[c.id]) for c in reader.connections}
        return reader

    def close(self) -> None:
        """Write the index, and put the bag where it belongs."""
        self.writer.close()
        if isinstance(self.target, Path):
            if self.path != self.target:
                os.replace(self.path, self.target)
            return
        with self.path.open("rb") as written:
            shutil.copyfileobj(written, self.target)
        self.path.unlink()
        self.target.close()
