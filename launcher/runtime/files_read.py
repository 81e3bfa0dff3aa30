"""The launch files being read, innermost last: what $(dirname), $(filename) and an include's
relative path are relative to, and launch's `context.locals.current_launch_file_path`."""

from __future__ import annotations

from collections.abc import Callable, MutableMapping
from pathlib import Path
from typing import Any


class FilesRead:
    """A stack of the files being read (None for a description built in code). `locals_of`
    gives the context's current locals, which follow the file on top."""

    def __init__(self, locals_of: Callable[[], MutableMapping[str, Any]]) -> None:
        self._stack: list[Path | None] = []
        self._locals_of = locals_of

    @property
    def current(self) -> Path | None:
        return self._stack[-1] if self._stack else None

    @property
    def all(self) -> list[Path | None]:
        """Every file being read, the outermost first (an include's chain)."""
        return list(self._stack)

    def push(self, path: Path | None) -> None:
        self._stack.append(path)
        self._tell_locals()

    def pop(self) -> None:
        self._stack.pop()
        self._tell_locals()

    def enter(self, path: Path | None) -> None:
        """Put back a file a snapshot was taken in (its locals come with the snapshot)."""
        self._stack.append(path)

    def leave(self) -> None:
        self._stack.pop()

    def _tell_locals(self) -> None:
        path = self.current
        if path is not None:
            self._locals_of().update(current_launch_file_path=str(path),
                                     current_launch_file_directory=str(path.parent))
