"""Files that hold launch data (run files naming the router, logs, parameter files with the
robot description) are the user's own: folders 0700, files 0600, whatever the umask."""

from __future__ import annotations

import contextlib
import os
from pathlib import Path
from typing import IO, Any


def private_folder(path: Path) -> Path:
    """Make `path` (and missing parents) and leave it 0700."""
    path.mkdir(parents=True, exist_ok=True)
    os.chmod(path, 0o700)
    return path


def open_private(path: Path, mode: str = "w", **kwargs: Any) -> IO[Any]:
    """`open()`, creating the file 0600 (an existing file is made 0600 too)."""

    def opener(name: str, flags: int) -> int:
        descriptor = os.open(name, flags, 0o600)
        os.fchmod(descriptor, 0o600)
        return descriptor

    return open(path, mode, opener=opener, **kwargs)  # noqa: SIM115 - the caller closes


def write_private(path: Path, text: str) -> None:
    with open_private(path, "w", encoding="utf-8") as handle:
        handle.write(text)


def create_once(path: Path, text: str) -> None:
    """Write `path` (0600, its folder 0700) unless it exists, under a temporary name linked
    into place: two processes making it at once end up with the same one."""
    private_folder(path.parent)
    temporary = path.with_name(f".{path.name}.{os.getpid()}.{os.urandom(4).hex()}")
    descriptor = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    with os.fdopen(descriptor, "w", encoding="utf-8") as handle:
        handle.write(text)
    try:
        os.link(temporary, path)
    except FileExistsError:
        pass  # another process was first: its file is the one
    finally:
        with contextlib.suppress(OSError):
            temporary.unlink()
