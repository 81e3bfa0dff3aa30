"""Reading the user's files (launch files, parameters, hooks, worlds, configs) so that no file
can hang or flood the launcher: only regular files are read (a FIFO, `/dev/zero`, a socket or
a folder named as one is refused, before anything blocks on it), up to a size limit; YAML
nested past any real file's depth is refused where it gets there (check_yaml_depth), before
a parser would recurse past Python's limit.
"""

from __future__ import annotations

import errno
import os
import stat
from pathlib import Path

from launcher.errors import LaunchError, Location

MAX_BYTES = 64 << 20  # 64 MiB: far past any launch file, world or URDF

_KINDS = ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
          (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
          (stat.S_ISSOCK, "a socket"))


def _kind(mode: int) -> str:
    return next((name for test, name in _KINDS if test(mode)), "not a regular file")


def read_bytes(path: str | os.PathLike[str], limit: int = MAX_BYTES) -> bytes:
    """The file's bytes. OSError as usual for a missing or unreadable file; LaunchError (at the
    file) for one that is not a regular file or is larger than `limit`."""
    where = Location(str(path))
    check_readable(path, limit)
    descriptor = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    with os.fdopen(descriptor, "rb") as handle:
        info = os.fstat(descriptor)  # what was opened (it may have changed since the stat)
        if not stat.S_ISREG(info.st_mode):
            raise LaunchError(f"{_kind(info.st_mode)}, not a regular file: expected a file to "
                              f"read", where)
        data = handle.read(limit + 1)
    if len(data) > limit:
        raise LaunchError(f"larger than {limit >> 20} MiB: not a file launcher reads", where)
    return data


def read_text(path: str | os.PathLike[str], limit: int = MAX_BYTES) -> str:
    """The file as UTF-8 text (UnicodeDecodeError when it is not)."""
    return read_bytes(path, limit).decode("utf-8")


def check_readable(path: str | os.PathLike[str], limit: int = MAX_BYTES) -> None:
    """Refuse what `read_bytes` would refuse, before anything opens the file (a Python launch
    file that Python reads). A folder is IsADirectoryError, as open() has it."""
    info = os.stat(path)
    if stat.S_ISDIR(info.st_mode):
        raise IsADirectoryError(errno.EISDIR, os.strerror(errno.EISDIR), str(path))
    if not stat.S_ISREG(info.st_mode):
        raise LaunchError(f"{_kind(info.st_mode)}, not a regular file: expected a file to "
                          f"read", Location(str(Path(path))))
    if info.st_size > limit:
        raise LaunchError(f"larger than {limit >> 20} MiB ({info.st_size >> 20} MiB): not a "
                          f"file launcher reads", Location(str(Path(path))))


MAX_YAML_DEPTH = 100  # collections within collections: far past any launch file or config


def check_yaml_depth(text: str, file: str, limit: int = MAX_YAML_DEPTH) -> None:
    """Refuse a YAML document nested deeper than `limit`, at the place it gets there (a parser
    would recurse past Python's limit first). The cheap look at indentation and brackets
    comes first; only a deep-looking text is scanned event by event."""
    if max((len(line) - len(line.lstrip(" ")) for line in text.splitlines()), default=0) \
            < limit and text.count("[") + text.count("{") < limit:
        return
    import yaml

    try:
        loader: type = yaml.CSafeLoader
    except AttributeError:  # PyYAML without libyaml
        loader = yaml.SafeLoader
    depth = 0
    for event in yaml.parse(text, Loader=loader):
        if isinstance(event, yaml.CollectionStartEvent):
            depth += 1
            if depth > limit:
                mark = event.start_mark
                raise LaunchError(f"nested {depth} levels deep; launcher reads YAML nested up "
                                  f"to {limit} levels",
                                  Location(file, mark.line + 1, mark.column + 1))
        elif isinstance(event, yaml.CollectionEndEvent):
            depth -= 1
