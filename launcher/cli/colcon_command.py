"""`colcon build|test|list|graph|info …` as ROS 2 users type it: the real colcon, run by
launcher's build tools (packages/build.py), after every package.xml has been read with its
file:line on error. The shell reaches this through launcher's `colcon` (compat/bin), last on
PATH: a real colcon earlier on PATH is the one that runs."""

from __future__ import annotations

import os
from pathlib import Path


def main(argv: list[str], prog: str = "colcon") -> int:
    from launcher.packages import build

    if argv[:1] == ["build"]:
        bases = _base_paths(argv[1:])
        build.check_manifests(bases)
    return build.run_colcon(argv, Path.cwd(), os.environ)


def _base_paths(argv: list[str]) -> list[Path]:
    """colcon's `--base-paths` (default: the current folder)."""
    if "--base-paths" in argv:
        words = argv[argv.index("--base-paths") + 1:]
        found = []
        for word in words:
            if word.startswith("-"):
                break
            found.append(Path(word))
        return found or [Path.cwd()]
    return [Path.cwd()]
