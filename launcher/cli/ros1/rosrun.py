"""`rosrun [--prefix cmd] [--debug] PACKAGE EXECUTABLE [ARGS …]`: as `launcher run` (which
takes rosrun's options already), with rosrun's words when the executable is not there."""

from __future__ import annotations


def main(argv: list[str], prog: str = "rosrun") -> int:
    from launcher.cli.run_command import run_run
    from launcher.errors import LaunchError

    try:
        return run_run(argv)
    except LaunchError as exc:
        words = [w for w in argv if not w.startswith("-")]
        if "no executable" in str(exc) and len(words) >= 2:
            raise LaunchError(f"[rosrun] Couldn't find executable named {words[1]} below "
                              f"the package {words[0]}: {exc}") from None
        raise
