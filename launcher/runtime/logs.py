"""One log folder per run: `<LOG_ROOT>/<YYYY-MM-DD-HH-MM-SS-µs>-<host>-<pid>/`.

LOG_ROOT is `$LAUNCHER_LOG_DIR`, else `~/.launcher/log`. The folder holds `launch.log` and
the `own_log` files of processes; `LOG_ROOT/latest` points at the newest run.

Each file rotates when it reaches its limit (`--log-max-size`, 100 MiB unless set): `launch.log`
becomes `launch.log.1`, the one before `.2`, and so on; KEEP of them are kept. Lines are
written whole, never cut at a rotation.
"""

from __future__ import annotations

import contextlib
import os
import time
from pathlib import Path
from typing import TextIO

from launcher.private import open_private, private_folder
from launcher.runtime.output import Record, plain

DEFAULT_LIMIT = 100 << 20  # bytes a log file holds before it rotates
KEEP = 5  # rotated files kept of each


class LogFile:
    """One log file that rotates at `limit` bytes; each file begins with `header`."""

    def __init__(self, path: Path, limit: int, header: str = "") -> None:
        self.path, self.limit, self.header = path, limit, header
        self.handle: TextIO = open_private(path, "a", encoding="utf-8")
        self.size = path.stat().st_size
        if not self.size and header:
            self.write(header)

    def write(self, line: str) -> None:
        size = len(line.encode()) if not line.isascii() else len(line)
        if self.size and self.size + size > self.limit:
            self._rotate()
        self.handle.write(line)
        self.size += size

    def _rotate(self) -> None:
        """The file becomes `.1` (the one before `.2`, …); a rotation the disk refuses
        leaves the lines going on into the file as it is."""
        try:
            for n in range(KEEP - 1, 0, -1):
                older = self.path.with_name(f"{self.path.name}.{n}")
                if older.exists():
                    older.replace(self.path.with_name(f"{self.path.name}.{n + 1}"))
            self.path.replace(self.path.with_name(f"{self.path.name}.1"))
            fresh = open_private(self.path, "a", encoding="utf-8")
        except OSError:
            return
        self.handle.close()
        self.handle, self.size = fresh, 0
        if self.header:
            self.write(self.header)

    def flush(self) -> None:
        self.handle.flush()

    def close(self) -> None:
        self.handle.close()


def log_root(environ: dict[str, str] | None = None) -> Path:
    env = os.environ if environ is None else environ
    if env.get("LAUNCHER_LOG_DIR"):
        return Path(env["LAUNCHER_LOG_DIR"]).expanduser()
    return Path.home() / ".launcher" / "log"


class RunLog:
    def __init__(self, root: Path, limit: int = DEFAULT_LIMIT) -> None:
        self.limit = limit
        now = time.time()
        stamp = time.strftime("%Y-%m-%d-%H-%M-%S", time.localtime(now))
        micros = int(now % 1 * 1_000_000)
        name = f"{stamp}-{micros:06d}-{os.uname().nodename}-{os.getpid()}"
        self.folder = private_folder(root / name)  # logs hold what the nodes printed
        latest = root / "latest"
        with contextlib.suppress(OSError):
            if latest.is_symlink() or latest.exists():
                latest.unlink()
            latest.symlink_to(name)
        self._launch_log = LogFile(self.folder / "launch.log", limit)
        self._own: dict[str, LogFile] = {}

    def write(self, record: Record) -> None:
        self._launch_log.write(plain(record) + "\n")

    def write_own(self, record: Record) -> None:
        """A process's own log files: `<name>-stdout.log`, `-stderr.log`, `-stdout_stderr.log`."""
        for suffix in (record.stream, "stdout_stderr"):
            key = f"{record.source}-{suffix}"
            if key not in self._own:
                self._own[key] = LogFile(self.folder / f"{key}.log", self.limit)
            self._own[key].write(record.text + "\n")

    def flush(self) -> None:
        self._launch_log.flush()
        for handle in self._own.values():
            handle.flush()

    def close(self) -> None:
        self.flush()
        self._launch_log.close()
        for handle in self._own.values():
            handle.close()
