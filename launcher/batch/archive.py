"""A job's folder as one file and back: what travels from a node to the driver. Logs past a
size keep their end; nothing from a node may write outside the folder it is unpacked in."""

from __future__ import annotations

import io
import tarfile
import tempfile
from pathlib import Path

PER_FILE = 8 * 2**20  # bytes of one file that travel (its end)
IN_ALL = 64 * 2**20  # bytes of one job that travel


def pack(folder: Path) -> Path:
    """A .tar.gz of `folder` beside it; over-large files keep their last PER_FILE bytes."""
    fd, name = tempfile.mkstemp(prefix=f"{folder.name}-", suffix=".tar.gz")
    total = 0
    with open(fd, "wb") as out, tarfile.open(fileobj=out, mode="w:gz") as tar:
        for path in sorted(p for p in folder.rglob("*") if p.is_file() and not p.is_symlink()):
            size = path.stat().st_size
            if total >= IN_ALL:
                break
            with open(path, "rb") as f:
                if size > PER_FILE:
                    f.seek(size - PER_FILE)
                data = f.read(min(PER_FILE, IN_ALL - total))
            if size > len(data):
                data = f"[the first {size - len(data)} bytes were left out]\n".encode() + data
            info = tarfile.TarInfo(str(path.relative_to(folder)))
            info.size, info.mode = len(data), 0o600
            tar.addfile(info, io.BytesIO(data))
            total += len(data)
    return Path(name)


def unpack(data: bytes, into: Path) -> None:
    """Unpack a job's archive into `into` (made 0700): regular files only, inside it."""
    into.mkdir(mode=0o700, parents=True, exist_ok=True)
    with tarfile.open(fileobj=io.BytesIO(data), mode="r:gz") as tar:
        if hasattr(tarfile, "data_filter"):  # Python 3.11.4 and later
            tar.extractall(into, filter="data")
            return
        for member in tar.getmembers():  # (earlier 3.11: the same checks, by hand)
            tar.extract(_checked(member, into), into)


def _checked(member: tarfile.TarInfo, into: Path) -> tarfile.TarInfo:
    """A member as the "data" filter lets it through: a regular file or folder, its leading
    slashes dropped, inside `into`; else tarfile's own error."""
    if not (member.isfile() or member.isdir()):
        raise tarfile.TarError(f"{member.name}: not a regular file")
    member.name = member.name.lstrip("/")
    target = (into / member.name).resolve()
    if not target.is_relative_to(into.resolve()):
        raise tarfile.TarError(f"{member.name}: outside the folder it is unpacked in")
    member.mode = 0o600 if member.isfile() else 0o700
    return member
