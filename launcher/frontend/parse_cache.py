"""Parsed launch files kept between runs, as Python keeps its .pyc files.

A YAML or XML launch file parses into an `Entity` tree; the tree is kept in the user's cache
(`$LAUNCHER_CACHE_DIR`, else `$XDG_CACHE_HOME/launcher` or `~/.cache/launcher`, folder 0700,
files 0600) with the file's whole text. The next run that reads the same text gets the tree
back without importing the parser (PyYAML alone is a fifth of `launcher launch`'s imports).
An entry is used only when its text is the file's text byte for byte and it was written by the
same loaders (their files' sizes and times are part of the entry); anything else, a damaged or
foreign entry included, is parsed again. Only files that parsed cleanly are kept: an error is
found and reported anew on every run.
"""

from __future__ import annotations

import contextlib
import marshal
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from launcher.errors import Location
from launcher.frontend.entity import Attribute, Entity
from launcher.private import open_private, private_folder

FORMAT = 4
MAX_ENTRIES = 512  # past this, a new entry makes room by removing the older half
_HERE = os.path.dirname(os.path.abspath(__file__))
_LOADERS = ("entity.py", "yaml_loader.py", "xml_loader.py", "ros1.py", "parse_cache.py")


def folder(environ: Mapping[str, str] | None = None) -> Path:
    environ = os.environ if environ is None else environ
    if environ.get("LAUNCHER_CACHE_DIR"):
        return Path(environ["LAUNCHER_CACHE_DIR"]).expanduser() / "parsed"
    base = environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "launcher" / "parsed"


def _stamp() -> tuple[int, ...]:
    """The loaders' sizes and times: a changed loader makes every entry stale."""
    stamp: list[int] = [FORMAT]
    for name in _LOADERS:
        info = os.stat(os.path.join(_HERE, name))
        stamp += [info.st_size, info.st_mtime_ns]
    return tuple(stamp)


def _entry(path: Path, environ: Mapping[str, str] | None) -> Path:
    """The entry's file: named by a hash of the path (FNV-1a, no import needed)."""
    digest = 0xCBF29CE484222325
    for byte in os.fsencode(path):
        digest = ((digest ^ byte) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return folder(environ) / f"{digest:016x}"


def _safe_folder(path: Path) -> bool:
    """Ours and closed to others: an entry anyone else could write is never read."""
    try:
        info = os.stat(path)
    except OSError:
        return False
    return info.st_uid == os.getuid() and not info.st_mode & 0o022


def get(path: Path, data: bytes, environ: Mapping[str, str] | None = None) -> Entity | None:
    """The tree kept for `path` with exactly this text, or None."""
    entry = _entry(path, environ)
    if not _safe_folder(entry.parent):
        return None
    try:
        with open(entry, "rb") as handle:
            stamp, kept_path, kept_data, tree = marshal.load(handle)
        if stamp != _stamp() or kept_path != str(path) or kept_data != data:
            return None
        return _unpack(tree)
    except Exception:  # noqa: BLE001 - missing, damaged or foreign: parse the file instead
        return None


def put(path: Path, data: bytes, root: Entity, environ: Mapping[str, str] | None = None) -> None:
    """Keep the tree; a cache that cannot be written is no error (the next run parses)."""
    entry = _entry(path, environ)
    with contextlib.suppress(OSError, ValueError):
        private_folder(entry.parent)
        _make_room(entry.parent)
        temporary = entry.with_name(f"{entry.name}.{os.getpid()}")
        with open_private(temporary, "wb") as handle:
            marshal.dump((_stamp(), str(path), data, _pack(root)), handle)
        os.replace(temporary, entry)


def _make_room(where: Path) -> None:
    entries = [e for e in os.scandir(where) if e.is_file(follow_symlinks=False)]
    if len(entries) < MAX_ENTRIES:
        return
    entries.sort(key=lambda e: e.stat(follow_symlinks=False).st_mtime_ns)
    for old in entries[:len(entries) // 2]:
        with contextlib.suppress(OSError):
            os.unlink(old.path)


def _pack(entity: Entity) -> tuple[Any, ...]:
    attributes = tuple(
        (name, a.value if isinstance(a.value, str) else [_pack(e) for e in a.value],
         tuple(a.location), a.text_offset, tuple(a.key_location) if a.key_location else None,
         a.string, a.roslaunch, a.literal)
        for name, a in entity.attributes.items())
    return (entity.tag, tuple(entity.location), attributes,
            tuple(_pack(child) for child in entity.children), entity.nested_in_children)


def _unpack(packed: tuple[Any, ...]) -> Entity:
    tag, location, attributes, children, nested = packed
    entity = Entity(tag, Location(*location), nested_in_children=nested)
    for name, value, where, offset, key_where, string, roslaunch, literal in attributes:
        entity.attributes[name] = Attribute(
            value if isinstance(value, str) else [_unpack(e) for e in value],
            Location(*where), offset, Location(*key_where) if key_where else None, string,
            roslaunch, literal)
    entity.children = [_unpack(child) for child in children]
    return entity
