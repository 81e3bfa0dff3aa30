"""roslaunch.roslaunch_logs: `roslaunch-logs`, the folder of the launch's logs."""

from __future__ import annotations

import os
import sys

NAME = "roslaunch-logs"


def get_run_id() -> str | None:
    """The run id of the latest launch: launcher's newest run folder's name, if any."""
    from launcher.runtime.logs import log_root

    root = log_root()
    runs = sorted((p for p in root.iterdir() if p.is_dir()), key=lambda p: p.stat().st_mtime) \
        if root.is_dir() else []
    return runs[-1].name if runs else None


def logs_main() -> None:
    """Print the folder of the latest launch's logs (launcher's log root when none)."""
    from launcher.runtime.logs import log_root

    run_id = get_run_id()
    folder = log_root() / run_id if run_id else log_root()
    if not os.path.isdir(folder):
        print(f"No log files to show ({folder} does not exist)", file=sys.stderr)
        sys.exit(1)
    print(folder)
