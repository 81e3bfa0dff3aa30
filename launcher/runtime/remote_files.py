"""A launch's folder on a host it reaches over ssh: what the launching host sends along
(parameter files, the graph's credentials) written there, the user's own (folder 0700, files
0600), and the paths of the launching host rewritten to them.

    <run folder>/launches/<launch id>/
        pid                  the supervisor's (a folder whose supervisor is gone is stale)
        credentials          the graph's, when the launch joins this host to it
        files/<id>/<name>    the files process <id> was started with

It is removed when the supervisor ends; a supervisor starting removes the stale ones that a
killed one left.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
from collections.abc import Iterable, Mapping
from pathlib import Path

from launcher import lineage
from launcher.errors import LaunchError
from launcher.private import private_folder, write_private

_LAUNCH_ID = re.compile(r"^[0-9a-fA-F]{1,64}$")


class LaunchFolder:
    def __init__(self, run_folder: Path, launch: str) -> None:
        """`launch`: the launch's id (hex), never a path of the other side's choosing."""
        if not _LAUNCH_ID.match(launch):
            raise LaunchError(f"launch id {launch!r}: expected 1 to 64 hex digits")
        self.path = private_folder(run_folder / "launches") / launch
        private_folder(self.path)
        write_private(self.path / "pid", f"{os.getpid()}\n")

    def credentials(self, text: str) -> Path:
        path = self.path / "credentials"
        write_private(path, text)
        return path

    def ship(self, ident: int, files: Iterable[tuple[str, str]]) -> dict[str, str]:
        """Write each (path on the launching host, text) for process `ident`; → {that path:
        the one here}. Names are kept (a node may look at a file's suffix)."""
        folder = self.path / "files" / str(ident)
        shutil.rmtree(folder, ignore_errors=True)  # (an id's files of an earlier start)
        private_folder(folder)
        moved: dict[str, str] = {}
        for count, (path, text) in enumerate(files):
            name = _file_name(path)
            here = folder / name
            if here.exists():  # two files of one name: each keeps it, in a folder of its own
                here = private_folder(folder / str(count)) / name
            write_private(here, text)
            moved[path] = str(here)
        return moved

    def forget(self, ident: int) -> None:
        """Process `ident`'s files are no longer needed (its group is gone)."""
        shutil.rmtree(self.path / "files" / str(ident), ignore_errors=True)

    def remove(self) -> None:
        shutil.rmtree(self.path, ignore_errors=True)


def _file_name(path: str) -> str:
    name = os.path.basename(path.rstrip("/"))
    return name if name not in ("", ".", "..") else "file"


def rewrite(argv: list[str], env: Mapping[str, str],
            moved: Mapping[str, str]) -> tuple[list[str], dict[str, str]]:
    """`argv` and `env` with every occurrence of a moved path replaced by where it is here
    (`--params-file P`, `__params:=P`, a path inside a variable's JSON). Longer paths first,
    so that one path that begins another is not replaced inside it."""
    order = sorted((path for path in moved if path), key=len, reverse=True)

    def swap(text: str) -> str:
        for old in order:
            if old in text:
                text = text.replace(old, moved[old])
        return text

    if not order:
        return list(argv), dict(env)
    return [swap(word) for word in argv], {name: swap(value) for name, value in env.items()}


def sweep_stale(run_folder: Path) -> None:
    """Remove the launch folders of supervisors that are gone (killed, or their host was cut
    off and their watchdog ended them)."""
    try:
        folders = list((run_folder / "launches").iterdir())
    except OSError:
        return
    for folder in folders:
        with contextlib.suppress(OSError, ValueError):
            pid = int((folder / "pid").read_text())  # (not written yet: ValueError)
            if lineage.alive(pid):
                continue
            shutil.rmtree(folder, ignore_errors=True)
