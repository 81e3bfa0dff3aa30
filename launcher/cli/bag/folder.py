"""A bag named on the command line: the folder rosbag2 wrote."""

from __future__ import annotations

from pathlib import Path

from launcher.errors import UsageError


def bag_folder(path: str) -> Path:
    folder = Path(path)
    if not (folder / "metadata.yaml").is_file():
        raise UsageError(f"'{path}' is not a bag (no metadata.yaml)")
    return folder
