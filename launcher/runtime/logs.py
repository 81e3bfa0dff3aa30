"""One log folder per run: `<LOG_ROOT>/<YYYY-MM-DD-HH-MM-SS-µs>-<host>-<pid>/`.

LOG_ROOT is `$LAUNCHER_LOG_DIR`, else `~/.launcher/log`. The folder holds `launch.log` and
the `own_log` files of processes; `LOG_ROOT/latest` points at the newest run.
"""

from __future__ import annotations

import contextlib
import os
import time
from pathlib import Path
from typing import TextIO

from launcher.private import open_private, private_folder
from launcher.runtime.output import Record, plain


def log_root(environ: dict[str, str] | None = None) -> Path:
    env = os.environ if environ is None else environ
    if env.get("LAUNCHER_LOG_DIR"):
        return Path(env["LAUNCHER_LOG_DIR"]).expanduser()
    return Path.home() / ".launcher" / "log"


class RunLog:
    def __init__(self, root: Path) -> None:
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
        self._launch_log = open_private(self.folder / "launch.log", "a", encoding="utf-8")
        self._own: dict[str, TextIO] = {}

    def write(self, record: Record) -> None:
        self._launch_log.write(plain(record) + "\n")

    def write_own(self, record: Record) -> None:
        """A process's own log files: `<name>-stdout.log`, `-stderr.log`, `-stdout_stderr.log`."""
        for suffix in (record.stream, "stdout_stderr"):
            key = f"{record.source}-{suffix}"
            if key not in self._own:
                self._own[key] = open_private(self.folder / f"{key}.log", "a", encoding="utf-8")
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
